// How a sharded bake (--shard i/N, --slurm N) divides its work: each part bakes one contiguous
// range of the lightmap charts, then of the light grid's cells, then of the probes, cut where the
// estimated cost of the work that a part does alone reaches an equal share. The charts are taken
// whole and in space order (chartSpaceOrder): the denoiser reads every texel within its largest
// window in world space, and a part must gather those texels too, so a part's charts are kept
// together in space, where their windows overlap one another rather than other parts' charts. What
// every part does whole (the texture stage, the scene, the direct light and the cached bounce
// passes over every texel) is not divided and not counted; the visibility set's view cells are
// divided apart, every N-th cell to each part (bake/visibility/visibility_bake.hpp).
//
// The estimate is in core-seconds, from per-item costs measured on one core of the reference
// machine (docs/slurm.md, "Shard balance": aggressor at draft and default, the demo at draft;
// only their ratios matter for the cut). S is the shadow rays per light, T the lights that reach
// the point (its light cell's, the suns, the emitters as one), min(T, 16) the shadow-ray budget
// of estimateVisibilities (at most 8 terms: S rays each; more: about 2 x 8 S in all):
//   chart   1.5 us per gathering path (P_lm) of each of its placed texels: a path's hit reads
//           the cached bounces, glossy hits are traced on, and the denoiser's window costs its
//           share. Its lights do not count here: the direct light of every texel is computed
//           whole in every part
//   cell    0.45 us per gathering path (P_grid; from the open, cheaper than a texel's) and
//           0.1 us per shadow ray, S min(T, 16), of its direct light
//   probe   1.9 us per path, 6 f^2 spp of them (f: the face size), prefiltering included
//   without cached bounces (--paths-only) every gathering path costs twice as much (a whole
//   path: measured 2.2x for texels, 1.8x for cells)
// The parts record their ranges (section 40), so that the merge needs neither the lights nor
// the settings to join them.
#pragma once

#include <cstdint>
#include <vector>

#include "bake/grid/light_grid.hpp"
#include "bake/lighting/lights.hpp"
#include "bake/lightmap/lightmap_bake.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "bake/probes/probe_capture.hpp"
#include "world/baked_lighting.hpp"

namespace onelight::bake {

/// The level's charts in space order: along a Morton curve through the centres of their
/// surfaces' bounds, over the level's bounds (ties by index). A shard's chart range
/// [chartBegin, chartEnd) is of positions in this order. Depends on the compiled level alone,
/// so that the parts and the merge agree; a bake computes it once and hands it to the two
/// functions below.
[[nodiscard]] std::vector<uint32_t> chartSpaceOrder(const world::CompiledLevel& level);

/// The estimated core-seconds of each item in the divided work.
struct ShardCosts {
    std::vector<double> charts;  // per chart, in the order given to estimateShardCosts
    std::vector<double> cells;   // per light grid cell
    std::vector<double> probes;  // per probe
};

/// The lights whose light reaches `position` as the direct-light estimate weighs them.
[[nodiscard]] uint32_t lightsReaching(const BakeLights& lights, const glm::vec3& position);

/// The costs of the level's charts (laid in `chartOrder`, chartSpaceOrder's), cells and probes.
[[nodiscard]] ShardCosts estimateShardCosts(
    const BakeLights& lights, const world::CompiledLevel& level,
    const std::vector<uint32_t>& chartOrder, const std::vector<TexelSample>& samples,
    const world::LightGrid& grid, size_t probes, const LightmapSettings& lightmap,
    const GridSettings& gridSettings, const ProbeCaptureSettings& probe);

/// Part `index` of `count`: charts, cells and probes laid end to end in that order, cut where
/// the running cost reaches index / count of the total (by count when every cost is 0). Every
/// chart, cell and probe belongs to exactly one part.
[[nodiscard]] world::ShardRange shardRange(const ShardCosts& costs, uint32_t index, uint32_t count);

/// The estimated core-seconds of `range`'s items, for the report.
[[nodiscard]] double shardCost(const ShardCosts& costs, const world::ShardRange& range);

/// The samples (indices into `samples`, increasing) whose charts `range` holds (positions in
/// `chartOrder`, chartSpaceOrder's).
[[nodiscard]] std::vector<uint32_t> samplesOfRange(const world::CompiledLevel& level,
                                                   const std::vector<uint32_t>& chartOrder,
                                                   const std::vector<TexelSample>& samples,
                                                   const world::ShardRange& range);

}  // namespace onelight::bake
