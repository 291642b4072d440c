// The bake's report.json: seconds per stage, rays by kind and rays/s, peak memory, samples per
// texel and the estimated noise.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bake/embree/bake_scene.hpp"
#include "world/baked_lighting.hpp"

namespace onelight::bake {

struct StageReport {
    std::string name;
    double seconds = 0.0;
    RayCounts rays;
    uint64_t items = 0;  // texels, cells, ... the stage worked on
};

/// One texture the texture stage made, as the package stores it.
struct TextureReport {
    std::string name, format;
    uint32_t width = 0, height = 0, mips = 0;
    uint64_t bytes = 0;  // every mip
};

/// One choice of --error-budget: what was left out (or kept), the error it is predicted to
/// cost, and why.
struct BudgetChoiceReport {
    std::string feature, choice, why;
    double predictedError = 0.0;
};

struct BakeReport {
    std::string level;
    std::string quality;
    uint32_t threads = 0;
    uint32_t shardIndex = 0, shardCount = 1;
    // A part of a sharded bake: the estimated core-seconds of the work it bakes alone, and of
    // all the parts' (bake/shard_plan.hpp); 0 for a whole bake.
    double shardCost = 0.0, shardCostTotal = 0.0;
    std::vector<StageReport> stages;
    uint64_t triangles = 0;
    uint32_t primaryLights = 0, bakedLights = 0, emissiveTriangles = 0;
    uint64_t texelsTotal = 0, texelsSampled = 0, texelsMoved = 0;
    // Texels whose final gather ran: those sampled and the ones their denoiser windows read. A
    // whole bake gathers each texel once; parts gather their neighbours' edges again.
    uint64_t texelsGathered = 0;
    // The pilot pass of adaptive density: charts given fewer texels, and the sampled texels at
    // the requested density (0 when no pilot ran).
    uint32_t chartsReduced = 0;
    uint64_t texelsBeforeDensity = 0;
    uint64_t gridCells = 0, gridCellsInside = 0;
    uint32_t shadowSamplesPerLight = 0;
    uint32_t indirectSamplesPerTexel = 0;
    uint32_t gridSamplesPerCell = 0;
    double lightmapMeanRelativeNoise = 0.0;      // estimated standard error / value
    double lightmapDenoisedRelativeNoise = 0.0;  // the same after the denoiser
    uint64_t probesTotal = 0, probesBaked = 0;   // placed in the level; captured by this run
    uint32_t probeFaceSize = 0, probeSamplesPerTexel = 0;
    uint64_t probeBytes = 0;              // section 35 bytes of the probes this run baked
    std::vector<TextureReport> textures;  // the texture stage's, with their memory
    uint64_t textureBytes = 0;            // their texels, every mip
    // The potentially visible set: view cells, leaf clusters, distinct rows, and the mean
    // fraction of the clusters a cell's set holds (0 cells: none baked).
    uint32_t visibilityCells = 0, visibilityClusters = 0, visibilityRows = 0;
    double visibilityMeanFraction = 0.0;
    // "sampled" (rays), "sampled within the source's own" (rays bounded by q3map2 -vis) or "the
    // source's own" (q3map2 -vis, no ray)
    std::string visibilitySource;
    // --error-budget (budget.budget > 0): the choices, as the package stores them and as lines.
    world::ErrorBudgetChoices budget;
    std::vector<BudgetChoiceReport> budgetChoices;
    std::vector<double> probeErrorPerView;  // the probes' predicted error from each view
    std::vector<std::string> warnings;      // one line each, naming the thing and what to change
    std::vector<std::string> lightSources;  // where each kind of the level's light came from
    uint64_t peakMemoryBytes = 0;
    uint64_t packageBytes = 0;
};

/// Peak resident memory of this process so far (getrusage), bytes.
[[nodiscard]] uint64_t peakMemoryBytes();

[[nodiscard]] std::string reportJson(const BakeReport& report);
/// Writes the JSON to `path` (atomically). Throws world::Error.
void writeReport(const std::string& path, const BakeReport& report);
/// A few lines for stdout at the end of a run.
[[nodiscard]] std::string reportSummary(const BakeReport& report);

}  // namespace onelight::bake
