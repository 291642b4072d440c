// Lightmap texels: the own primary's baked shadow mask and the directional secondary
// irradiance, per texel of every static surface (docs/lighting.md "Secondary diffuse").
#pragma once

#include <cstdint>
#include <vector>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/lights.hpp"
#include "bake/lighting/radiance.hpp"
#include "bake/lightmap/lightmap_denoise.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "bake/report/progress.hpp"
#include "world/baked_lighting.hpp"

namespace onelight::bake {

struct LightmapSettings {
    uint32_t shadowSamples = 16;     // shadow rays per light per texel (stratified)
    uint32_t indirectSamples = 256;  // cosine-distributed gathering directions per texel
    // Cached bounces (lightmap_bake.cpp): passes over every texel before the final gather, and
    // their directions per texel. 0 passes: every direction is a whole path instead.
    uint32_t bouncePasses = 0;
    uint32_t cacheSamples = 64;
    DenoiseSettings denoise;  // the indirect part's filter (lightmap_denoise.hpp)
    bool directEdges = true;  // the direct light's sharp shadow edges as a distance field
    TransportSettings transport;
};

struct LightmapStats {
    RayCounts rays;
    uint64_t texelsBaked = 0;
    uint64_t texelsGathered = 0;  // final gathers: the texels baked and their denoiser windows'
    uint64_t texelsMoved = 0;     // sample points moved out of geometry
    // Estimated standard error / value, luminance-weighted: of the texels' own estimates, and
    // after the denoiser (from its windows' weights; bias not included).
    double meanRelativeNoise = 0.0;
    double meanRelativeNoiseDenoised = 0.0;
};

/// One texel's direct part (the estimator in lightmap_bake.cpp): its ray origin (moved out of a
/// solid if it lies in one), its own primary's shadow mask and shadowed light, and every other
/// light's shadowed light, with settings.shadowSamples rays per light. Seeded from the texel.
[[nodiscard]] TexelEstimate estimateTexelDirect(const BakeScene& scene, const BakeLights& lights,
                                                const world::CompiledLevel& level,
                                                const TexelSample& sample,
                                                const LightmapSettings& settings, RayCounts& rays);

/// Bakes the texels of `samples` whose global index is in [texelBegin, texelEnd) into
/// `baked` (already sized: texels and shadowMask to totalTexels). Each texel's random
/// sequence is seeded from (atlas, x, y, pass), so the result does not depend on threads,
/// order or sharding. With bounce passes, the cache of every texel is left in `cache` (when
/// given) for the grid and the probes to read.
[[nodiscard]] LightmapStats bakeLightmapTexels(const BakeScene& scene, const BakeLights& lights,
                                               const world::CompiledLevel& level,
                                               const std::vector<TexelSample>& samples,
                                               const LightmapSettings& settings,
                                               uint64_t texelBegin, uint64_t texelEnd,
                                               world::BakedLighting& baked, Progress* progress,
                                               RadianceCache* cache = nullptr);
/// The same for the samples `ownedSamples` (indices into `samples`, increasing): a shard's
/// charts (bake/shard_plan.hpp).
[[nodiscard]] LightmapStats bakeLightmapTexels(const BakeScene& scene, const BakeLights& lights,
                                               const world::CompiledLevel& level,
                                               const std::vector<TexelSample>& samples,
                                               const LightmapSettings& settings,
                                               const std::vector<uint32_t>& ownedSamples,
                                               world::BakedLighting& baked, Progress* progress,
                                               RadianceCache* cache = nullptr);

/// The progress units bakeLightmapTexels advances by for `allSamples` texels of which it owns
/// `ownedSamples`.
[[nodiscard]] uint64_t lightmapWorkUnits(size_t allSamples, size_t ownedSamples,
                                         const LightmapSettings& settings);

/// Fills each chart's unsampled texels from their sampled neighbours, ring by ring, inside
/// the chart's rectangle only (charts never bleed into each other).
void dilateLightmaps(const world::CompiledLevel& level, world::BakedLighting& baked);

/// The total irradiance a static surface receives at a texel, as the runtime reconstructs it
/// at the surface normal: own primary x shadow mask + secondary. For tests and the benchmark.
[[nodiscard]] glm::vec3 lightmapTotalIrradiance(const BakeLights& lights,
                                                const world::CompiledLevel& level,
                                                const world::BakedLighting& baked,
                                                const TexelSample& sample);

}  // namespace onelight::bake
