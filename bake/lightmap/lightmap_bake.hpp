// Lightmap texels: the own primary's baked shadow mask and the directional secondary
// irradiance, per texel of every static surface (docs/lighting.md "Secondary diffuse").
#pragma once

#include <cstdint>
#include <vector>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/lights.hpp"
#include "bake/lighting/radiance.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "bake/report/progress.hpp"
#include "world/baked_lighting.hpp"

namespace onelight::bake {

struct LightmapSettings {
    uint32_t shadow_samples = 16;     // shadow rays per light per texel (stratified)
    uint32_t indirect_samples = 256;  // cosine-distributed paths per texel
    TransportSettings transport;
};

struct LightmapStats {
    RayCounts rays;
    uint64_t texels_baked = 0;
    uint64_t texels_moved = 0;         // sample points moved out of geometry
    double mean_relative_noise = 0.0;  // estimated standard error / value, luminance-weighted
};

/// Bakes the texels of `samples` whose global index is in [texel_begin, texel_end) into
/// `baked` (already sized: texels and shadow_mask to total_texels). Each texel's random
/// sequence is seeded from (atlas, x, y, pass), so the result does not depend on threads,
/// order or sharding.
LightmapStats bake_lightmap_texels(const BakeScene& scene, const BakeLights& lights,
                                   const world::CompiledLevel& level,
                                   const std::vector<TexelSample>& samples,
                                   const LightmapSettings& settings, uint64_t texel_begin,
                                   uint64_t texel_end, world::BakedLighting& baked,
                                   Progress* progress);

/// Fills each chart's unsampled texels from their sampled neighbours, ring by ring, inside
/// the chart's rectangle only (charts never bleed into each other).
void dilate_lightmaps(const world::CompiledLevel& level, world::BakedLighting& baked);

/// The total irradiance a static surface receives at a texel, as the runtime reconstructs it
/// at the surface normal: own primary x shadow mask + secondary. For tests and the benchmark.
glm::vec3 lightmap_total_irradiance(const BakeLights& lights, const world::CompiledLevel& level,
                                    const world::BakedLighting& baked, const TexelSample& sample);

}  // namespace onelight::bake
