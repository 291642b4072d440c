// The shared float BRDF's dot products (shaders/brdf.glsl BrdfDots) for one reflection of the
// half-vector integration (albedo.hpp): what every lab integrand evaluates the BRDF with. In an
// anonymous namespace like shading.hpp, whose BrdfDots each translation unit has its own of.
#pragma once

#include "albedo.hpp"
#include "shading.hpp"

namespace onelight::lab {
namespace {

inline glsl::BrdfDots dotsOf(const Reflection& r) {
    glsl::BrdfDots d;
    d.NoV = glsl::clamp(float(r.NoV), glsl::MIN_NOV, 1.0f);
    d.NoL = float(r.NoL);
    d.LoH = float(r.VoH);
    d.NxH2 = float(r.sin2H);
    return d;
}

}  // namespace
}  // namespace onelight::lab
