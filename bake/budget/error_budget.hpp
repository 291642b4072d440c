// onelight-bake --error-budget E: what a level can leave out for a mean block error of at most
// E on its views (docs/level-report.md, "Error budget"). The choices may spend half of E,
// a quarter each on the probes and on the lightmap's density; the other half is left for the
// full model's own error (its BRDF approximations, shadow maps, the bake's noise), which no
// choice here can remove. Each choice comes with the error it is predicted to cost; the level
// report measures the real one.
#pragma once

#include <vector>

#include "bake/grid/light_grid.hpp"
#include "bake/lightmap/chart_density.hpp"
#include "bake/probes/probe_capture.hpp"
#include "bake/report/report.hpp"
#include "world/compiled_level.hpp"

namespace onelight::bake {

inline constexpr float kBudgetProbeShare = 0.25f;     // of E, for a uniform environment
inline constexpr float kBudgetLightmapShare = 0.25f;  // of E, for coarser charts
// The share of a chart's texels (the nearest to their surroundings) whose indirect light may be
// interpolated over a step longer than the distance criterion allows (chart_density.hpp).
inline constexpr float kBudgetDistanceQuantile = 0.02f;

/// A budget's chart density: bilinear interpolation between texels k apart is off by about an
/// eighth of the second difference it leaves (chart_density.hpp), so the curvature tolerance
/// is 8 x the lightmap's share; the distance criterion (indirect light, whose interpolation
/// error grows with the square of the step) grows by the square root of the tolerance's ratio
/// to the default's; up to 64x fewer texels per axis. The views are budgetViews(level): a chart
/// they see only within the runtime's shadows is judged by the light its lightmap holds, not
/// by its primary's shadow, which the runtime draws per pixel there.
[[nodiscard]] ChartDensitySettings chartDensityForBudget(float budget,
                                                         const world::CompiledLevel& level);

/// The lightmap error that `settings` is predicted to cost: curvatureTolerance / 8.
[[nodiscard]] float predictedLightmapError(const ChartDensitySettings& settings);

/// The light grid of a budget: only where dynamic objects can go (world::dynamicObjectReach,
/// grown by one cell), or, with none, one cell per `kBudgetEmptyGridCell` metres over the
/// level, for the game's exposure metering; the full layout when that is not smaller.
inline constexpr float kBudgetEmptyGridCell = 8.0f;
struct BudgetGridChoice {
    uint64_t fullCells = 0;              // cells of the full layout
    bool reduced = false;                // the layout is smaller than the full one
    bool followsDynamicObjects = false;  // the level has dynamic objects
};
[[nodiscard]] world::LightGrid budgetGridLayout(const world::CompiledLevel& level,
                                                const GridSettings& settings,
                                                BudgetGridChoice& choice);

/// The budget's choices once the lightmaps are baked (`report` holds their texel counts):
/// predicts the probes' cost from budgetViews (probe_drop.hpp) and clears `placements` when it is
/// within kBudgetProbeShare x budget; fills report.budget, report.budgetChoices and
/// report.probeErrorPerView. `grid` and `gridChoice` are budgetGridLayout's.
void chooseWithinBudget(const BakeScene& scene, const BakeLights& lights,
                        const TransportSettings& transport, const world::CompiledLevel& level,
                        float budget, const ChartDensitySettings& density,
                        const world::LightGrid& grid, const BudgetGridChoice& gridChoice,
                        std::vector<ProbePlacement>& placements, RayCounts& rays,
                        BakeReport& report);

}  // namespace onelight::bake
