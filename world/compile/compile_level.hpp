// The level compile without lighting: static/dynamic split, primary regions, lightmap charts,
// BSP, surfaces, feature analysis. Deterministic: the same source gives the same level.
#pragma once

#include <cstdint>

#include "world/bsp/bsp_build.hpp"
#include "world/charts/chart_pack.hpp"
#include "world/compiled_level.hpp"
#include "world/regions/region_split.hpp"
#include "world/source_level.hpp"

namespace onelight::world {

/// The most lightmap texels a level may have (every atlas's area), and the bake's memory per
/// texel this limit assumes: the texel (32 bytes), its shadow mask, the denoiser's and the
/// dilation's copies and the sampler's accumulators (an estimate from the baker's structures).
inline constexpr uint64_t kMaxLightmapTexels = uint64_t(1) << 27;  // 134M texels
inline constexpr double kBakeBytesPerTexel = 96.0;

struct CompileOptions {
    RegionOptions regions;
    ChartOptions charts;
    BspOptions bsp;
};

/// What the compile did, for the command's summary and the benchmark.
struct CompileStats {
    uint64_t sourceTriangles = 0;  // static triangles imported
    uint64_t degenerateRemoved = 0;
    uint64_t duplicatesRemoved = 0;
    uint64_t triangles = 0;               // static triangles in the package
    uint64_t dynamicTriangles = 0;        // every dynamic mesh's, as drawn
    uint64_t dynamicTrianglesShared = 0;  // ...of which drawn from another mesh's copy
    uint64_t surfaces = 0;
    uint32_t bspDepth = 0;
    uint64_t bspLeaves = 0;
    uint64_t bspNodes = 0;
    uint64_t bspSplits = 0;  // triangles cut by BSP planes
    uint32_t primaryCandidates = 0;
    uint32_t primariesUsed = 0;  // primaries owning at least one surface
    RegionStats regions;
    uint64_t charts = 0;
    uint64_t authoredCharts = 0;
    uint64_t atlases = 0;
    uint64_t texels = 0;
    double fillRatio = 0.0;
    double secondsSplit = 0.0, secondsRegions = 0.0, secondsCharts = 0.0, secondsBsp = 0.0,
           secondsSurfaces = 0.0;
};

struct CompileResult {
    CompiledLevel level;
    CompileStats stats;
};

/// Compiles `source`. `illuminance` gives each primary candidate's illuminance (the baker's
/// includes visibility); null uses makeUnshadowedPrimaryIlluminance. Throws Error.
[[nodiscard]] CompileResult compileLevel(const SourceLevel& source, const CompileOptions& options,
                                         const PrimaryIlluminanceFn* illuminance = nullptr);

}  // namespace onelight::world
