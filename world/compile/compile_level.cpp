#include "world/compile/compile_level.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <numeric>

#include "world/compile/static_split.hpp"
#include "world/error.hpp"
#include "world/features/feature_analysis.hpp"

namespace onelight::world {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

void grow(glm::vec3& lo, glm::vec3& hi, const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
}

Vertex toVertex(const CompileVertex& v) {
    Vertex out;
    out.position = glm::vec3(v.position);
    out.normal = v.normal;
    out.tangent = v.tangent;
    out.uv0 = v.uv0;
    out.uv1 = v.uv1;
    return out;
}

/// Leaf by leaf: triangles sorted by (material, primary, chart) and grouped into surfaces;
/// vertices compacted in order of first use.
void buildSurfaces(const StaticGeometry& geometry, const BspBuild& bsp,
                   const std::vector<uint32_t>& lightOfPrimary, uint32_t primaryCount,
                   const PrimaryIlluminanceFn& illuminance, const ChartLayout& charts,
                   CompiledLevel& level) {
    std::vector<uint32_t> newIndex(geometry.vertices.size(), kNoIndex);
    level.bspLeaves = bsp.leaves;
    for (size_t leaf = 0; leaf < level.bspLeaves.size(); ++leaf) {
        BspLeaf& l = level.bspLeaves[leaf];
        std::vector<uint32_t> order(l.triangleCount);
        std::iota(order.begin(), order.end(), l.firstTriangle);
        std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
            const StaticTriangle &x = geometry.triangles[a], &y = geometry.triangles[b];
            return std::tie(x.material, x.primary, x.chart) <
                   std::tie(y.material, y.primary, y.chart);
        });
        l.firstSurface = static_cast<uint32_t>(level.surfaces.size());
        l.boundsMin = glm::vec3(INFINITY);
        l.boundsMax = glm::vec3(-INFINITY);
        for (size_t i = 0; i < order.size();) {
            const StaticTriangle& first = geometry.triangles[order[i]];
            size_t j = i;
            Surface s;
            s.firstIndex = static_cast<uint32_t>(level.indices.size());
            s.material = first.material;
            s.primaryLight = first.primary == kNoIndex ? kNoIndex : lightOfPrimary[first.primary];
            s.chart = first.chart;
            const Chart& c = charts.charts[first.chart];
            s.atlas = c.atlas;
            s.lightmapX = c.x;
            s.lightmapY = c.y;
            s.lightmapWidth = c.width;
            s.lightmapHeight = c.height;
            s.leaf = static_cast<uint32_t>(leaf);
            s.boundsMin = glm::vec3(INFINITY);
            s.boundsMax = glm::vec3(-INFINITY);
            std::vector<StaticTriangle> members;
            for (; j < order.size(); ++j) {
                const StaticTriangle& t = geometry.triangles[order[j]];
                if (t.material != first.material || t.primary != first.primary ||
                    t.chart != first.chart)
                    break;
                members.push_back(t);
                for (uint32_t id : t.v) {
                    if (newIndex[id] == kNoIndex) {
                        newIndex[id] = static_cast<uint32_t>(level.vertices.size());
                        level.vertices.push_back(toVertex(geometry.vertices[id]));
                    }
                    level.indices.push_back(newIndex[id]);
                    grow(s.boundsMin, s.boundsMax, level.vertices[newIndex[id]].position);
                }
            }
            s.indexCount = static_cast<uint32_t>(level.indices.size()) - s.firstIndex;
            if (primaryCount > 0) {
                s.firstGivenUp = static_cast<uint32_t>(level.givenUpLights.size());
                for (uint32_t p :
                     givenUpPrimaries(geometry, members, first.primary, primaryCount, illuminance))
                    level.givenUpLights.push_back(lightOfPrimary[p]);
                s.givenUpCount = static_cast<uint32_t>(level.givenUpLights.size()) - s.firstGivenUp;
            } else {
                s.firstGivenUp = static_cast<uint32_t>(level.givenUpLights.size());
            }
            grow(l.boundsMin, l.boundsMax, s.boundsMin);
            grow(l.boundsMin, l.boundsMax, s.boundsMax);
            level.surfaces.push_back(s);
            i = j;
        }
        l.surfaceCount = static_cast<uint32_t>(level.surfaces.size()) - l.firstSurface;
        if (l.triangleCount == 0) l.boundsMin = l.boundsMax = glm::vec3(0.0f);
    }
}

void boundNodes(CompiledLevel& level) {
    // Children have larger indices than their parent: fill from the back.
    for (size_t i = level.bspNodes.size(); i-- > 0;) {
        BspNode& n = level.bspNodes[i];
        n.boundsMin = glm::vec3(INFINITY);
        n.boundsMax = glm::vec3(-INFINITY);
        for (int32_t child : {n.front, n.back}) {
            glm::vec3 lo, hi;
            bool empty;
            if (child >= 0) {
                const BspNode& c = level.bspNodes[static_cast<size_t>(child)];
                lo = c.boundsMin;
                hi = c.boundsMax;
                empty = lo.x > hi.x;
            } else {
                const BspLeaf& c = level.bspLeaves[static_cast<size_t>(-child - 1)];
                lo = c.boundsMin;
                hi = c.boundsMax;
                empty = c.triangleCount == 0;
            }
            if (!empty) {
                grow(n.boundsMin, n.boundsMax, lo);
                grow(n.boundsMin, n.boundsMax, hi);
            }
        }
        if (n.boundsMin.x > n.boundsMax.x) n.boundsMin = n.boundsMax = glm::vec3(0.0f);
    }
}

// Refuses, before anything allocates a texel, a lightmap the bake could not hold: the figure,
// the memory it would take and the limit (docs/limits.md), rather than "out of memory" later.
void checkLightmapBudget(const ChartLayout& charts, const ChartOptions& options,
                         const std::string& path) {
    if (charts.texelCount <= kMaxLightmapTexels) return;
    char text[320];
    std::snprintf(text, sizeof text,
                  ": %llu lightmap texels in %zu atlases at %g texels per metre (%.1f GB to bake);"
                  " expected at most %llu texels (%.1f GB): lower the density "
                  "(--texels-per-metre or extras.onelight.texels_per_metre)",
                  static_cast<unsigned long long>(charts.texelCount), charts.atlases.size(),
                  options.texelsPerMetre, double(charts.texelCount) * kBakeBytesPerTexel * 1e-9,
                  static_cast<unsigned long long>(kMaxLightmapTexels),
                  double(kMaxLightmapTexels) * kBakeBytesPerTexel * 1e-9);
    throw Error(path + text);
}

}  // namespace

CompileResult compileLevel(const SourceLevel& source, const CompileOptions& options,
                           const PrimaryIlluminanceFn* illuminance) {
    CompileResult result;
    CompileStats& stats = result.stats;
    CompiledLevel& level = result.level;

    Clock::time_point start = Clock::now();
    SplitLevel split = splitStaticDynamic(source);
    StaticGeometry& geometry = split.staticGeometry;
    stats.degenerateRemoved = split.degenerateRemoved;
    stats.duplicatesRemoved = split.duplicatesRemoved;
    stats.sourceTriangles =
        geometry.triangles.size() + split.degenerateRemoved + split.duplicatesRemoved;
    for (const DynamicMesh& mesh : split.dynamicMeshes)
        stats.dynamicTriangles += mesh.indexCount / 3;
    stats.dynamicTrianglesShared = stats.dynamicTriangles - split.dynamicIndices.size() / 3;
    stats.secondsSplit = secondsSince(start);

    std::vector<Light> primaries;
    std::vector<uint32_t> lightOfPrimary;
    for (size_t i = 0; i < source.lights.size(); ++i) {
        if (source.lights[i].role != LightRole::kPrimary) continue;
        primaries.push_back(source.lights[i]);
        lightOfPrimary.push_back(static_cast<uint32_t>(i));
    }
    const uint32_t primaryCount = static_cast<uint32_t>(primaries.size());
    stats.primaryCandidates = primaryCount;
    const PrimaryIlluminanceFn unshadowed = makeUnshadowedPrimaryIlluminance(primaries);
    const PrimaryIlluminanceFn& lightAt = illuminance ? *illuminance : unshadowed;

    start = Clock::now();
    stats.regions = assignPrimaryRegions(geometry, primaryCount, lightAt, options.regions);
    stats.secondsRegions = secondsSince(start);

    start = Clock::now();
    ChartOptions chartOptions = options.charts;
    if (source.texelsPerMetre > 0.0f && !chartOptions.densityFromCommandLine)
        chartOptions.texelsPerMetre = double(source.texelsPerMetre);
    const ChartLayout charts = buildLightmapCharts(geometry, chartOptions);
    stats.secondsCharts = secondsSince(start);
    checkLightmapBudget(charts, chartOptions, source.sourcePath);

    start = Clock::now();
    const BspBuild bsp = buildBsp(geometry, options.bsp);
    stats.secondsBsp = secondsSince(start);

    start = Clock::now();
    level.materials = source.materials;
    level.textures = source.textures;
    level.images = source.images;
    level.lights = source.lights;
    level.cameras = source.cameras;
    level.charts = charts.charts;
    level.atlases = charts.atlases;
    level.bspPlanes = bsp.planes;
    level.bspNodes = bsp.nodes;
    buildSurfaces(geometry, bsp, lightOfPrimary, primaryCount, lightAt, charts, level);
    boundNodes(level);
    level.dynamicVertices = std::move(split.dynamicVertices);
    level.dynamicIndices = std::move(split.dynamicIndices);
    level.dynamicMeshes = std::move(split.dynamicMeshes);
    level.entities = std::move(split.entities);
    level.collision = source.collision;  // already in metres, Y up
    level.movers = source.movers;        // by entity index, which the split keeps

    LevelSettings& settings = level.settings;
    settings.exposureEv100 = source.exposureEv100;
    settings.hasExposure = source.hasExposure;
    settings.texelsPerMetre = static_cast<float>(chartOptions.texelsPerMetre);
    settings.probeSpacing = source.probeSpacing;
    settings.diffuseModel = source.diffuseModel;
    settings.glossMips = source.glossMips;
    settings.skyRadiance = source.skyRadiance;
    settings.skyImage = source.skyImage;
    if (!level.vertices.empty()) {
        settings.boundsMin = glm::vec3(INFINITY);
        settings.boundsMax = glm::vec3(-INFINITY);
        for (const Vertex& v : level.vertices)
            grow(settings.boundsMin, settings.boundsMax, v.position);
    }
    level.features = analyseFeatures(level, source.hasGridBounds, source.gridMin, source.gridMax);
    stats.secondsSurfaces = secondsSince(start);

    stats.triangles = level.indices.size() / 3;
    stats.surfaces = level.surfaces.size();
    stats.bspDepth = bsp.depth;
    stats.bspLeaves = bsp.leaves.size();
    stats.bspNodes = bsp.nodes.size();
    stats.bspSplits = bsp.splits;
    std::vector<uint8_t> used(source.lights.size(), 0);
    for (const Surface& s : level.surfaces)
        if (s.primaryLight != kNoIndex) used[s.primaryLight] = 1;
    stats.primariesUsed = static_cast<uint32_t>(std::count(used.begin(), used.end(), 1));
    stats.charts = charts.charts.size();
    stats.authoredCharts = static_cast<uint64_t>(std::count_if(
        charts.charts.begin(), charts.charts.end(), [](const Chart& c) { return c.authored; }));
    stats.atlases = charts.atlases.size();
    stats.texels = charts.texelCount;
    stats.fillRatio = charts.fillRatio;
    return result;
}

}  // namespace onelight::world
