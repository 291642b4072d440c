// bake/lighting/punctual.glsl compiled as C++ in namespace onelight::glsl, beside the shared
// BRDF of shaders/shading.hpp (same pattern: an internal copy per translation unit).
#pragma once

#include "glsl.hpp"
#include "shading.hpp"

namespace onelight::glsl {
namespace {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "punctual.glsl"
#pragma GCC diagnostic pop
}  // namespace
}  // namespace onelight::glsl
