#include "bake/budget/error_budget.hpp"

#include <algorithm>
#include <cmath>

#include <cstdio>
#include <string>

#include "bake/budget/probe_drop.hpp"
#include "world/features/feature_analysis.hpp"
#include "world/light_model.hpp"

namespace onelight::bake {

ChartDensitySettings chartDensityForBudget(float budget, const world::CompiledLevel& level) {
    ChartDensitySettings s;
    for (const world::Camera& view : budgetViews(level)) s.views.push_back(view.position);
    s.maskDistance = world::kRuntimeShadowRadius - world::kRuntimeShadowBand;
    const float tolerance = 8.0f * kBudgetLightmapShare * budget;
    const float ratio = std::max(1.0f, tolerance / s.curvatureTolerance);
    s.curvatureTolerance = std::max(s.curvatureTolerance, tolerance);
    s.distanceFraction = std::min(1.0f, s.distanceFraction * std::sqrt(ratio));
    s.distanceQuantile = kBudgetDistanceQuantile;
    s.maxReduction = 64;
    return s;
}

float predictedLightmapError(const ChartDensitySettings& settings) {
    return settings.curvatureTolerance / 8.0f;
}

world::LightGrid budgetGridLayout(const world::CompiledLevel& level, const GridSettings& settings,
                                  BudgetGridChoice& choice) {
    world::LightGrid full = layoutLightGrid(level, settings);
    choice.fullCells = full.cells.size();
    glm::vec3 lo, hi;
    choice.followsDynamicObjects = world::dynamicObjectReach(level, lo, hi);
    world::LightGrid grid;
    if (choice.followsDynamicObjects) {
        grid = layoutLightGridOver(lo - full.cellSize, hi + full.cellSize, settings);
    } else {
        GridSettings coarse = settings;
        coarse.cellSize = std::max(settings.cellSize, kBudgetEmptyGridCell);
        grid = layoutLightGrid(level, coarse);
    }
    choice.reduced = grid.cells.size() < full.cells.size();
    return choice.reduced ? grid : full;
}

namespace {

std::string percent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f%%", 100.0 * fraction);
    return text;
}

}  // namespace

void chooseWithinBudget(const BakeScene& scene, const BakeLights& lights,
                        const TransportSettings& transport, const world::CompiledLevel& level,
                        float budget, const ChartDensitySettings& density,
                        const world::LightGrid& grid, const BudgetGridChoice& gridChoice,
                        std::vector<ProbePlacement>& placements, RayCounts& rays,
                        BakeReport& report) {
    world::ErrorBudgetChoices& c = report.budget;
    c.budget = budget;
    const std::vector<world::Camera> views = budgetViews(level);
    c.viewsPredicted = uint32_t(views.size());

    // Probes.
    c.probesPlaced = uint32_t(placements.size());
    const double probeShare = kBudgetProbeShare * budget;
    if (placements.empty()) {
        report.budgetChoices.push_back(
            {"probes", "none placed", "no specular surface sees anything to reflect", 0.0});
    } else if (views.empty()) {
        report.budgetChoices.push_back(
            {"probes", "kept", "the level has no camera or spawn to predict their error from",
             0.0});
    } else {
        const ProbeDropPrediction p = predictProbeDropError(scene, lights, transport, views);
        rays += p.rays;
        report.probeErrorPerView = p.views;
        c.probeError = float(p.error);
        const std::string why = std::to_string(p.glossySamples) + " of " +
                                std::to_string(p.samples) + " view samples glossy; " +
                                percent(p.error) + " predicted against a share of " +
                                percent(probeShare);
        if (p.error <= probeShare) {
            c.flags |= world::kBudgetProbesDropped;
            report.budgetChoices.push_back({"probes",
                                            "dropped " + std::to_string(placements.size()) +
                                                ": a uniform environment, error +" +
                                                percent(p.error),
                                            why, p.error});
            placements.clear();
        } else {
            report.budgetChoices.push_back(
                {"probes", "kept " + std::to_string(placements.size()), why, p.error});
        }
    }

    // Lightmap density.
    c.densityTolerance = density.curvatureTolerance;
    c.lightmapError = predictedLightmapError(density);
    c.texelsRequested = uint32_t(std::min<uint64_t>(report.texelsBeforeDensity, UINT32_MAX));
    c.texelsSampled = uint32_t(std::min<uint64_t>(report.texelsSampled, UINT32_MAX));
    c.texelsSampled = std::min(c.texelsSampled, c.texelsRequested);
    char densityWhy[160];
    std::snprintf(densityWhy, sizeof densityWhy,
                  "charts whose direct light's second difference stays within %.0f%% over the "
                  "coarser step, up to %ux fewer texels per axis",
                  100.0 * double(density.curvatureTolerance), density.maxReduction);
    report.budgetChoices.push_back({"lightmap",
                                    std::to_string(report.texelsSampled) + " texels sampled of " +
                                        std::to_string(report.texelsBeforeDensity) +
                                        " at the requested density, error +" +
                                        percent(c.lightmapError),
                                    densityWhy, c.lightmapError});

    // Light grid.
    c.gridCellsFull = uint32_t(gridChoice.fullCells);
    c.gridCells = uint32_t(grid.cells.size());
    if (gridChoice.reduced) c.flags |= world::kBudgetGridReduced;
    report.budgetChoices.push_back(
        {"light grid",
         std::to_string(c.gridCells) + " cells of " + std::to_string(c.gridCellsFull) +
             ", error +0.00% on the static world",
         !gridChoice.reduced ? "kept whole: dynamic objects can go anywhere in it"
         : gridChoice.followsDynamicObjects
             ? "it lights dynamic objects only: cells where they can go, one cell around"
             : "no dynamic object: coarse cells for the exposure meter alone",
         0.0});

    c.predictedError =
        c.lightmapError + ((c.flags & world::kBudgetProbesDropped) ? c.probeError : 0.0f);
}

}  // namespace onelight::bake
