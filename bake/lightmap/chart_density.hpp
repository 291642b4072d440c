// Lightmap density per chart from a pilot pass (docs/lighting.md "Density per chart"): a chart
// whose light is smooth is baked with fewer texels. Decided from every texel's direct light and
// the distance to what surrounds it, never from a texel's own noise.
#pragma once

#include <cstdint>
#include <vector>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/lights.hpp"
#include "bake/lightmap/lightmap_bake.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "world/compiled_level.hpp"

namespace onelight::bake {

struct ChartDensitySettings {
    // The largest second difference of the direct light over a coarse step, relative to the
    // light there, that the coarser lattice may leave: bilinear interpolation between texels
    // k apart is then off by about an eighth of it (0.5%).
    float curvatureTolerance = 0.04f;
    // The coarse step (k texels) may be at most this fraction of the harmonic mean distance to
    // the surroundings: indirect light changes by about step / distance (Ward's split sphere).
    float distanceFraction = 0.25f;
    // Which of the chart's texels the distance criterion holds for: all of them (0), or all but
    // this fraction of the nearest to their surroundings (an error budget's: their indirect
    // light is interpolated over a longer step; on a few percent of the area, its block error
    // stays within the budget's share).
    float distanceQuantile = 0.0f;
    uint32_t maxReduction = 32;  // k in {2, 4, ..., maxReduction}
    uint32_t shadowSamples = 4;  // per light per texel, for the pilot's direct light
    uint32_t distanceRays = 16;  // cosine-distributed rays per texel, their hit distances only
    // The views a level is judged from (an error budget's, bake/budget/): a chart that every
    // view sees only nearer than `maskDistance` never shows its baked shadow mask (the runtime
    // shadows its primary per pixel there, world::kRuntimeShadowRadius), so its own primary's
    // light is left out of the curvature test; the light the lightmap itself holds still
    // counts. Empty: the own primary's light always counts.
    std::vector<glm::vec3> views;
    float maskDistance = 0.0f;  // metres
};

struct ChartDensityStats {
    uint32_t chartsReduced = 0;  // charts that got fewer texels
    RayCounts rays;
};

/// The density scale of every chart of `level` (in chart order; 1 / k, or 1 to keep it):
/// per generated chart, the largest k of 2, 4, ... settings.maxReduction such that
///   - along every row and column of the chart's sampled texels, every triple of texels k apart
///     (x - k, x, x + k) has |f(x - k) + f(x + k) - 2 f(x)| <= curvatureTolerance x
///     max(f(x), 1% of the chart's brightest), f the texel's direct light (its own primary's,
///     shadowed, unless no view sees the chart's mask, and every other light's), and
///   - k texels are at most distanceFraction of every texel's harmonic mean hit distance (but
///     the distanceQuantile nearest),
/// and the chart spans at least 2k + 1 texels along one axis. Authored charts keep their
/// density. Deterministic: every texel's rays are seeded from the texel.
[[nodiscard]] std::vector<float> chartDensityScales(const BakeScene& scene,
                                                    const BakeLights& lights,
                                                    const world::CompiledLevel& level,
                                                    const std::vector<TexelSample>& samples,
                                                    const ChartDensitySettings& settings,
                                                    ChartDensityStats* stats = nullptr);

}  // namespace onelight::bake
