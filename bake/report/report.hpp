// The bake's report.json: seconds per stage, rays by kind and rays/s, peak memory, samples per
// texel and the estimated noise.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bake/embree/bake_scene.hpp"

namespace onelight::bake {

struct StageReport {
    std::string name;
    double seconds = 0.0;
    RayCounts rays;
    uint64_t items = 0;  // texels, cells, ... the stage worked on
};

struct BakeReport {
    std::string level;
    std::string quality;
    uint32_t threads = 0;
    uint32_t shard_index = 0, shard_count = 1;
    std::vector<StageReport> stages;
    uint64_t triangles = 0;
    uint64_t texels_total = 0, texels_sampled = 0, texels_moved = 0;
    uint64_t grid_cells = 0, grid_cells_inside = 0;
    uint32_t shadow_samples_per_light = 0;
    uint32_t indirect_samples_per_texel = 0;
    uint32_t grid_samples_per_cell = 0;
    double lightmap_mean_relative_noise = 0.0;    // estimated standard error / value
    uint64_t probes_total = 0, probes_baked = 0;  // placed in the level; captured by this run
    uint32_t probe_face_size = 0, probe_samples_per_texel = 0;
    uint64_t probe_bytes = 0;           // section 35 bytes of the probes this run baked
    std::vector<std::string> warnings;  // one line each, naming the thing and what to change
    uint64_t peak_memory_bytes = 0;
    uint64_t package_bytes = 0;
};

/// Peak resident memory of this process so far (getrusage), bytes.
uint64_t peak_memory_bytes();

std::string report_json(const BakeReport& report);
/// Writes the JSON to `path` (atomically). Throws world::Error.
void write_report(const std::string& path, const BakeReport& report);
/// A few lines for stdout at the end of a run.
std::string report_summary(const BakeReport& report);

}  // namespace onelight::bake
