// Baked lighting in memory: what the baker produces and what the runtime reads back from the
// package's sections 32..39 (their on-disk twins are in package/format.hpp). Plain data.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"
#include "world/visibility.hpp"

namespace onelight::world {

enum LightmapTexelFlags : uint32_t {
    kLightmapTexelSampled = 1u << 0,  // baked at a point of its own surface
    kLightmapTexelDilated = 1u << 1,  // padding, copied from sampled neighbours
};
inline constexpr uint32_t kAllLightmapTexelFlags = kLightmapTexelSampled | kLightmapTexelDilated;

/// A texel's distance to its baked direct light's shadow edge is kept to this many texels (the
/// bilinear filter reads the four texels around a point, each within 1.5 texels of an edge
/// through their cell), its penumbra's width to at most kDirectEdgeMaxWidth texels (the runtime's
/// twins: DIRECT_EDGE_REACH and DIRECT_EDGE_MAX_WIDTH, shaders/gpu_interface.glsl).
inline constexpr float kDirectEdgeReach = 2.0f;
inline constexpr float kDirectEdgeMaxWidth = 1.0f;

/// One lightmap texel: directional secondary irradiance (see DiskLightmapTexel for the
/// reconstruction E(n') = irradiance * max(0, 0.5 + n'.direction) / normalWeight), and the two
/// parts the probes' specular needs apart (docs/lighting.md "Normalisation"): the baked punctual
/// lights' direct light, as one light of its own, and the rest's average over normals.
struct LightmapTexel {
    glm::vec3 irradiance{0.0f};  // lux at the surface normal, >= 0
    glm::vec3 direction{0.0f};   // |direction| <= 0.5
    float normalWeight = 1.0f;   // 0.5 + dot(normal, direction)
    uint32_t flags = 0;          // LightmapTexelFlags; 0 = outside every chart (all zero)
    // The baked punctual lights' shadowed direct light (a part of `irradiance`) as one light
    // from directLight: lux on a surface facing it, so that it gives directIrradiance
    // max(0, n'.directLight) at a normal n'. Zero (and directLight 0) where none reaches.
    glm::vec3 directIrradiance{0.0f};  // >= 0
    glm::vec3 directLight{0.0f};       // unit, towards the light; 0 when directIrradiance is 0
    // The rest (bounces, sky, emitters: irradiance - the direct light at the surface normal),
    // the pixel's side of the probes' statistic (shaders/probe.glsl, "Normalization"): lux,
    // >= 0, at the surface normal.
    glm::vec3 indirectIrradiance{0.0f};
    // The direct light's shadow edge (bake/lightmap/direct_edges.hpp, docs/lighting.md "Baked
    // shadow edges"): its visibility, the luminance of directIrradiance over the same lights
    // unshadowed (1 where none reaches); near a sharp edge, the signed distance to the line half
    // way between the edge's two levels of visibility (texels, + on the lit side, within
    // +-kDirectEdgeReach), the penumbra's width across it (texels), the two levels, and the share
    // the runtime gives the edge over the bilinear visibility (1 near an edge it draws, else 0,
    // with both levels the texel's visibility).
    float directVisibility = 1.0f;                // [0, 1]
    float directEdgeDistance = kDirectEdgeReach;  // [-kDirectEdgeReach, kDirectEdgeReach]
    float directEdgeWidth = 0.0f;                 // [0, kDirectEdgeMaxWidth]
    float directEdgeLow = 1.0f;                   // [0, directEdgeHigh]
    float directEdgeHigh = 1.0f;                  // [directEdgeLow, 1]
    float directEdgeSharpness = 0.0f;             // [0, 1]
};

enum LightGridCellFlags : uint32_t {
    kLightGridCellInsideSolid = 1u << 0,  // centre inside geometry: skip when interpolating
};
inline constexpr uint32_t kAllLightGridCellFlags = kLightGridCellInsideSolid;

struct LightGridCell {
    std::array<glm::vec3, 6> ambientCube{};  // lux facing +x -x +y -y +z -z
    uint32_t dominantPrimary = kNoIndex;     // into lights
    float primaryVisibility = 0.0f;          // [0, 1]
    uint32_t flags = 0;                      // LightGridCellFlags
};

/// A light grid's limits, checked by the package reader (docs/limits.md): every axis has at
/// least one cell, and the whole grid at most kMaxLightGridCells (1.4 GB of cells on disk).
inline constexpr uint32_t kMaxLightGridCellsPerAxis = 4096;
inline constexpr uint64_t kMaxLightGridCells = uint64_t(1) << 24;

struct LightGrid {
    glm::vec3 origin{0.0f};    // metres, minimum corner
    glm::vec3 cellSize{1.0f};  // metres
    glm::uvec3 dims{0u};
    uint32_t samples = 0;
    std::vector<LightGridCell> cells;  // x fastest
};

/// The centre of cell `cell` (x fastest) of `grid`, metres, world.
[[nodiscard]] inline glm::vec3 lightGridCellCentre(const LightGrid& grid, uint64_t cell) {
    const auto x = static_cast<uint32_t>(cell % grid.dims.x);
    const auto y = static_cast<uint32_t>((cell / grid.dims.x) % grid.dims.y);
    const auto z = static_cast<uint32_t>(cell / (uint64_t(grid.dims.x) * grid.dims.y));
    return grid.origin + (glm::vec3(x, y, z) + 0.5f) * grid.cellSize;
}

/// What `onelight-bake --error-budget E` chose to leave out of a level, and the error each
/// choice is predicted to cost (section 39; bake/budget/ decides, docs/level-report.md "Error
/// budget"). Errors are the level report's measure: the mean relative error of 8x8-pixel blocks
/// over the level's views. The runtime honours the choices (probesDropped: the shader
/// permutation without probes).
enum ErrorBudgetFlags : uint32_t {
    kBudgetProbesDropped = 1u << 0,  // no probe baked: a uniform environment instead
    kBudgetGridReduced = 1u << 1,    // the grid covers only where dynamic objects can go
};
inline constexpr uint32_t kAllErrorBudgetFlags = kBudgetProbesDropped | kBudgetGridReduced;

struct ErrorBudgetChoices {
    float budget = 0.0f;            // E in (0, 1]; 0: baked without a budget
    uint32_t flags = 0;             // ErrorBudgetFlags
    float probeError = 0.0f;        // predicted cost of a uniform environment, [0, inf)
    uint32_t probesPlaced = 0;      // probes the level would have had
    float densityTolerance = 0.0f;  // the chart density's curvature tolerance used
    float lightmapError = 0.0f;     // predicted cost of the coarser charts (tolerance / 8)
    uint32_t texelsRequested = 0;   // texels at the requested density
    uint32_t texelsSampled = 0;     // texels sampled after the charts' choice
    uint32_t gridCellsFull = 0;     // cells over the whole level
    uint32_t gridCells = 0;         // cells baked
    uint32_t viewsPredicted = 0;    // views (cameras, else spawns) the errors come from
    float predictedError = 0.0f;    // probeError + lightmapError
};

/// One baked environment probe in memory (DiskProbe's twin): its prefiltered, normalised
/// radiance as RGB9E5 texels, mips from the largest, each 6 faces of rows from the top.
struct EnvironmentProbe {
    glm::vec3 position{0.0f};              // metres, world: the capture point
    glm::vec3 boxMin{0.0f}, boxMax{0.0f};  // box projection when min < max on every axis
    glm::vec3 irradianceAverage{1.0f};     // lux, RGB: E_avg (probeNormalize), the cube's mean
    // The light the probe reflects as irradiance on surfaces facing +x -x +y -y +z -z at the
    // capture point (the grid's ambient cube there, without the punctual lights' direct light):
    // the capture's side of the probes' statistic (shaders/probe.glsl, "Normalization").
    std::array<glm::vec3, 6> irradianceCube{};
    uint32_t faceSize = 0, mipCount = 0;  // mip 0 edge (a power of two); down to 1x1
    uint32_t entity = kNoIndex;           // the probe entity, kNoIndex when placed
    std::vector<uint32_t> texels;         // RGB9E5, 6 * sum_m (face_size >> m)^2
};

/// What an unmerged part of a sharded bake holds (section 40): the lightmap charts (every texel
/// of their rectangles; positions in the charts' space order), light grid cells and probes
/// [begin, end) it baked, each a contiguous range cut by estimated cost (bake/shard_plan.hpp);
/// the merge checks that the parts tile every range.
struct ShardRange {
    uint64_t chartBegin = 0, chartEnd = 0;
    uint64_t cellBegin = 0, cellEnd = 0;
    uint64_t probeBegin = 0, probeEnd = 0;
    uint64_t probeTotal = 0;  // probes of the whole level
    bool operator==(const ShardRange&) const = default;
};

struct BakedLighting {
    std::vector<LightmapTexel> texels;  // every atlas in order, row-major
    std::vector<uint8_t> shadowMask;    // same order: own primary's visibility 0..255
    LightGrid grid;
    std::vector<EnvironmentProbe> probes;       // section 35; a part holds its shard's range
    Visibility visibility;                      // section 37; empty: no culling
    std::vector<LightmapTexel> importedTexels;  // section 36: the source's own bake (q3map2's)
                                                // at the same texels; empty when it has none
    uint32_t shardIndex = 0, shardCount = 1;    // shardCount > 1: an unmerged part
    ShardRange shardRange;                      // section 40, in an unmerged part only
    ErrorBudgetChoices budget;                  // section 39, when budget > 0
};

/// Offset of atlas `atlas`'s first texel in BakedLighting::texels.
[[nodiscard]] inline uint64_t atlasTexelOffset(const CompiledLevel& level, uint32_t atlas) {
    uint64_t offset = 0;
    for (uint32_t a = 0; a < atlas; ++a)
        offset += uint64_t(level.atlases[a].width) * level.atlases[a].height;
    return offset;
}

}  // namespace onelight::world

namespace onelight::world {

/// A texel as the four linear coefficients per channel of shaders/lighting.glsl's
/// irradianceLinear (E(n) = max(0, c0 + c.n)): (E / w) (0.5, d). Exact, not a fit: the texel's
/// reconstruction E (0.5 + n.d) / w is linear in n.
[[nodiscard]] inline glm::vec4 linearIrradianceCoefficients(const LightmapTexel& t, int channel) {
    const float scale = t.irradiance[channel] / t.normalWeight;
    return glm::vec4(0.5f * scale, scale * t.direction);
}

}  // namespace onelight::world
