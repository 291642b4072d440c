// The shared shading functions of shaders/*.glsl, compiled as C++ in namespace
// onelight::glsl. Each translation unit gets its own internal copy (an anonymous namespace),
// exactly as each shader gets its own: no ODR issues, and the optimizer inlines freely.
#pragma once

#include "glsl.hpp"

namespace onelight::glsl {
namespace {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "brdf.glsl"
#include "brdf_pieces.glsl"
#include "env_brdf_fit.glsl"
#include "lighting.glsl"
#include "material.glsl"
#include "probe.glsl"
#include "sky.glsl"
#include "tonemap.glsl"
#pragma GCC diagnostic pop
}  // namespace
}  // namespace onelight::glsl
