// The bake pipeline: import -> texture stage -> Embree scene of the static world -> world
// compile with the shadowed dominant-primary function -> lightmap texels (shadow masks +
// directional secondary irradiance) -> light grid -> environment probes -> dilation -> package.
// Sharding bakes a contiguous part of the texels, of the grid cells and of the probes, cut by
// estimated cost (shard_plan.hpp), and every N-th view cell of the visibility set; merge joins the
// parts and finishes them exactly as a whole bake does, so the package is byte-identical. A
// Slurm bake runs stages 0 to 2 once and its shards read the compiled level (bake/slurm/).
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "bake/embree/bake_scene.hpp"
#include "bake/grid/light_grid.hpp"
#include "bake/lighting/lights.hpp"
#include "bake/lightmap/chart_density.hpp"
#include "bake/lightmap/lightmap_bake.hpp"
#include "bake/probes/probe_capture.hpp"
#include "bake/report/report.hpp"
#include "bake/shard_plan.hpp"
#include "bake/visibility/visibility_bake.hpp"
#include "world/baked_lighting.hpp"
#include "world/compile/compile_level.hpp"
#include "world/source_level.hpp"

namespace onelight::bake {

enum class BakeQuality { kDraft, kDefault, kHigh };

/// "draft", "default", "high".
[[nodiscard]] const char* qualityName(BakeQuality quality);
[[nodiscard]] bool parseQuality(const std::string& text, BakeQuality& quality);

struct BakeOptions {
    BakeQuality quality = BakeQuality::kDefault;
    world::CompileOptions compile;
    LightSizes lightSizes;
    std::optional<glm::vec3> skyRadiance;  // cd/m^2, uniform sky; unset: the level's
    float gridCellSize = 1.0f;             // metres
    float probeSpacing = 8.0f;  // metres between automatic probes unless the level sets it
    bool probeSpacingOverridesLevel = false;  // --probe-spacing: wins over the level's
    uint32_t shardIndex = 0, shardCount = 1;
    bool showProgress = true;
    // Every light at every point with its own shadow rays, instead of lights drawn by
    // importance (light_cells.hpp, direct_light.hpp): the exact, slow baseline they are
    // measured against.
    bool allLights = false;
    // Every gathering direction a whole path, instead of cached bounce passes over the texels
    // (lightmap_bake.cpp): the unbiased, slow baseline the cache is measured against.
    bool pathsOnly = false;
    // The lightmaps' indirect part as estimated, without the denoiser (lightmap_denoise.hpp):
    // the baseline the denoiser is measured against.
    bool noDenoise = false;
    // The baked direct light's shadow edges without their distance field (direct_edges.hpp): the
    // texels' bilinear visibility only, the baseline the field is measured against.
    bool noDirectEdges = false;
    // Normal maps without their facet tables (facet_table.hpp): the footprint's facets from its
    // moments alone, the baseline the tables are measured against.
    bool noFacetTables = false;
    // Lightmap density per chart from a pilot pass (chart_density.hpp): charts whose light is
    // smooth get fewer texels. Off: every chart at the requested density. onelight-bake turns
    // it on unless --uniform-density.
    bool adaptiveDensity = false;
    // The potentially visible set (bake/visibility/), which the runtime culls by.
    bool visibility = true;
    // Take the source's own set where it has one (a Quake 3 map's q3map2 -vis,
    // SourceLevel::importedVisibility) instead of sampling one with rays: kaos bakes in 38 s
    // instead of 108, but the set is looser (a spawn's view drew 669 surfaces instead of 161,
    // 21% more frame time), so the rays stay the default.
    bool ownVisibility = false;
    VisibilitySettings visibilitySettings;
    // Overrides of the quality preset; 0 keeps the preset.
    uint32_t shadowSamples = 0, indirectSamples = 0, gridSamples = 0;
    uint32_t probeFaceSize = 0, probeSamples = 0;  // a power of two; paths per texel
    // --error-budget E (bake/budget/): 0 bakes everything; in (0, 1] leaves out what the
    // level's views are predicted not to need (probes, texels, grid cells) for a mean block
    // error of at most E. A whole bake only (no shards).
    float errorBudget = 0.0f;
};

/// Sample counts of a quality preset, overrides applied.
[[nodiscard]] LightmapSettings lightmapSettings(const BakeOptions& options);
[[nodiscard]] GridSettings gridSettings(const BakeOptions& options);
/// Environment probe capture of a quality preset: face size draft 32, default 64, high 128;
/// paths per texel 16, 64, 256; overrides applied.
[[nodiscard]] ProbeCaptureSettings probeSettings(const BakeOptions& options);

/// Stage 0, the texture stage: every mip the runtime uploads and the bake samples (whole in
/// every part of a sharded bake: it is deterministic), with `options`' facet tables or not. Adds
/// its stage to `report`.
[[nodiscard]] world::ProcessedTextures bakeTextures(const world::SourceLevel& source,
                                                    const BakeOptions& options, BakeReport& report);

/// Stage 1: the Embree scene of the source's static world, shaded with the texture stage's
/// mips, and everything the bake lights with. Built once per bake (once per part) and traced
/// by every later stage. Adds the "scene" stage and the light counts to `report`.
struct BakeWorld {
    BakeWorld(const world::SourceLevel& source, const world::ProcessedTextures& textures,
              const BakeOptions& options, BakeReport& report);
    std::chrono::steady_clock::time_point startedAt = std::chrono::steady_clock::now();
    EmbreeDevice device;
    BakeScene scene;
    BakeLights lights;
};

/// What stage 2, the world compile, makes: the compiled level (its charts at the densities
/// the pilot pass chose) and the pilot's settings, which the error budget reads again.
struct CompiledForBake {
    world::CompiledLevel level;
    world::CompileStats stats;
    ChartDensitySettings density;
};

/// Stage 2: the world compile, its region splitter asking the shadowed dominant primary, then
/// the density pilot and the charts compiled again at its densities. Adds the "compile" stage,
/// the pilot's figures and the import's notes to `report`.
[[nodiscard]] CompiledForBake compileForBake(const world::SourceLevel& source,
                                             const BakeWorld& world, const BakeOptions& options,
                                             BakeReport& report);

/// Stages 3 to 7 over `compiled` (a part of it for a shard): lightmaps, the error budget's
/// choices, light grid, probes, visibility set, dilation (a whole bake only). Adds each stage
/// to `report`.
[[nodiscard]] world::BakedLighting bakeLighting(const world::SourceLevel& source,
                                                const BakeWorld& world,
                                                const CompiledForBake& compiled,
                                                const BakeOptions& options, BakeReport& report);

/// The report a bake starts with: the level, quality, threads and shard.
[[nodiscard]] BakeReport startReport(const world::SourceLevel& source, const BakeOptions& options);

struct BakeResult {
    world::CompiledLevel level;
    world::ProcessedTextures textures;  // the texture stage's (bake/textures/texture_stage.hpp)
    world::CompileStats compileStats;
    world::BakedLighting baked;  // finished (dilated) when shardCount == 1
    BakeReport report;
};

/// Compiles and bakes `source` (or its shard): every stage above. Throws world::Error on bad
/// input and std::runtime_error on Embree failures.
[[nodiscard]] BakeResult bakeLevel(const world::SourceLevel& source, const BakeOptions& options);

/// The capture's side of each probe's statistic (probe_capture.hpp, shaders/probe.glsl): the light
/// grid's ambient cube sampled at the capture point exactly as world::sampleLightGrid samples the
/// finished grid, less every punctual light's direct light (GridSettings::punctualDirect false),
/// as the texels' side is (world::LightmapTexel::indirectIrradiance). Only the corner cells the
/// sample weighs are baked, into a scratch copy of `layout` (seeded per cell, so that their traced
/// part equals the grid stage's cells'): a shard gets the whole grid's value without the grid.
[[nodiscard]] std::vector<IrradianceCube> probeIrradianceCubes(
    const BakeScene& scene, const BakeLights& lights, const GridSettings& settings,
    const world::LightGrid& layout, const std::vector<ProbePlacement>& probes, RayCounts& rays);

/// Dilates the source format's own lightmap (importedTexels), which every part holds whole and
/// finishes itself: a package keeps only its light, not which texels were sampled, so a merge
/// could not dilate it as the whole bake does.
void finishImportedLightmap(const world::CompiledLevel& level, world::BakedLighting& baked);

/// The steps after every texel is baked: dilation of the lightmaps. Makes a part complete
/// (shard 0 of 1).
void finishBakedLighting(const world::CompiledLevel& level, world::BakedLighting& baked);

/// Joins the parts of a sharded bake (any order) into the unfinished whole, then finishes it.
/// Throws world::Error on a missing or repeated shard, mismatched sizes or grids; `names` (the
/// parts' files, in the order of `parts`) name the parts in messages.
[[nodiscard]] world::BakedLighting mergeBakedLighting(const world::CompiledLevel& level,
                                                      std::vector<world::BakedLighting> parts,
                                                      const std::vector<std::string>& names = {});

/// The package bytes of a bake result: the compiled level, its baked lighting and the texture
/// stage's mip chains.
[[nodiscard]] std::vector<uint8_t> packageBytes(const world::CompiledLevel& level,
                                                const world::BakedLighting& baked,
                                                const world::ProcessedTextures& textures);

}  // namespace onelight::bake
