// The dominant primary at a point with visibility: what the world compiler's region splitter
// asks (world/regions/primary_illuminance.hpp). Each primary's shadowed illuminance counts
// its falloff, its cone, the surface's cosine and the visible fraction of the light's size.
#pragma once

#include <atomic>
#include <cstdint>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/lights.hpp"
#include "world/regions/primary_illuminance.hpp"

namespace onelight::bake {

/// Shadow rays the function traced (it may run on any thread).
struct AtomicRayCount {
    std::atomic<uint64_t> shadow{0};
};

/// Illuminance (lux, luminance of the RGB irradiance) of every primary candidate, in the order
/// of the level's primary lights, with visibility from `shadow_samples` stratified rays. The
/// random sequence is seeded from the position's bits: the same point gives the same answer.
/*
   E_i(x, n) = Y(E_i) max(0, n . w_i) V_i(x),  V_i = (1/N) sum_k vis(x, w_k)   (lights.hpp)
   (n = 0: no cosine)
                            +--------------------------------------+
                            | E_i = Y(E_i) (n . w_i)+ V_i          |
                            +--------------------------------------+
   The scene and lights are borrowed and must outlive the function.
*/
[[nodiscard]] world::PrimaryIlluminanceFn makeShadowedPrimaryIlluminance(const BakeScene& scene,
                                                                         const BakeLights& lights,
                                                                         uint32_t shadowSamples,
                                                                         AtomicRayCount* rays);

}  // namespace onelight::bake
