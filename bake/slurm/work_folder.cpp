#include "bake/slurm/work_folder.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "bake/slurm/content_hash.hpp"
#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/file_write.hpp"

namespace onelight::bake::slurm {
namespace {

constexpr const char* kManifestFormat = "onelight slurm work folder 1";

void writeJson(const std::string& path, const nlohmann::ordered_json& json) {
    const std::string text = json.dump(2) + "\n";
    world::writeFileAtomically(path, text);
}

/// The JSON in `path`; nothing when the file is absent. Throws world::Error when it is no JSON.
std::optional<nlohmann::json> readJson(const std::string& path, const char* expected) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) return std::nullopt;
    const std::vector<uint8_t> bytes = world::readRegularFile(path, expected, 1 << 20);
    nlohmann::json json = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
    if (json.is_discarded() || !json.is_object())
        throw world::Error(path + ": not JSON; expected " + expected);
    return json;
}

uint64_t parseHex(const nlohmann::json& value) {
    if (!value.is_string()) return 0;
    try {
        return std::stoull(value.get<std::string>(), nullptr, 16);
    } catch (const std::exception&) {
        return 0;
    }
}

std::string joined(const std::vector<std::string>& arguments) {
    std::string text;
    for (const std::string& a : arguments) text += (text.empty() ? "" : " ") + a;
    return text.empty() ? "(none)" : text;
}

}  // namespace

std::string WorkFolder::shardPackage(uint32_t shard) const {
    return root + "/shards/shard-" + std::to_string(shard) + ".olpak";
}
std::string WorkFolder::shardReport(uint32_t shard) const {
    return root + "/shards/shard-" + std::to_string(shard) + ".json";
}
std::string WorkFolder::shardStamp(uint32_t shard) const {
    return root + "/shards/shard-" + std::to_string(shard) + ".stamp.json";
}

uint64_t Manifest::settingsHash() const {
    uint64_t hash = hashText("shards " + std::to_string(shardCount) + " for " + output + '\0');
    for (const std::string& a : bakeArguments) hash = hashText(a + '\0', hash);
    return hash;
}

void makeWorkFolder(const WorkFolder& work) {
    for (const std::string& folder :
         {work.root, work.scripts(), work.logs(), work.root + "/shards"}) {
        std::error_code error;
        std::filesystem::create_directories(folder, error);
        if (error || !std::filesystem::is_directory(folder))
            throw world::Error(folder + ": cannot make the folder (" + error.message() +
                               "); expected a writable work folder");
    }
}

void writeManifest(const WorkFolder& work, const Manifest& m) {
    nlohmann::ordered_json json;
    json["format"] = kManifestFormat;
    json["level"] = m.level;
    json["level_hash"] = hashHex(m.levelHash);
    json["output"] = m.output;
    json["bake_arguments"] = m.bakeArguments;
    json["shards"] = m.shardCount;
    json["settings_hash"] = hashHex(m.settingsHash());
    writeJson(work.manifest(), json);
}

std::optional<Manifest> readManifest(const WorkFolder& work) {
    const std::optional<nlohmann::json> json = readJson(work.manifest(), "a Slurm bake's manifest");
    if (!json) return std::nullopt;
    const nlohmann::json& j = *json;
    if (j.value("format", "") != kManifestFormat || !j.contains("level") ||
        !j["level"].is_string() || !j.contains("bake_arguments") ||
        !j["bake_arguments"].is_array() || !j.contains("shards") ||
        !j["shards"].is_number_unsigned())
        throw world::Error(work.manifest() + ": not a manifest of '" + kManifestFormat +
                           "'; expected the work folder of onelight-bake --slurm");
    Manifest m;
    m.level = j["level"].get<std::string>();
    m.levelHash = parseHex(j["level_hash"]);
    m.output = j.value("output", "");
    for (const nlohmann::json& a : j["bake_arguments"])
        if (a.is_string()) m.bakeArguments.push_back(a.get<std::string>());
    m.shardCount = j["shards"].get<uint32_t>();
    return m;
}

bool sameBake(const Manifest& a, const Manifest& b) {
    return a.level == b.level && a.levelHash == b.levelHash && a.output == b.output &&
           a.bakeArguments == b.bakeArguments && a.shardCount == b.shardCount;
}

std::string describeChange(const Manifest& found, const Manifest& wanted) {
    if (found.level != wanted.level)
        return "it bakes another level (" + found.level + ", now " + wanted.level + ")";
    if (found.levelHash != wanted.levelHash)
        return "the level's content changed (hash " + hashHex(found.levelHash) + ", now " +
               hashHex(wanted.levelHash) + ")";
    if (found.output != wanted.output)
        return "it writes another package (" + found.output + ", now " + wanted.output +
               "; the shards place the level's images beside it)";
    if (found.shardCount != wanted.shardCount)
        return "it bakes " + std::to_string(found.shardCount) + " shards, now " +
               std::to_string(wanted.shardCount);
    return "the settings changed (" + joined(found.bakeArguments) + ", now " +
           joined(wanted.bakeArguments) + ")";
}

namespace {

/// The stamp of `package` (shard `shard`, or kCompiledStamp) at `stampPath`.
void writeStamp(const std::string& stampPath, const std::string& package, const char* what,
                const Manifest& manifest, uint32_t shard, const std::string& node, double seconds) {
    const std::vector<uint8_t> bytes = world::readRegularFile(package, what);
    nlohmann::ordered_json json;
    json["shard"] = shard;
    json["shards"] = manifest.shardCount;
    json["level_hash"] = hashHex(manifest.levelHash);
    json["settings_hash"] = hashHex(manifest.settingsHash());
    json["package_checksum"] = hashHex(hashBytes(bytes));
    json["package_bytes"] = bytes.size();
    json["node"] = node;
    json["seconds"] = seconds;
    writeJson(stampPath, json);
}

std::optional<ShardStamp> verifiedStamp(const std::string& stampPath, const std::string& package,
                                        const char* what, const Manifest& manifest,
                                        uint32_t shard) {
    std::optional<nlohmann::json> json;
    try {
        json = readJson(stampPath, "a stamp");
    } catch (const world::Error&) {
        return std::nullopt;  // a damaged stamp: the work is done again
    }
    if (!json) return std::nullopt;
    const nlohmann::json& j = *json;
    ShardStamp s;
    s.shard = j.value("shard", uint32_t(~0u) - 1);
    s.shardCount = j.value("shards", 0u);
    s.levelHash = parseHex(j.value("level_hash", nlohmann::json()));
    s.settingsHash = parseHex(j.value("settings_hash", nlohmann::json()));
    s.packageChecksum = parseHex(j.value("package_checksum", nlohmann::json()));
    s.packageBytes = j.value("package_bytes", uint64_t(0));
    s.node = j.value("node", "");
    s.seconds = j.value("seconds", 0.0);
    if (s.shard != shard || s.shardCount != manifest.shardCount ||
        s.levelHash != manifest.levelHash || s.settingsHash != manifest.settingsHash())
        return std::nullopt;
    std::error_code error;
    if (!std::filesystem::is_regular_file(package, error) ||
        std::filesystem::file_size(package, error) != s.packageBytes)
        return std::nullopt;
    if (hashBytes(world::readRegularFile(package, what)) != s.packageChecksum) return std::nullopt;
    return s;
}

}  // namespace

void writeCompiledStamp(const WorkFolder& work, const Manifest& manifest, const std::string& node,
                        double seconds) {
    writeStamp(work.compiledStamp(), work.compiled(), "the compiled level", manifest,
               kCompiledStamp, node, seconds);
}

std::optional<ShardStamp> verifiedCompiled(const WorkFolder& work, const Manifest& manifest) {
    return verifiedStamp(work.compiledStamp(), work.compiled(), "the compiled level", manifest,
                         kCompiledStamp);
}

void writeShardStamp(const WorkFolder& work, const Manifest& manifest, uint32_t shard,
                     const std::string& node, double seconds) {
    writeStamp(work.shardStamp(shard), work.shardPackage(shard), "a shard's package", manifest,
               shard, node, seconds);
}

std::optional<ShardStamp> verifiedShard(const WorkFolder& work, const Manifest& manifest,
                                        uint32_t shard) {
    return verifiedStamp(work.shardStamp(shard), work.shardPackage(shard), "a shard's package",
                         manifest, shard);
}

void writeSubmittedJobs(const WorkFolder& work, const SubmittedJobs& jobs) {
    nlohmann::ordered_json json;
    json["array_job"] = jobs.arrayJob;
    json["merge_job"] = jobs.mergeJob;
    json["shards"] = jobs.shards;
    writeJson(work.jobs(), json);
}

std::optional<SubmittedJobs> readSubmittedJobs(const WorkFolder& work) {
    try {
        const std::optional<nlohmann::json> json = readJson(work.jobs(), "a record of jobs");
        if (!json) return std::nullopt;
        SubmittedJobs jobs;
        jobs.arrayJob = json->value("array_job", "");
        jobs.mergeJob = json->value("merge_job", "");
        jobs.shards = json->value("shards", std::vector<uint32_t>{});
        if (jobs.mergeJob.empty()) return std::nullopt;
        return jobs;
    } catch (const std::exception&) {
        return std::nullopt;  // damaged: the rerun submits afresh
    }
}

void writeMergeStamp(const WorkFolder& work, const MergeStamp& stamp) {
    nlohmann::ordered_json json;
    json["node"] = stamp.node;
    json["output"] = stamp.output;
    json["seconds"] = stamp.seconds;
    json["package_bytes"] = stamp.packageBytes;
    writeJson(work.mergeStamp(), json);
}

std::optional<MergeStamp> readMergeStamp(const WorkFolder& work) {
    const std::optional<nlohmann::json> json = readJson(work.mergeStamp(), "a merge stamp");
    if (!json) return std::nullopt;
    MergeStamp s;
    s.node = json->value("node", "");
    s.output = json->value("output", "");
    s.seconds = json->value("seconds", 0.0);
    s.packageBytes = json->value("package_bytes", uint64_t(0));
    return s;
}

std::string hostName() {
    if (const char* node = std::getenv("SLURMD_NODENAME"); node && *node) return node;
    char name[256] = {};
    if (gethostname(name, sizeof name - 1) != 0) return "unknown";
    return name;
}

}  // namespace onelight::bake::slurm
