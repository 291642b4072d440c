#include "bake/report/report.hpp"

#include <sys/resource.h>

#include <cstdio>

#include <nlohmann/json.hpp>

#include "world/file_write.hpp"

namespace onelight::bake {

uint64_t peakMemoryBytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<uint64_t>(usage.ru_maxrss) * 1024u;  // Linux reports kilobytes
}

std::string reportJson(const BakeReport& r) {
    nlohmann::ordered_json j;
    j["level"] = r.level;
    j["quality"] = r.quality;
    j["threads"] = r.threads;
    j["shard"] = {{"index", r.shardIndex},
                  {"count", r.shardCount},
                  {"estimated_core_seconds", r.shardCost},
                  {"estimated_core_seconds_all_shards", r.shardCostTotal}};
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
    j["peak_memory_bytes"] = r.peakMemoryBytes;
    j["package_bytes"] = r.packageBytes;
    j["triangles"] = r.triangles;
    j["lights"] = {{"primary", r.primaryLights},
                   {"baked", r.bakedLights},
                   {"emissive_triangles", r.emissiveTriangles}};
    j["lightmap"] = {{"texels_total", r.texelsTotal},
                     {"texels_sampled", r.texelsSampled},
                     {"texels_gathered", r.texelsGathered},
                     {"texels_moved_out_of_geometry", r.texelsMoved},
                     {"charts_with_fewer_texels", r.chartsReduced},
                     {"texels_sampled_at_requested_density", r.texelsBeforeDensity},
                     {"shadow_samples_per_light", r.shadowSamplesPerLight},
                     {"indirect_samples_per_texel", r.indirectSamplesPerTexel},
                     {"estimated_relative_noise", r.lightmapMeanRelativeNoise},
                     {"estimated_relative_noise_denoised", r.lightmapDenoisedRelativeNoise}};
    j["light_grid"] = {{"cells", r.gridCells},
                       {"cells_inside_solid", r.gridCellsInside},
                       {"samples_per_cell", r.gridSamplesPerCell}};
    j["probes"] = {{"placed", r.probesTotal},
                   {"baked", r.probesBaked},
                   {"face_size", r.probeFaceSize},
                   {"paths_per_texel", r.probeSamplesPerTexel},
                   {"bytes", r.probeBytes}};
    j["visibility"] = {{"cells", r.visibilityCells},
                       {"clusters", r.visibilityClusters},
                       {"rows", r.visibilityRows},
                       {"mean_visible_fraction", r.visibilityMeanFraction},
                       {"source", r.visibilitySource}};
    nlohmann::json textures = nlohmann::json::array();
    for (const TextureReport& t : r.textures)
        textures.push_back({{"name", t.name},
                            {"format", t.format},
                            {"width", t.width},
                            {"height", t.height},
                            {"mips", t.mips},
                            {"bytes", t.bytes}});
    j["textures"] = {{"count", r.textures.size()}, {"bytes", r.textureBytes}, {"list", textures}};
    if (r.budget.budget > 0.0f) {
        nlohmann::json choices = nlohmann::json::array();
        for (const BudgetChoiceReport& c : r.budgetChoices)
            choices.push_back({{"feature", c.feature},
                               {"choice", c.choice},
                               {"predicted_error", c.predictedError},
                               {"why", c.why}});
        j["error_budget"] = {
            {"budget", r.budget.budget},
            {"predicted_error", r.budget.predictedError},
            {"probes_dropped", (r.budget.flags & world::kBudgetProbesDropped) != 0},
            {"probe_error", r.budget.probeError},
            {"lightmap_error", r.budget.lightmapError},
            {"views", r.budget.viewsPredicted},
            {"probe_error_per_view", r.probeErrorPerView},
            {"choices", choices}};
    }
    j["warnings"] = r.warnings;
    j["light_sources"] = r.lightSources;
    return j.dump(2) + "\n";
}

void writeReport(const std::string& path, const BakeReport& report) {
    const std::string json = reportJson(report);
    world::writeFileAtomically(path, json);
}

std::string reportSummary(const BakeReport& r) {
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
                  double(r.peakMemoryBytes) / (1024.0 * 1024.0));
    s += line;
    std::snprintf(line, sizeof line,
                  "  lightmaps  %llu texels sampled of %llu, %u paths/texel, estimated noise "
                  "%.2f%% (%.2f%% denoised); grid %llu cells (%llu inside solid)\n",
                  static_cast<unsigned long long>(r.texelsSampled),
                  static_cast<unsigned long long>(r.texelsTotal), r.indirectSamplesPerTexel,
                  100.0 * r.lightmapMeanRelativeNoise, 100.0 * r.lightmapDenoisedRelativeNoise,
                  static_cast<unsigned long long>(r.gridCells),
                  static_cast<unsigned long long>(r.gridCellsInside));
    s += line;
    if (r.texelsBeforeDensity > 0) {
        std::snprintf(line, sizeof line,
                      "  density    %u charts with fewer texels: %llu texels sampled instead of "
                      "%llu\n",
                      r.chartsReduced, static_cast<unsigned long long>(r.texelsSampled),
                      static_cast<unsigned long long>(r.texelsBeforeDensity));
        s += line;
    }
    if (r.probesTotal) {
        std::snprintf(line, sizeof line,
                      "  probes     %llu of %llu baked, face %u, %u paths/texel, %.1f KiB\n",
                      static_cast<unsigned long long>(r.probesBaked),
                      static_cast<unsigned long long>(r.probesTotal), r.probeFaceSize,
                      r.probeSamplesPerTexel, double(r.probeBytes) / 1024.0);
        s += line;
    }
    if (!r.textures.empty()) {
        std::snprintf(line, sizeof line,
                      "  textures   %zu with every mip, %.1f MiB (report.json lists each)\n",
                      r.textures.size(), double(r.textureBytes) / (1024.0 * 1024.0));
        s += line;
    }
    if (r.budget.budget > 0.0f) {
        std::snprintf(line, sizeof line,
                      "  budget     %.1f%% mean block error; the choices are predicted to cost "
                      "%.2f%%:\n",
                      100.0 * double(r.budget.budget), 100.0 * double(r.budget.predictedError));
        s += line;
        for (const BudgetChoiceReport& c : r.budgetChoices)
            s += "    " + c.feature + ": " + c.choice + " (" + c.why + ")\n";
    }
    if (r.visibilityCells && r.visibilityRows) {
        std::snprintf(
            line, sizeof line,
            "  visibility %u cells, %u clusters of surfaces, %u distinct sets (%s); an open cell "
            "sees %.1f%% of the clusters on average\n",
            r.visibilityCells, r.visibilityClusters, r.visibilityRows, r.visibilitySource.c_str(),
            100.0 * r.visibilityMeanFraction);
        s += line;
    } else if (r.visibilityCells) {  // parts of a sharded bake: the merge joins the sets
        std::snprintf(line, sizeof line,
                      "  visibility %u cells sampled, %u clusters of surfaces (the sets are "
                      "joined by the merge)\n",
                      r.visibilityCells, r.visibilityClusters);
        s += line;
    }
    return s;
}

}  // namespace onelight::bake
