#include "bake/slurm/shard_reports.hpp"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/file_write.hpp"

namespace onelight::bake::slurm {
namespace {

/// Stages that every shard runs whole (the rest are split between the shards).
bool wholeInEveryShard(const std::string& stage) {
    return stage != "lightmaps" && stage != "grid" && stage != "probes" && stage != "visibility";
}

double stageSeconds(const BakeReport& report, const char* name) {
    for (const StageReport& s : report.stages)
        if (s.name == name) return s.seconds;
    return 0.0;
}

}  // namespace

BakeReport readReport(const std::string& path) {
    const std::vector<uint8_t> bytes = world::readRegularFile(path, "a bake report", 64 << 20);
    const nlohmann::json j = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("stages") || !j["stages"].is_array())
        throw world::Error(path + ": not a bake report; expected the JSON of --report");
    try {
        BakeReport r;
        r.level = j.value("level", "");
        r.quality = j.value("quality", "");
        r.threads = j.value("threads", 0u);
        if (j.contains("shard") && j["shard"].is_object()) {
            r.shardIndex = j["shard"].value("index", 0u);
            r.shardCount = j["shard"].value("count", 1u);
            r.shardCost = j["shard"].value("estimated_core_seconds", 0.0);
            r.shardCostTotal = j["shard"].value("estimated_core_seconds_all_shards", 0.0);
        }
        for (const nlohmann::json& s : j["stages"]) {
            StageReport stage;
            stage.name = s.value("name", "");
            stage.seconds = s.value("seconds", 0.0);
            stage.items = s.value("items", uint64_t(0));
            const nlohmann::json& rays = s.at("rays");
            stage.rays.shadow = rays.value("shadow", uint64_t(0));
            stage.rays.bounce = rays.value("bounce", uint64_t(0));
            stage.rays.probe = rays.value("probe", uint64_t(0));
            r.stages.push_back(stage);
        }
        r.peakMemoryBytes = j.value("peak_memory_bytes", uint64_t(0));
        r.packageBytes = j.value("package_bytes", uint64_t(0));
        r.triangles = j.value("triangles", uint64_t(0));
        const nlohmann::json& lm = j.at("lightmap");
        r.texelsTotal = lm.value("texels_total", uint64_t(0));
        r.texelsSampled = lm.value("texels_sampled", uint64_t(0));
        r.texelsGathered = lm.value("texels_gathered", uint64_t(0));
        r.chartsReduced = lm.value("charts_with_fewer_texels", 0u);
        r.texelsBeforeDensity = lm.value("texels_sampled_at_requested_density", uint64_t(0));
        r.indirectSamplesPerTexel = lm.value("indirect_samples_per_texel", 0u);
        r.shadowSamplesPerLight = lm.value("shadow_samples_per_light", 0u);
        r.lightmapMeanRelativeNoise = lm.value("estimated_relative_noise", 0.0);
        r.lightmapDenoisedRelativeNoise = lm.value("estimated_relative_noise_denoised", 0.0);
        const nlohmann::json& grid = j.at("light_grid");
        r.gridCells = grid.value("cells", uint64_t(0));
        r.gridCellsInside = grid.value("cells_inside_solid", uint64_t(0));
        const nlohmann::json& probes = j.at("probes");
        r.probesTotal = probes.value("placed", uint64_t(0));
        r.probesBaked = probes.value("baked", uint64_t(0));
        r.probeFaceSize = probes.value("face_size", 0u);
        r.probeSamplesPerTexel = probes.value("paths_per_texel", 0u);
        r.probeBytes = probes.value("bytes", uint64_t(0));
        const nlohmann::json& vis = j.at("visibility");
        r.visibilityCells = vis.value("cells", 0u);
        r.visibilityClusters = vis.value("clusters", 0u);
        r.visibilityRows = vis.value("rows", 0u);
        r.visibilityMeanFraction = vis.value("mean_visible_fraction", 0.0);
        for (const nlohmann::json& t : j.at("textures").at("list"))
            r.textures.push_back({t.value("name", ""), t.value("format", ""), t.value("width", 0u),
                                  t.value("height", 0u), t.value("mips", 0u),
                                  t.value("bytes", uint64_t(0))});
        r.textureBytes = j.at("textures").value("bytes", uint64_t(0));
        for (const nlohmann::json& w : j.value("warnings", nlohmann::json::array()))
            if (w.is_string()) r.warnings.push_back(w.get<std::string>());
        return r;
    } catch (const nlohmann::json::exception& e) {
        throw world::Error(path + ": " + e.what() + "; expected the JSON of --report");
    }
}

BakeReport combineShardReports(const BakeReport& compile, const std::vector<BakeReport>& shards) {
    if (shards.empty()) return compile;
    BakeReport whole = shards[0];
    // The compile's stages first (the texture stage, its scene, the compile), then the shards'.
    std::vector<StageReport> stages = compile.stages;
    for (const StageReport& s : whole.stages) {
        auto found = std::find_if(stages.begin(), stages.end(),
                                  [&](const StageReport& c) { return c.name == s.name; });
        if (found == stages.end()) {
            stages.push_back(s);
        } else {
            found->seconds += s.seconds;
            found->rays += s.rays;
        }
    }
    whole.stages = std::move(stages);
    whole.texelsBeforeDensity = compile.texelsBeforeDensity;
    whole.chartsReduced = compile.chartsReduced;
    whole.textures = compile.textures;
    whole.textureBytes = compile.textureBytes;
    whole.warnings.insert(whole.warnings.begin(), compile.warnings.begin(), compile.warnings.end());
    whole.shardCost = whole.shardCostTotal;
    // Each part's visibility rows are its own cells' sets: the whole's are only known merged.
    whole.visibilityRows = 0;
    whole.visibilityMeanFraction = 0.0;
    whole.shardIndex = 0;
    whole.shardCount = uint32_t(shards.size());
    double noise = whole.lightmapMeanRelativeNoise * double(whole.texelsSampled);
    double denoised = whole.lightmapDenoisedRelativeNoise * double(whole.texelsSampled);
    for (size_t i = 1; i < shards.size(); ++i) {
        const BakeReport& r = shards[i];
        for (const StageReport& s : r.stages) {
            auto found = std::find_if(whole.stages.begin(), whole.stages.end(),
                                      [&](const StageReport& w) { return w.name == s.name; });
            if (found == whole.stages.end()) {
                whole.stages.push_back(s);
                continue;
            }
            found->seconds += s.seconds;
            found->rays += s.rays;
            if (!wholeInEveryShard(s.name)) found->items += s.items;
        }
        whole.texelsSampled += r.texelsSampled;
        whole.texelsGathered += r.texelsGathered;
        whole.texelsMoved += r.texelsMoved;
        whole.probesBaked += r.probesBaked;
        whole.gridCellsInside += r.gridCellsInside;
        whole.visibilityCells += r.visibilityCells;
        whole.probeBytes += r.probeBytes;
        whole.peakMemoryBytes = std::max(whole.peakMemoryBytes, r.peakMemoryBytes);
        noise += r.lightmapMeanRelativeNoise * double(r.texelsSampled);
        denoised += r.lightmapDenoisedRelativeNoise * double(r.texelsSampled);
    }
    if (whole.texelsSampled > 0) {
        whole.lightmapMeanRelativeNoise = noise / double(whole.texelsSampled);
        whole.lightmapDenoisedRelativeNoise = denoised / double(whole.texelsSampled);
    }
    return whole;
}

std::string shardTimeLines(const std::vector<ShardStamp>& stamps,
                           const std::vector<BakeReport>& reports) {
    std::string text;
    double slowest = 0.0, sum = 0.0;
    for (const ShardStamp& s : stamps) {
        slowest = std::max(slowest, s.seconds);
        sum += s.seconds;
    }
    char line[256];
    for (size_t i = 0; i < stamps.size(); ++i) {
        const ShardStamp& s = stamps[i];
        const BakeReport* r = i < reports.size() ? &reports[i] : nullptr;
        const double share =
            r && r->shardCostTotal > 0.0 ? 100.0 * r->shardCost / r->shardCostTotal : 0.0;
        std::snprintf(line, sizeof line,
                      "  shard %-4u %-12s %8.2f s (lightmaps %.2f s, grid %.2f s, probes %.2f s; "
                      "%.1f%% of the divided work by estimate)%s\n",
                      s.shard, s.node.c_str(), s.seconds, r ? stageSeconds(*r, "lightmaps") : 0.0,
                      r ? stageSeconds(*r, "grid") : 0.0, r ? stageSeconds(*r, "probes") : 0.0,
                      share, s.seconds == slowest && stamps.size() > 1 ? "  slowest" : "");
        text += line;
    }
    if (!stamps.empty() && sum > 0.0) {
        std::snprintf(line, sizeof line, "  balance    slowest shard %.2f x the mean (%.2f s)\n",
                      slowest / (sum / double(stamps.size())), sum / double(stamps.size()));
        text += line;
    }
    uint64_t sampled = 0, gathered = 0;
    for (const BakeReport& r : reports) {
        sampled += r.texelsSampled;
        gathered += r.texelsGathered;
    }
    if (sampled > 0 && gathered > 0) {
        std::snprintf(line, sizeof line,
                      "  gathers    %.2f x a whole bake's final gathers (%llu texels for %llu: "
                      "each part also gathers the texels its denoiser windows read)\n",
                      double(gathered) / double(sampled), static_cast<unsigned long long>(gathered),
                      static_cast<unsigned long long>(sampled));
        text += line;
    }
    return text;
}

void writeSlurmReport(const std::string& path, const BakeReport& whole, const ShardStamp& compile,
                      const std::vector<ShardStamp>& stamps, const std::vector<BakeReport>& reports,
                      const MergeStamp& merge, double wallSeconds) {
    nlohmann::ordered_json json = nlohmann::ordered_json::parse(reportJson(whole));
    nlohmann::ordered_json shards = nlohmann::ordered_json::array();
    for (size_t i = 0; i < stamps.size(); ++i) {
        nlohmann::ordered_json stages = nlohmann::ordered_json::object();
        if (i < reports.size())
            for (const StageReport& s : reports[i].stages) stages[s.name] = s.seconds;
        shards.push_back(
            {{"index", stamps[i].shard},
             {"node", stamps[i].node},
             {"seconds", stamps[i].seconds},
             {"stage_seconds", stages},
             {"estimated_core_seconds", i < reports.size() ? reports[i].shardCost : 0.0}});
    }
    json["compile"] = {{"node", compile.node}, {"seconds", compile.seconds}};
    json["shards"] = shards;
    json["merge"] = {{"node", merge.node}, {"seconds", merge.seconds}};
    json["wall_seconds"] = wallSeconds;
    const std::string text = json.dump(2) + "\n";
    world::writeFileAtomically(path, text);
}

}  // namespace onelight::bake::slurm
