#include "bake/report/report.hpp"

#include <sys/resource.h>

#include <cstdio>
#include <span>

#include <nlohmann/json.hpp>

#include "world/package/package_writer.hpp"

namespace onelight::bake {

uint64_t peak_memory_bytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<uint64_t>(usage.ru_maxrss) * 1024u;  // Linux reports kilobytes
}

std::string report_json(const BakeReport& r) {
    nlohmann::ordered_json j;
    j["level"] = r.level;
    j["quality"] = r.quality;
    j["threads"] = r.threads;
    j["shard"] = {{"index", r.shard_index}, {"count", r.shard_count}};
    double seconds = 0.0;
    RayCounts all;
    nlohmann::ordered_json stages = nlohmann::ordered_json::array();
    for (const StageReport& s : r.stages) {
        seconds += s.seconds;
        all += s.rays;
        stages.push_back(
            {{"name", s.name},
             {"seconds", s.seconds},
             {"items", s.items},
             {"rays",
              {{"shadow", s.rays.shadow},
               {"bounce", s.rays.bounce},
               {"probe", s.rays.probe},
               {"total", s.rays.total()}}},
             {"rays_per_second", s.seconds > 0.0 ? double(s.rays.total()) / s.seconds : 0.0}});
    }
    j["stages"] = stages;
    j["seconds_total"] = seconds;
    j["rays"] = {{"shadow", all.shadow},
                 {"bounce", all.bounce},
                 {"probe", all.probe},
                 {"total", all.total()}};
    j["rays_per_second"] = seconds > 0.0 ? double(all.total()) / seconds : 0.0;
    j["peak_memory_bytes"] = r.peak_memory_bytes;
    j["package_bytes"] = r.package_bytes;
    j["triangles"] = r.triangles;
    j["lightmap"] = {{"texels_total", r.texels_total},
                     {"texels_sampled", r.texels_sampled},
                     {"texels_moved_out_of_geometry", r.texels_moved},
                     {"shadow_samples_per_light", r.shadow_samples_per_light},
                     {"indirect_samples_per_texel", r.indirect_samples_per_texel},
                     {"estimated_relative_noise", r.lightmap_mean_relative_noise}};
    j["light_grid"] = {{"cells", r.grid_cells},
                       {"cells_inside_solid", r.grid_cells_inside},
                       {"samples_per_cell", r.grid_samples_per_cell}};
    j["probes"] = {{"placed", r.probes_total},
                   {"baked", r.probes_baked},
                   {"face_size", r.probe_face_size},
                   {"paths_per_texel", r.probe_samples_per_texel},
                   {"bytes", r.probe_bytes}};
    j["warnings"] = r.warnings;
    return j.dump(2) + "\n";
}

void write_report(const std::string& path, const BakeReport& report) {
    const std::string json = report_json(report);
    package::write_file_atomically(
        path, std::span(reinterpret_cast<const uint8_t*>(json.data()), json.size()));
}

std::string report_summary(const BakeReport& r) {
    std::string s;
    char line[256];
    double seconds = 0.0;
    RayCounts all;
    for (const StageReport& st : r.stages) {
        std::snprintf(line, sizeof line, "  %-10s %8.2f s  %12llu rays  %7.2f Mrays/s\n",
                      st.name.c_str(), st.seconds, static_cast<unsigned long long>(st.rays.total()),
                      st.seconds > 0.0 ? double(st.rays.total()) / st.seconds * 1e-6 : 0.0);
        s += line;
        seconds += st.seconds;
        all += st.rays;
    }
    std::snprintf(line, sizeof line,
                  "  total      %8.2f s  %12llu rays  %7.2f Mrays/s, peak memory %.1f MiB\n",
                  seconds, static_cast<unsigned long long>(all.total()),
                  seconds > 0.0 ? double(all.total()) / seconds * 1e-6 : 0.0,
                  double(r.peak_memory_bytes) / (1024.0 * 1024.0));
    s += line;
    std::snprintf(line, sizeof line,
                  "  lightmaps  %llu texels sampled of %llu, %u paths/texel, estimated noise "
                  "%.2f%%; grid %llu cells (%llu inside solid)\n",
                  static_cast<unsigned long long>(r.texels_sampled),
                  static_cast<unsigned long long>(r.texels_total), r.indirect_samples_per_texel,
                  100.0 * r.lightmap_mean_relative_noise,
                  static_cast<unsigned long long>(r.grid_cells),
                  static_cast<unsigned long long>(r.grid_cells_inside));
    s += line;
    if (r.probes_total) {
        std::snprintf(line, sizeof line,
                      "  probes     %llu of %llu baked, face %u, %u paths/texel, %.1f KiB\n",
                      static_cast<unsigned long long>(r.probes_baked),
                      static_cast<unsigned long long>(r.probes_total), r.probe_face_size,
                      r.probe_samples_per_texel, double(r.probe_bytes) / 1024.0);
        s += line;
    }
    return s;
}

}  // namespace onelight::bake
