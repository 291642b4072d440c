// The bake pipeline: import -> Embree scene of the static world -> world compile with the
// shadowed dominant-primary function -> lightmap texels (shadow masks + directional secondary
// irradiance) -> light grid -> environment probes -> dilation -> package. Sharding bakes a
// contiguous part of the texels, of the grid cells and of the probes; merge joins the parts
// and finishes them exactly as a whole bake does, so the package is byte-identical.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "bake/grid/light_grid.hpp"
#include "bake/lighting/lights.hpp"
#include "bake/lightmap/lightmap_bake.hpp"
#include "bake/probes/probe_capture.hpp"
#include "bake/report/report.hpp"
#include "world/baked_lighting.hpp"
#include "world/compile/compile_level.hpp"
#include "world/source_level.hpp"

namespace onelight::bake {

enum class BakeQuality { draft, normal, high };

/// "draft", "default", "high".
const char* quality_name(BakeQuality quality);
bool parse_quality(const std::string& text, BakeQuality& quality);

struct BakeOptions {
    BakeQuality quality = BakeQuality::normal;
    world::CompileOptions compile;
    LightSizes light_sizes;
    std::optional<glm::vec3> sky_radiance;  // cd/m^2, uniform sky; unset: the level's
    float grid_cell_size = 1.0f;            // metres
    float probe_spacing = 8.0f;  // metres between automatic probes unless the level sets it
    uint32_t shard_index = 0, shard_count = 1;
    bool show_progress = true;
    // Overrides of the quality preset; 0 keeps the preset.
    uint32_t shadow_samples = 0, indirect_samples = 0, grid_samples = 0;
    uint32_t probe_face_size = 0, probe_samples = 0;  // a power of two; paths per texel
};

/// Sample counts of a quality preset, overrides applied.
LightmapSettings lightmap_settings(const BakeOptions& options);
GridSettings grid_settings(const BakeOptions& options);
/// Environment probe capture of a quality preset: face size draft 32, default 64, high 128;
/// paths per texel 16, 64, 256; overrides applied.
ProbeCaptureSettings probe_settings(const BakeOptions& options);

struct BakeResult {
    world::CompiledLevel level;
    world::CompileStats compile_stats;
    world::BakedLighting baked;  // finished (dilated) when shard_count == 1
    BakeReport report;
};

/// Compiles and bakes `source` (or its shard). Throws world::Error on bad input and
/// std::runtime_error on Embree failures.
BakeResult bake_level(const world::SourceLevel& source, const BakeOptions& options);

/// Texels, cells and probes [begin, end) that shard i of n owns: contiguous ranges.
struct ShardRange {
    uint64_t texel_begin = 0, texel_end = 0;
    uint64_t cell_begin = 0, cell_end = 0;
    uint64_t probe_begin = 0, probe_end = 0;
};
ShardRange shard_range(uint64_t texels, uint64_t cells, uint64_t probes, uint32_t index,
                       uint32_t count);

/// E_avg of each probe (probe_capture.hpp): ambientCubeAverage of the light grid sampled at the
/// capture point exactly as world::sampleLightGrid samples the finished grid. Only the corner
/// cells the sample weighs are baked, into a scratch copy of `layout` (seeded per cell, so they
/// equal the grid stage's cells): a shard gets the whole grid's value without the whole grid.
std::vector<glm::vec3> probe_average_irradiance(const BakeScene& scene, const BakeLights& lights,
                                                const GridSettings& settings,
                                                const world::LightGrid& layout,
                                                const std::vector<ProbePlacement>& probes,
                                                RayCounts& rays);

/// The steps after every texel is baked: dilation. Makes a part complete (shard 0 of 1).
void finish_baked_lighting(const world::CompiledLevel& level, world::BakedLighting& baked);

/// Joins the parts of a sharded bake (any order) into the unfinished whole, then finishes it.
/// Throws world::Error on a missing or repeated shard or mismatched sizes.
[[nodiscard]] world::BakedLighting merge_baked_lighting(const world::CompiledLevel& level,
                                                        std::vector<world::BakedLighting> parts);

/// The package bytes of a bake result.
std::vector<uint8_t> package_bytes(const world::CompiledLevel& level,
                                   const world::BakedLighting& baked);

}  // namespace onelight::bake
