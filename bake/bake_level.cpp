#include "bake/bake_level.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <stdexcept>

#include <tbb/global_control.h>

#include "bake/budget/error_budget.hpp"
#include "bake/dominant/dominant_primary.hpp"
#include "bake/embree/bake_scene.hpp"
#include "bake/lightmap/imported_lightmap.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "bake/probes/probe_placement.hpp"
#include "bake/textures/texture_stage.hpp"
#include "world/compile/static_split.hpp"
#include "world/error.hpp"
#include "world/light_grid_sample.hpp"
#include "world/package/baked_sections.hpp"
#include "world/package/package_writer.hpp"
#include "world/package/texture_section.hpp"

namespace onelight::bake {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Shadow rays per primary per point for the region splitter: it only ranks lights, and it
/// runs at many points, so fewer than the lightmaps.
constexpr uint32_t kDominantShadowSamples = 8;

/// What a quality preset bakes with, in BakeQuality's order.
struct QualityPreset {
    const char* name;          // as the command line says it
    uint32_t shadowSamples;    // per light and lightmap texel or grid cell
    uint32_t indirectSamples;  // paths per lightmap texel (and grid cell)
    uint32_t probeFaceSize;    // texels per probe cube face
    uint32_t probeSamples;     // paths per probe texel
    uint32_t bouncePasses;     // cached bounce passes over the lightmap texels
    uint32_t cacheSamples;     // gathering directions per texel in each of them
};
constexpr QualityPreset kQualityPresets[] = {{"draft", 8, 128, 32, 16, 3, 32},
                                             {"default", 16, 512, 64, 64, 4, 64},
                                             {"high", 32, 2048, 128, 256, 6, 128}};
static_assert(size_t(BakeQuality::kHigh) + 1 == std::size(kQualityPresets));

}  // namespace

const char* qualityName(BakeQuality quality) {
    return kQualityPresets[size_t(quality)].name;
}

bool parseQuality(const std::string& text, BakeQuality& quality) {
    for (size_t i = 0; i < std::size(kQualityPresets); ++i)
        if (text == kQualityPresets[i].name) {
            quality = BakeQuality(i);
            return true;
        }
    return false;
}

LightmapSettings lightmapSettings(const BakeOptions& options) {
    const QualityPreset& preset = kQualityPresets[size_t(options.quality)];
    LightmapSettings s;
    s.shadowSamples = options.shadowSamples ? options.shadowSamples : preset.shadowSamples;
    s.indirectSamples = options.indirectSamples ? options.indirectSamples : preset.indirectSamples;
    s.transport.sampleLights = !options.allLights;
    s.bouncePasses = options.pathsOnly ? 0 : preset.bouncePasses;
    s.cacheSamples = preset.cacheSamples;
    s.denoise.enabled = !options.noDenoise;
    s.directEdges = !options.noDirectEdges;
    return s;
}

GridSettings gridSettings(const BakeOptions& options) {
    GridSettings g;
    const LightmapSettings l = lightmapSettings(options);
    g.cellSize = options.gridCellSize;
    g.shadowSamples = l.shadowSamples;
    g.samples = options.gridSamples ? options.gridSamples : l.indirectSamples;
    g.transport = l.transport;
    return g;
}

ProbeCaptureSettings probeSettings(const BakeOptions& options) {
    const QualityPreset& preset = kQualityPresets[size_t(options.quality)];
    ProbeCaptureSettings p;
    p.faceSize = options.probeFaceSize ? options.probeFaceSize : preset.probeFaceSize;
    p.samplesPerTexel = options.probeSamples ? options.probeSamples : preset.probeSamples;
    p.transport.sampleLights = !options.allLights;
    return p;
}

BakeReport startReport(const world::SourceLevel& source, const BakeOptions& options) {
    if (!source.lightless.empty()) throw world::Error(source.lightless);
    if (options.shardCount == 0 || options.shardIndex >= options.shardCount)
        throw std::runtime_error("shard " + std::to_string(options.shardIndex) + "/" +
                                 std::to_string(options.shardCount) + "; expected index < count");
    BakeReport report;
    report.level = source.sourcePath;
    report.quality = qualityName(options.quality);
    report.threads = static_cast<uint32_t>(
        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
    report.shardIndex = options.shardIndex;
    report.shardCount = options.shardCount;
    report.lightSources = source.lightSources;
    return report;
}

world::ProcessedTextures bakeTextures(const world::SourceLevel& source, const BakeOptions& options,
                                      BakeReport& report) {
    const auto start = std::chrono::steady_clock::now();
    TextureStageOptions stageOptions;
    stageOptions.facetTables = !options.noFacetTables;
    world::ProcessedTextures textures =
        processLevelTextures(source, source.glossMips, stageOptions);
    const TextureStageReport stage = textureStageReport(textures);
    report.stages.push_back({"textures", secondsSince(start), {}, stage.textures.size()});
    report.textureBytes = stage.totalBytes;
    for (const ProcessedTextureRow& row : stage.textures)
        report.textures.push_back({row.name, texelFormatName(row.format), row.width, row.height,
                                   row.mipCount, row.bytes});
    return textures;
}

BakeWorld::BakeWorld(const world::SourceLevel& source, const world::ProcessedTextures& textures,
                     const BakeOptions& options, BakeReport& report)
    : scene(device, world::splitStaticDynamic(source).staticGeometry,
            processedSceneMaterials(source, textures)),
      lights(makeLevelLights(scene, source, options.lightSizes, options.skyRadiance)) {
    report.triangles = scene.triangleCount();
    for (const world::Light& l : source.lights)
        (l.role == world::LightRole::kPrimary ? report.primaryLights : report.bakedLights) += 1;
    report.emissiveTriangles = uint32_t(lights.emitters.triangles.size());
    report.stages.push_back({"scene", secondsSince(startedAt), {}, scene.triangleCount()});
}

CompiledForBake compileForBake(const world::SourceLevel& source, const BakeWorld& world,
                               const BakeOptions& options, BakeReport& report) {
    const auto start = std::chrono::steady_clock::now();
    CompiledForBake result;
    AtomicRayCount dominantRays;
    const world::PrimaryIlluminanceFn dominant = makeShadowedPrimaryIlluminance(
        world.scene, world.lights, kDominantShadowSamples, &dominantRays);
    {
        Progress progress("compile", 1, options.showProgress);
        world::CompileResult compiled = world::compileLevel(source, options.compile, &dominant);
        result.level = std::move(compiled.level);
        result.stats = compiled.stats;
        progress.advance(1);
    }
    // Density per chart: a pilot pass over the texels at the requested density, then the
    // charts compiled again with the coarser densities it chose (their shapes do not change).
    RayCounts pilotRays;
    const bool budgeted = options.errorBudget > 0.0f;
    result.density = budgeted ? chartDensityForBudget(options.errorBudget, result.level)
                              : ChartDensitySettings{};
    if (options.adaptiveDensity || budgeted) {
        const std::vector<TexelSample> pilotSamples = placeTexels(result.level);
        ChartDensityStats density;
        std::vector<float> scales = chartDensityScales(world.scene, world.lights, result.level,
                                                       pilotSamples, result.density, &density);
        pilotRays = density.rays;
        report.texelsBeforeDensity = pilotSamples.size();
        report.chartsReduced = density.chartsReduced;
        if (density.chartsReduced > 0) {
            world::CompileOptions coarser = options.compile;
            coarser.charts.densityScale = std::move(scales);
            world::CompileResult compiled = world::compileLevel(source, coarser, &dominant);
            result.level = std::move(compiled.level);
            result.stats = compiled.stats;
        }
    }
    StageReport stage{"compile", secondsSince(start), pilotRays, result.level.surfaces.size()};
    stage.rays.shadow += dominantRays.shadow.load();
    report.stages.push_back(stage);
    report.warnings.insert(report.warnings.end(), source.importNotes.begin(),
                           source.importNotes.end());
    return result;
}

world::BakedLighting bakeLighting(const world::SourceLevel& source, const BakeWorld& world,
                                  const CompiledForBake& compiled, const BakeOptions& options,
                                  BakeReport& report) {
    const BakeScene& scene = world.scene;
    const BakeLights& lights = world.lights;
    const world::CompiledLevel& level = compiled.level;
    const bool budgeted = options.errorBudget > 0.0f;

    // 3. Lightmaps.
    const LightmapSettings lm = lightmapSettings(options);
    const std::vector<TexelSample> samples = placeTexels(level);
    const uint64_t texelCount = totalTexels(level);
    BudgetGridChoice gridChoice;
    world::LightGrid grid = budgeted ? budgetGridLayout(level, gridSettings(options), gridChoice)
                                     : layoutLightGrid(level, gridSettings(options));
    const world::LightGrid gridLayout = grid;
    std::vector<ProbePlacement> placements = placeProbes(
        level, scene,
        ProbePlacementSettings{options.probeSpacing, options.probeSpacingOverridesLevel});
    checkProbeBudget(placements.size(), probeSettings(options).faceSize);
    for (const ProbePlacement& p : placements)
        if (p.insideSolid)
            report.warnings.push_back(
                "probe '" +
                (p.entity < level.entities.size() ? level.entities[p.entity].name : "placed") +
                "' at (" + std::to_string(p.position.x) + ", " + std::to_string(p.position.y) +
                ", " + std::to_string(p.position.z) +
                ") is inside solid geometry: its reflections will be dark; move it into the open");
    world::BakedLighting baked;
    baked.shardIndex = options.shardIndex;
    baked.shardCount = options.shardCount;
    baked.shardRange = {
        0, level.charts.size(), 0, grid.cells.size(), 0, placements.size(), placements.size()};
    const std::vector<uint32_t> chartOrder = chartSpaceOrder(level);
    if (options.shardCount > 1) {
        const ShardCosts costs =
            estimateShardCosts(lights, level, chartOrder, samples, grid, placements.size(), lm,
                               gridSettings(options), probeSettings(options));
        report.shardCostTotal = shardCost(costs, baked.shardRange);
        baked.shardRange = shardRange(costs, options.shardIndex, options.shardCount);
        report.shardCost = shardCost(costs, baked.shardRange);
    }
    const world::ShardRange& range = baked.shardRange;
    const std::vector<uint32_t> ownedSamples = samplesOfRange(level, chartOrder, samples, range);
    baked.texels.assign(texelCount, world::LightmapTexel{});
    baked.shadowMask.assign(texelCount, 0);
    // The source's own bake at the same texels (every shard holds all of it; it is cheap).
    baked.importedTexels =
        resampleImportedLightmap(world.device.handle(), level, samples, source.importedLightmap);
    auto start = std::chrono::steady_clock::now();
    // The lightmaps' cached bounces, which the grid and the probes read too.
    RadianceCache bounceCache;
    if (source.lightmapIsImported) {
        // The source's own lightmaps are the level's (a Quake 3 map whose light entities are
        // lost: q3_import.hpp): copied, not baked; the grid and probes trace the lights left.
        uint64_t copied = 0;
        for (const uint32_t i : ownedSamples) {
            const uint64_t texel = samples[i].texel;
            if (texel < baked.importedTexels.size() &&
                (baked.importedTexels[texel].flags & world::kLightmapTexelSampled)) {
                baked.texels[texel] = baked.importedTexels[texel];
                ++copied;
            }
        }
        report.stages.push_back({"lightmaps", secondsSince(start), {}, copied});
        report.texelsSampled = copied;
    } else {
        Progress progress("lightmaps", lightmapWorkUnits(samples.size(), ownedSamples.size(), lm),
                          options.showProgress);
        const LightmapStats stats = bakeLightmapTexels(
            scene, lights, level, samples, lm, ownedSamples, baked, &progress, &bounceCache);
        progress.finish();
        report.stages.push_back({"lightmaps", secondsSince(start), stats.rays, stats.texelsBaked});
        report.texelsSampled = stats.texelsBaked;
        report.texelsGathered = stats.texelsGathered;
        report.texelsMoved = stats.texelsMoved;
        report.lightmapMeanRelativeNoise = stats.meanRelativeNoise;
        report.lightmapDenoisedRelativeNoise = stats.meanRelativeNoiseDenoised;
    }
    report.texelsTotal = texelCount;
    report.shadowSamplesPerLight = lm.shadowSamples;
    report.indirectSamplesPerTexel = lm.indirectSamples;

    // 3b. The error budget's choices (a whole bake only: the CLI refuses shards).
    if (budgeted) {
        start = std::chrono::steady_clock::now();
        TransportSettings transport;
        if (!bounceCache.empty()) transport.cache = &bounceCache;
        RayCounts rays;
        chooseWithinBudget(scene, lights, transport, level, options.errorBudget, compiled.density,
                           grid, gridChoice, placements, rays, report);
        baked.budget = report.budget;
        report.stages.push_back(
            {"budget", secondsSince(start), rays, report.budget.viewsPredicted});
    }

    // 4. Light grid.
    start = std::chrono::steady_clock::now();
    {
        GridSettings gs = gridSettings(options);
        if (!bounceCache.empty()) gs.transport.cache = &bounceCache;
        Progress progress("grid", range.cellEnd - range.cellBegin, options.showProgress);
        const GridStats stats =
            bakeLightGrid(scene, lights, gs, range.cellBegin, range.cellEnd, grid, &progress);
        progress.finish();
        report.stages.push_back({"grid", secondsSince(start), stats.rays, stats.cellsBaked});
        report.gridCells = grid.cells.size();
        report.gridCellsInside = stats.cellsInside;
        report.gridSamplesPerCell = gs.samples;
    }
    baked.grid = std::move(grid);

    // 5. Environment probes (only where the level has them: placeProbes decides), this part's.
    start = std::chrono::steady_clock::now();
    if (!placements.empty()) {
        ProbeCaptureSettings ps = probeSettings(options);
        GridSettings gs = gridSettings(options);
        if (!bounceCache.empty()) gs.transport.cache = ps.transport.cache = &bounceCache;
        RayCounts rays;
        // The statistic of this part's probes only (each probe's is independent of the others').
        const std::vector<ProbePlacement> owned(placements.begin() + long(range.probeBegin),
                                                placements.begin() + long(range.probeEnd));
        const std::vector<IrradianceCube> ownedIrradiance =
            probeIrradianceCubes(scene, lights, gs, gridLayout, owned, rays);
        std::vector<IrradianceCube> irradiance(placements.size(), IrradianceCube{});
        std::copy(ownedIrradiance.begin(), ownedIrradiance.end(),
                  irradiance.begin() + long(range.probeBegin));
        // Each probe is seeded by its index among all the level's.
        baked.probes = bakeProbes(scene, lights, placements, irradiance, ps, range.probeBegin,
                                  range.probeEnd, options.showProgress, rays);
        report.stages.push_back({"probes", secondsSince(start), rays, baked.probes.size()});
        report.probesTotal = placements.size();
        report.probesBaked = baked.probes.size();
        report.probeFaceSize = ps.faceSize;
        report.probeSamplesPerTexel = ps.samplesPerTexel;
        if (!baked.probes.empty())
            report.probeBytes = package::encodeProbeSection(baked.probes).bytes.size();
    }

    // 6. The potentially visible set: a shard samples every N-th view cell (interleaved); the
    // merge joins the parts' cells and finishes them.
    if (options.visibility) {
        start = std::chrono::steady_clock::now();
        const BakeScene levelScene(world.device, level);
        VisibilityStats stats;
        // A Quake 3 map's own set (q3map2 -vis) bounds the rays, or replaces them when asked.
        const world::ImportedVisibility& imported = source.importedVisibility;
        baked.visibility =
            bakeVisibility(levelScene, level, options.visibilitySettings, options.showProgress,
                           &stats, options.shardIndex, options.shardCount, &imported,
                           options.ownVisibility ? ImportedVisibilityUse::kReplacesTheRays
                                                 : ImportedVisibilityUse::kBoundsTheRays);
        report.visibilitySource = imported.empty()        ? "sampled"
                                  : options.ownVisibility ? "the source's own"
                                                          : "sampled within the source's own";
        report.stages.push_back({"visibility", secondsSince(start), stats.rays, stats.cells});
        report.visibilityCells = stats.cells;
        report.visibilityClusters = stats.clusters;
        report.visibilityRows = stats.rows;
        report.visibilityMeanFraction = stats.meanVisibleFraction;
    }

    // 7. Finish (a whole bake only; parts are finished by merge).
    start = std::chrono::steady_clock::now();
    finishImportedLightmap(level, baked);  // whole in every part: each finishes its copy
    if (options.shardCount == 1) finishBakedLighting(level, baked);
    report.stages.push_back({"dilate", secondsSince(start), {}, texelCount});
    report.peakMemoryBytes = peakMemoryBytes();
    return baked;
}

BakeResult bakeLevel(const world::SourceLevel& source, const BakeOptions& options) {
    BakeResult result;
    result.report = startReport(source, options);
    result.textures = bakeTextures(source, options, result.report);
    const BakeWorld world(source, result.textures, options, result.report);
    CompiledForBake compiled = compileForBake(source, world, options, result.report);
    result.baked = bakeLighting(source, world, compiled, options, result.report);
    result.level = std::move(compiled.level);
    result.compileStats = compiled.stats;
    return result;
}

std::vector<IrradianceCube> probeIrradianceCubes(const BakeScene& scene, const BakeLights& lights,
                                                 const GridSettings& settings,
                                                 const world::LightGrid& layout,
                                                 const std::vector<ProbePlacement>& probes,
                                                 RayCounts& rays) {
    std::vector<IrradianceCube> cubes(probes.size(), IrradianceCube{});
    if (layout.cells.empty()) return cubes;
    // The light a probe reflects: without the punctual lights' direct light, which the texels
    // keep apart and reflect by a lobe of their own (docs/lighting.md "Normalisation").
    GridSettings indirect = settings;
    indirect.punctualDirect = false;
    world::LightGrid scratch = layout;
    std::vector<uint8_t> baked(scratch.cells.size(), 0);
    for (size_t i = 0; i < probes.size(); ++i) {
        const world::LightGridSample corners = world::sampleLightGrid(scratch, probes[i].position);
        for (size_t k = 0; k < corners.cells.size(); ++k) {
            const uint32_t c = corners.cells[k];
            if (corners.weights[k] <= 0.0f || baked[c]) continue;
            rays += bakeLightGrid(scene, lights, indirect, c, c + 1, scratch, nullptr).rays;
            baked[c] = 1;
        }
        cubes[i] = world::sampleLightGrid(scratch, probes[i].position).ambientCube;
    }
    return cubes;
}

void finishImportedLightmap(const world::CompiledLevel& level, world::BakedLighting& baked) {
    if (baked.importedTexels.empty()) return;
    world::BakedLighting imported;
    imported.texels = std::move(baked.importedTexels);
    imported.shadowMask.assign(imported.texels.size(), 0);
    dilateLightmaps(level, imported);
    baked.importedTexels = std::move(imported.texels);
}

void finishBakedLighting(const world::CompiledLevel& level, world::BakedLighting& baked) {
    dilateLightmaps(level, baked);
    baked.shardIndex = 0;
    baked.shardCount = 1;
}

world::BakedLighting mergeBakedLighting(const world::CompiledLevel& level,
                                        std::vector<world::BakedLighting> parts,
                                        const std::vector<std::string>& names) {
    if (parts.empty()) throw world::Error("merge: no parts given");
    auto name = [&](size_t i) {
        return i < names.size() ? names[i] : "part " + std::to_string(i + 1);
    };
    const uint32_t count = parts[0].shardCount;
    if (count == 1)
        throw world::Error("merge: " + name(0) +
                           " is a complete package (a bake of one shard); expected the parts of "
                           "one sharded bake (onelight-bake --shard i/N)");
    if (parts.size() != count)
        throw world::Error("merge: " + std::to_string(parts.size()) + " parts given; " + name(0) +
                           " is a part of " + std::to_string(count));
    uint32_t faceSize = 0;  // the first part's probes', which every part's must match
    size_t faceSizeOf = 0;
    std::vector<const world::BakedLighting*> byIndex(count, nullptr);
    std::vector<size_t> partOfShard(count, 0);
    const uint64_t texels = totalTexels(level);
    const world::LightGrid& grid0 = parts[0].grid;
    for (size_t i = 0; i < parts.size(); ++i) {
        const world::BakedLighting& p = parts[i];
        const std::string shard = name(i) + " (shard " + std::to_string(p.shardIndex) + "/" +
                                  std::to_string(p.shardCount) + ")";
        if (p.shardCount != count || p.shardIndex >= count)
            throw world::Error("merge: " + shard + "; expected a part of " + std::to_string(count) +
                               " like " + name(0));
        if (byIndex[p.shardIndex])
            throw world::Error("merge: " + shard + ": shard " + std::to_string(p.shardIndex) +
                               " is also " + name(partOfShard[p.shardIndex]));
        if (p.texels.size() != texels || p.shadowMask.size() != texels ||
            p.grid.cells.size() != grid0.cells.size() || p.grid.dims != grid0.dims ||
            p.importedTexels.size() != parts[0].importedTexels.size())
            throw world::Error("merge: " + shard + " does not match the level of " + name(0) +
                               " (texel or grid cell counts differ)");
        if (p.grid.origin != grid0.origin || p.grid.cellSize != grid0.cellSize ||
            p.grid.samples != grid0.samples)
            throw world::Error("merge: " + shard + ": its light grid's origin, cell size or " +
                               "samples differ from " + name(0) +
                               "'s; expected the same grid (baked with other settings?)");
        const world::Visibility &v = p.visibility, &v0 = parts[0].visibility;
        if (v.empty() != v0.empty() || v.dims != v0.dims || v.origin != v0.origin ||
            v.cellSize != v0.cellSize || v.clusterCount != v0.clusterCount ||
            v.surfaceCluster != v0.surfaceCluster)
            throw world::Error("merge: " + shard + ": its visibility set's " +
                               (v.empty() != v0.empty() ? "presence" : "cells or clusters") +
                               " differ from " + name(0) +
                               "'s; expected the same view cells (baked with other settings?)");
        for (const world::EnvironmentProbe& probe : p.probes) {
            if (faceSize == 0) faceSize = probe.faceSize, faceSizeOf = i;
            if (probe.faceSize != faceSize)
                throw world::Error("merge: " + shard + ": its probes are " +
                                   std::to_string(probe.faceSize) + " texels a face; expected " +
                                   std::to_string(faceSize) + " like " + name(faceSizeOf) +
                                   "'s (baked with another --probe-face-size?)");
        }
        byIndex[p.shardIndex] = &p;
        partOfShard[p.shardIndex] = i;
    }
    // The parts' ranges (section 40) must tile every chart, cell and probe, in shard order.
    world::ShardRange next;
    next.probeTotal = byIndex[0]->shardRange.probeTotal;
    for (uint32_t i = 0; i < count; ++i) {
        const world::ShardRange& r = byIndex[i]->shardRange;
        if (r.chartBegin != next.chartEnd || r.cellBegin != next.cellEnd ||
            r.probeBegin != next.probeEnd || r.probeTotal != next.probeTotal)
            throw world::Error(
                "merge: " + name(partOfShard[i]) + " (shard " + std::to_string(i) + "/" +
                std::to_string(count) + ") holds charts [" + std::to_string(r.chartBegin) + ", " +
                std::to_string(r.chartEnd) + "), cells [" + std::to_string(r.cellBegin) + ", " +
                std::to_string(r.cellEnd) + "), probes [" + std::to_string(r.probeBegin) + ", " +
                std::to_string(r.probeEnd) + ") of " + std::to_string(r.probeTotal) +
                "; expected to start " +
                (i == 0 ? std::string("at 0") : "where shard " + std::to_string(i - 1) + " ends") +
                " (chart " + std::to_string(next.chartEnd) + ", cell " +
                std::to_string(next.cellEnd) + ", probe " + std::to_string(next.probeEnd) + " of " +
                std::to_string(next.probeTotal) + "): parts of one bake?");
        next = r;
    }
    if (next.chartEnd != level.charts.size() || next.cellEnd != grid0.cells.size() ||
        next.probeEnd != next.probeTotal)
        throw world::Error("merge: the last shard ends at chart " + std::to_string(next.chartEnd) +
                           ", cell " + std::to_string(next.cellEnd) + ", probe " +
                           std::to_string(next.probeEnd) + "; expected " +
                           std::to_string(level.charts.size()) + ", " +
                           std::to_string(grid0.cells.size()) + " and " +
                           std::to_string(next.probeTotal) + " (every one baked by some shard)");
    world::BakedLighting merged = parts[0];
    const std::vector<uint32_t> chartOrder = chartSpaceOrder(level);
    for (uint32_t i = 0; i < count; ++i) {
        const world::BakedLighting& p = *byIndex[i];
        const world::ShardRange& r = p.shardRange;
        // Every texel of the part's charts' rectangles (padding included).
        for (uint64_t k = r.chartBegin; k < r.chartEnd; ++k) {
            const world::Chart& chart = level.charts[chartOrder[k]];
            const uint64_t base = world::atlasTexelOffset(level, chart.atlas);
            const uint32_t width = level.atlases[chart.atlas].width;
            for (uint32_t y = chart.y; y < chart.y + chart.height; ++y)
                for (uint32_t x = chart.x; x < chart.x + chart.width; ++x) {
                    const uint64_t t = base + uint64_t(y) * width + x;
                    merged.texels[t] = p.texels[t];
                    merged.shadowMask[t] = p.shadowMask[t];
                }
        }
        for (uint64_t c = r.cellBegin; c < r.cellEnd; ++c) merged.grid.cells[c] = p.grid.cells[c];
    }
    std::vector<const world::Visibility*> visibility;
    for (uint32_t i = 0; i < count; ++i) visibility.push_back(&byIndex[i]->visibility);
    merged.visibility = mergeVisibilityParts(visibility);
    // The imported lightmap is parts[0]'s, finished in its shard (each part holds all of it).
    // Each part holds its contiguous range of the probes: in shard order they are the whole list.
    merged.probes.clear();
    for (uint32_t i = 0; i < count; ++i)
        merged.probes.insert(merged.probes.end(), byIndex[i]->probes.begin(),
                             byIndex[i]->probes.end());
    finishBakedLighting(level, merged);
    merged.shardRange = {
        0, level.charts.size(), 0, grid0.cells.size(), 0, next.probeTotal, next.probeTotal};
    return merged;
}

std::vector<uint8_t> packageBytes(const world::CompiledLevel& level,
                                  const world::BakedLighting& baked,
                                  const world::ProcessedTextures& textures) {
    std::vector<package::RawSection> sections = package::encodeBakedSections(baked);
    sections.push_back(package::encodeTextureSection(textures));
    return package::serializePackage(level, sections);
}

}  // namespace onelight::bake
