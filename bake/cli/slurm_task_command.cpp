// onelight-bake slurm-task --work DIR (--shard I | --merge -o OUT): what the jobs of a Slurm
// bake run (their batch scripts call it, bake/slurm/batch_scripts.hpp). A shard task bakes part
// I of the work folder's compiled level (made once by the submitting command, its stamp
// verified), after checking that the level is still the one the manifest hashed, and stamps the
// part (work_folder.hpp); the merge task merges the parts after verifying every stamp.
// ONELIGHT_SLURM_FAIL_SHARD=I makes shard I fail before it bakes: the tests' fault injection
// (sbatch passes the submitting environment on to the tasks).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include <tbb/global_control.h>

#include "bake/cli/bake_command_line.hpp"
#include "bake/cli/bake_plan.hpp"
#include "bake/cli/cli_common.hpp"
#include "bake/cli/subcommands.hpp"
#include "bake/report/interrupt.hpp"
#include "bake/slurm/content_hash.hpp"
#include "bake/slurm/work_folder.hpp"
#include "world/error.hpp"
#include "world/import/level_import.hpp"
#include "world/package/package_reader.hpp"
#include "world/package/texture_section.hpp"

namespace onelight::bake {
namespace {

using slurm::Manifest;
using slurm::WorkFolder;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Manifest requireManifest(const WorkFolder& work) {
    const std::optional<Manifest> manifest = slurm::readManifest(work);
    if (!manifest)
        throw world::Error(work.manifest() +
                           ": missing; expected the work folder of onelight-bake --slurm");
    return *manifest;
}

/// The threads Slurm gave the task (--cpus-per-task), or every core.
std::unique_ptr<tbb::global_control> limitThreadsToAllocation() {
    const char* cpus = std::getenv("SLURM_CPUS_PER_TASK");
    int64_t count = 0;
    if (!cpus || !world::parseWholeInteger(cpus, 1, 1024, count)) return nullptr;
    return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                 static_cast<size_t>(count));
}

/// The tests' fault injection: ONELIGHT_SLURM_FAIL_SHARD=I fails shard I each time it runs;
/// I,once only the first time (a marker in the work folder remembers it).
void failOnPurposeIfAsked(const WorkFolder& work, uint32_t shard) {
    const char* value = std::getenv("ONELIGHT_SLURM_FAIL_SHARD");
    if (!value) return;
    const std::string fail = value, index = std::to_string(shard);
    if (fail != index && fail != index + ",once") return;
    if (fail != index) {
        const std::string marker = work.root + "/fault-injected-" + index;
        if (std::filesystem::exists(marker)) return;
        std::FILE* file = std::fopen(marker.c_str(), "w");
        if (file) std::fclose(file);
    }
    throw world::Error("shard " + index + ": failing on purpose (ONELIGHT_SLURM_FAIL_SHARD=" +
                       fail + ", the tests' fault injection)");
}

int bakeShard(const WorkFolder& work, uint32_t shard) {
    const auto start = std::chrono::steady_clock::now();
    const Manifest manifest = requireManifest(work);
    if (shard >= manifest.shardCount)
        throw world::Error("--shard " + std::to_string(shard) + ": " + work.root + " bakes " +
                           std::to_string(manifest.shardCount) + " shards; expected 0.." +
                           std::to_string(manifest.shardCount - 1));
    failOnPurposeIfAsked(work, shard);
    // The plan the submitting command checked, its forwarded options as the manifest has them.
    // Whatever the manifest names (the level, its options) fails naming the manifest too.
    const auto fromManifest = [&](const world::Error& e) {
        return world::Error(std::string(e.what()) + " (as " + work.manifest() + " names it)");
    };
    BakePlan plan;
    try {
        plan = bakePlanOf(shardTaskArguments(work, manifest, shard));
    } catch (const world::Error& e) {
        throw fromManifest(e);
    }
    const std::unique_ptr<tbb::global_control> limit = limitThreadsToAllocation();
    // The compiled level, made once by the submitting command: the shard does not compile.
    if (!slurm::verifiedCompiled(work, manifest))
        throw world::Error(work.compiled() +
                           ": missing or does not verify (checksum, level or settings); expected "
                           "the compiled level that onelight-bake --slurm writes before it "
                           "submits: run that command again");
    noteStage("reading the compiled level");
    const package::PackageContents read = package::readPackageFile(work.compiled());
    CompiledForBake compiled{read.level, {}, {}};
    const package::TextureContents textures =
        package::decodeTextureSection(read.bakedSections, read.level, work.compiled());
    if (!textures.present)
        throw world::Error(work.compiled() +
                           ": no textures section (38); expected the texture stage's mips");
    // The source still gives the Embree scene and the lights: the scene is the source's static
    // geometry, as in a whole bake, so that the parts equal it byte for byte.
    noteStage("importing the level");
    world::SourceLevel source;
    try {
        source = world::importLevel(plan.input, plan.quake3);
    } catch (const world::Error& e) {
        throw fromManifest(e);
    }
    const uint64_t levelHash = slurm::hashFiles(source.inputFiles);
    if (levelHash != manifest.levelHash)
        throw world::Error(manifest.level +
                           ": changed since the bake was submitted (content hash " +
                           slurm::hashHex(levelHash) + ", the work folder's " +
                           slurm::hashHex(manifest.levelHash) +
                           "); expected the level the manifest hashed: run onelight-bake --slurm "
                           "again with another --work");
    noteStage("baking the shard");
    BakeReport report = startReport(source, plan.options);
    const BakeWorld bakeWorld(source, textures.textures, plan.options, report);
    const world::BakedLighting baked =
        bakeLighting(source, bakeWorld, compiled, plan.options, report);
    noteStage("writing the shard");
    writeBakedPackage(plan, compiled.level, baked, textures.textures, report);
    slurm::writeShardStamp(work, manifest, shard, slurm::hostName(), secondsSince(start));
    return 0;
}

int mergeShards(const WorkFolder& work, const std::string& output) {
    const auto start = std::chrono::steady_clock::now();
    const Manifest manifest = requireManifest(work);
    if (std::filesystem::absolute(output).lexically_normal() != manifest.output)
        throw world::Error("-o " + output + ": " + work.root + " bakes " + manifest.output +
                           "; expected that package (the shards placed its images for it)");
    std::vector<std::string> arguments = {"-o", output};
    for (uint32_t i = 0; i < manifest.shardCount; ++i) {
        if (!slurm::verifiedShard(work, manifest, i))
            throw world::Error(work.shardStamp(i) + ": shard " + std::to_string(i) + " of " +
                               std::to_string(manifest.shardCount) +
                               " is missing or does not verify (checksum, level or settings); "
                               "expected every shard baked before the merge");
        arguments.push_back(work.shardPackage(i));
    }
    const int code = runMergeCommand(arguments);
    if (code != 0) return code;
    std::error_code error;
    slurm::writeMergeStamp(work, {slurm::hostName(), output, secondsSince(start),
                                  std::filesystem::file_size(output, error)});
    return 0;
}

}  // namespace

const world::CommandTable& slurmTaskCommandTable() {
    static const world::CommandTable table = [] {
        world::CommandTable t;
        t.program = "onelight-bake slurm-task";
        t.synopsis = "onelight-bake slurm-task --work DIR (--shard I | --merge -o OUT)";
        t.summary =
            "what the jobs of onelight-bake --slurm run (their batch scripts call it): bake shard "
            "I of the work folder's level, or merge its verified shards into OUT";
        t.options = {world::textOption("--work", "DIR", "the work folder of the Slurm bake",
                                       world::kRequiredOption),
                     world::integerOption("--shard", "I", 0, 65535,
                                          "bake shard I (the array task's index)", "none"),
                     world::flagOption("--merge", "merge every verified shard", "none"),
                     world::textOption("-o", "PATH",
                                       "the package the merge writes (required with --merge)", "")};
        return t;
    }();
    return table;
}

std::string slurmTaskUsage() {
    return world::formatHelp(slurmTaskCommandTable());
}

int runSlurmTaskCommand(const std::vector<std::string>& arguments) {
    return runCommandLine(
        slurmTaskCommandTable(), arguments, [](const world::ParsedOptions& parsed) {
            const bool merge = parsed.has("--merge");
            if (merge == parsed.has("--shard"))
                throw world::Error("expected one of --shard I and --merge");
            if (merge && !parsed.has("-o")) throw world::Error("--merge needs -o OUT");
            if (!merge && parsed.has("-o"))
                throw world::Error(
                    "-o with --shard; expected -o only with --merge (a shard's "
                    "package goes to the work folder)");
            const WorkFolder work{
                std::filesystem::absolute(parsed.text("--work")).lexically_normal().string()};
            return runReportingErrors(work.root, [&] {
                return merge ? mergeShards(work, parsed.text("-o"))
                             : bakeShard(work, uint32_t(parsed.integer("--shard")));
            });
        });
}

}  // namespace onelight::bake
