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

struct CompileOptions {
    RegionOptions regions;
    ChartOptions charts;
    BspOptions bsp;
};

/// What the compile did, for the command's summary and the benchmark.
struct CompileStats {
    uint64_t source_triangles = 0;  // static triangles imported
    uint64_t degenerate_removed = 0;
    uint64_t duplicates_removed = 0;
    uint64_t triangles = 0;  // static triangles in the package
    uint64_t dynamic_triangles = 0;
    uint64_t surfaces = 0;
    uint32_t bsp_depth = 0;
    uint64_t bsp_leaves = 0;
    uint64_t bsp_nodes = 0;
    uint64_t bsp_splits = 0;  // triangles cut by BSP planes
    uint32_t primary_candidates = 0;
    uint32_t primaries_used = 0;  // primaries owning at least one surface
    RegionStats regions;
    uint64_t charts = 0;
    uint64_t authored_charts = 0;
    uint64_t atlases = 0;
    uint64_t texels = 0;
    double fill_ratio = 0.0;
    double seconds_split = 0.0, seconds_regions = 0.0, seconds_charts = 0.0, seconds_bsp = 0.0,
           seconds_surfaces = 0.0;
};

struct CompileResult {
    CompiledLevel level;
    CompileStats stats;
};

/// Compiles `source`. `illuminance` gives each primary candidate's illuminance (the baker's
/// includes visibility); null uses make_unshadowed_primary_illuminance. Throws Error.
CompileResult compile_level(const SourceLevel& source, const CompileOptions& options,
                            const PrimaryIlluminanceFn* illuminance = nullptr);

}  // namespace onelight::world
