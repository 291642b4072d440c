// The records and constants the renderer shares with its shaders, from their one source,
// shaders/gpu_interface.glsl, compiled as C++ (namespace onelight::glsl, not anonymous: one type
// in every translation unit), with the sizes both languages must agree on checked here.
#pragma once

#include <cstdint>

#include "glsl.hpp"
#include "world/no_index.hpp"

namespace onelight::glsl {
#include "gpu_interface.glsl"
}  // namespace onelight::glsl

namespace onelight::render {

using glsl::DrawPush;
using glsl::FrameUniforms;
using glsl::GpuLight;
using glsl::GpuMaterial;
using glsl::GpuObjectLighting;
using glsl::GpuProbe;
using glsl::GpuProbeGrid;
using glsl::GpuShadowView;
using glsl::MaskedShadowPush;

using world::kNoIndex;
inline constexpr uint32_t kMaxEffectOmnis = glsl::MAX_EFFECT_OMNIS;
static_assert(glsl::NO_INDEX == world::kNoIndex,
              "one \"no index\" on both sides of the GPU interface");

static_assert(sizeof(GpuLight) == 80);
static_assert(sizeof(FrameUniforms) == 224 + 80 * (kMaxEffectOmnis + 1));
static_assert(sizeof(GpuShadowView) == 80);
static_assert(sizeof(GpuMaterial) == 80);
static_assert(sizeof(GpuObjectLighting) == 64 + 96 * glsl::MAX_OBJECT_SAMPLES);
static_assert(sizeof(GpuProbe) == 176);
static_assert(sizeof(GpuProbeGrid) == 48);
static_assert(sizeof(DrawPush) == 112);
static_assert(sizeof(MaskedShadowPush) == 80);

}  // namespace onelight::render
