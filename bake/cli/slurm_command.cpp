// onelight-bake LEVEL -o OUT --slurm N [OPTIONS]: the bake as a Slurm job array of N shard
// tasks and a merge job that runs after them (afterok, --kill-on-invalid-dep=yes: a failed shard
// cancels it). The level is imported here once, to check it and hash it into the work folder's
// manifest, and compiled here once into the work folder, which every shard bakes from; shards
// already baked and verified there are skipped, so rerunning the same command resumes. Waits with a
// progress bar over the shards (ETA from the finished ones) and prints the summary a local bake
// prints, each shard's node and time, and the merge's.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "bake/cli/bake_plan.hpp"
#include "bake/cli/cli_common.hpp"
#include "bake/cli/subcommands.hpp"
#include "bake/report/interrupt.hpp"
#include "bake/report/progress.hpp"
#include "bake/slurm/batch_scripts.hpp"
#include "bake/slurm/content_hash.hpp"
#include "bake/slurm/job_watch.hpp"
#include "bake/slurm/scheduler.hpp"
#include "bake/slurm/shard_reports.hpp"
#include "bake/slurm/work_folder.hpp"
#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/file_write.hpp"
#include "world/import/level_import.hpp"
#include "world/level_names.hpp"
#include "world/package/package_writer.hpp"
#include "world/package/texture_section.hpp"
#include "world/process/child_process.hpp"

namespace onelight::bake {
namespace {

using slurm::Manifest;
using slurm::WorkFolder;

/// How long the merge job may take to end once the shards have: the merge itself is short,
/// and a merge cancelled by a failed shard ends within seconds.
constexpr double kMergeWaitSeconds = 3600.0;
constexpr double kCancelledMergeWaitSeconds = 120.0;

std::string absolutePath(const std::string& path) {
    return std::filesystem::absolute(path).lexically_normal().string();
}

/// The level as every node names it: a file's absolute path; PAK.pk3:maps/NAME.bsp with the
/// pk3's absolute path; an installed map's NAME as it is.
std::string levelForNodes(const std::string& level) {
    std::error_code error;
    if (std::filesystem::exists(level, error)) return absolutePath(level);
    const size_t colon = level.find(':');
    if (colon != std::string::npos && std::filesystem::exists(level.substr(0, colon), error))
        return absolutePath(level.substr(0, colon)) + level.substr(colon);
    return level;
}

std::string shardList(const std::vector<uint32_t>& shards) {
    return shards.size() == 1 ? "shard " + slurm::arraySpec(shards)
                              : "shards " + slurm::arraySpec(shards);
}

/// Submits the array of `shards` and the merge after it; returns {array job, merge job} (the
/// array job empty when there is no shard to bake).
std::pair<std::string, std::string> submit(const WorkFolder& work,
                                           const std::vector<uint32_t>& shards) {
    std::string array;
    std::vector<std::string> mergeArguments;
    if (!shards.empty()) {
        array =
            slurm::submitJob({"--array=" + slurm::arraySpec(shards)}, work.scripts() + "/shard.sh");
        mergeArguments = {"--dependency=afterok:" + array, "--kill-on-invalid-dep=yes"};
    }
    const std::string merge = slurm::submitJob(mergeArguments, work.scripts() + "/merge.sh");
    slurm::writeSubmittedJobs(work, {array, merge, shards});
    return {array, merge};
}

/// The last submission when it is still going, has failed nowhere and covers every shard still
/// to bake: its merge job queued or running, none of its array tasks failed. A rerun (after
/// --no-wait, or an interrupted wait) then waits for it instead of submitting again.
std::optional<slurm::SubmittedJobs> submissionInFlight(const WorkFolder& work,
                                                       const std::vector<uint32_t>& missing) {
    const std::optional<slurm::SubmittedJobs> jobs = slurm::readSubmittedJobs(work);
    if (!jobs) return std::nullopt;
    for (const uint32_t shard : missing)
        if (std::find(jobs->shards.begin(), jobs->shards.end(), shard) == jobs->shards.end())
            return std::nullopt;
    const slurm::JobDetails merge = slurm::queryJob(jobs->mergeJob);
    if (merge.state.empty() || slurm::finalState(merge.state)) return std::nullopt;
    if (!jobs->arrayJob.empty())
        for (const slurm::TaskState& t : slurm::queryArrayTasks(jobs->arrayJob))
            if (slurm::failedState(t.state)) return std::nullopt;
    return jobs;
}

void printSummary(const BakePlan& plan, const WorkFolder& work, const Manifest& manifest,
                  const std::string& mergeJob, double wallSeconds) {
    std::vector<BakeReport> reports;
    std::vector<slurm::ShardStamp> stamps;
    for (uint32_t i = 0; i < manifest.shardCount; ++i) {
        reports.push_back(slurm::readReport(work.shardReport(i)));
        const std::optional<slurm::ShardStamp> stamp = slurm::verifiedShard(work, manifest, i);
        if (stamp) stamps.push_back(*stamp);
    }
    const std::optional<slurm::ShardStamp> compiled = slurm::verifiedCompiled(work, manifest);
    BakeReport whole =
        slurm::combineShardReports(slurm::readReport(work.compiledReport()), reports);
    const std::optional<slurm::MergeStamp> merge = slurm::readMergeStamp(work);
    whole.packageBytes = merge ? merge->packageBytes : 0;
    if (!plan.reportPath.empty())
        slurm::writeSlurmReport(plan.reportPath, whole, compiled.value_or(slurm::ShardStamp{}),
                                stamps, reports, merge.value_or(slurm::MergeStamp{}), wallSeconds);
    std::printf("baked %s (%llu bytes, quality %s, %u shards on Slurm, merge job %s)\n",
                plan.output.c_str(), static_cast<unsigned long long>(whole.packageBytes),
                qualityName(plan.options.quality), manifest.shardCount, mergeJob.c_str());
    std::printf("%s", reportSummary(whole).c_str());
    std::printf("  (stage seconds and rays are summed over the shards)\n");
    if (compiled)
        std::printf("  compile    %-12s %8.2f s, once, before the shards\n", compiled->node.c_str(),
                    compiled->seconds);
    std::printf("%s", slurm::shardTimeLines(stamps, reports).c_str());
    if (merge) std::printf("  merge      %-12s %8.2f s\n", merge->node.c_str(), merge->seconds);
    std::printf("  wall       %.2f s from submission to the package\n", wallSeconds);
    for (const std::string& warning : whole.warnings)
        std::fprintf(stderr, "onelight-bake: warning: %s: %s\n", manifest.level.c_str(),
                     warning.c_str());
}

/// Compiles the level once into the work folder (stages 0 to 2 of the bake: the texture
/// stage, the scene, the compile with its density pilot), its images placed for the output, and
/// stamps it; every shard then bakes from it. Skipped when its stamp already verifies.
void compileIntoWorkFolder(const world::SourceLevel& source, const BakePlan& plan,
                           const WorkFolder& work, const Manifest& manifest) {
    if (const std::optional<slurm::ShardStamp> done = slurm::verifiedCompiled(work, manifest)) {
        std::printf("the compiled level in %s verifies: not compiled again\n",
                    work.compiled().c_str());
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    noteStage("compiling the level");
    BakeOptions options = plan.options;
    options.shardIndex = 0;
    options.shardCount = 1;
    BakeReport report = startReport(source, options);
    const world::ProcessedTextures textures = bakeTextures(source, options, report);
    CompiledForBake compiled;
    {
        const BakeWorld bakeWorld(source, textures, options, report);
        compiled = compileForBake(source, bakeWorld, options, report);
    }
    package::placeImagesForPackage(compiled.level, manifest.output);
    const std::vector<package::RawSection> sections = {package::encodeTextureSection(textures)};
    const std::vector<uint8_t> bytes = package::serializePackage(compiled.level, sections);
    report.peakMemoryBytes = peakMemoryBytes();
    writeReport(work.compiledReport(), report);
    world::writeFileAtomically(work.compiled(), bytes);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    slurm::writeCompiledStamp(work, manifest, slurm::hostName(), seconds);
    std::printf("compiled the level once into %s (%.2f s; %zu surfaces, %llu texels to bake)\n",
                work.compiled().c_str(), seconds, compiled.level.surfaces.size(),
                static_cast<unsigned long long>(totalTexels(compiled.level)));
}

/// Waits for the rounds of shard tasks (a first one, then one per retry) and the merge.
int waitForBake(const BakePlan& plan, const WorkFolder& work, const Manifest& manifest,
                std::vector<uint32_t> shards, std::pair<std::string, std::string> jobs) {
    const auto start = std::chrono::steady_clock::now();
    if (plan.options.showProgress)
        std::fprintf(
            stderr,
            "onelight-bake: waiting for the jobs; Ctrl-C stops waiting, the jobs go on and "
            "rerunning the same command resumes\n");
    Progress progress("shards", shards.size(), plan.options.showProgress);
    for (uint32_t attempt = 0; !shards.empty(); ++attempt) {
        std::vector<slurm::ShardFailure> failures = slurm::watchShardArray(
            work, manifest, jobs.first, shards, [&](uint32_t) { progress.advance(1); },
            [&](const slurm::ShardFailure& f) {
                std::fprintf(stderr, "\nonelight-bake: %s\n", slurm::describeFailure(f).c_str());
            });
        if (failures.empty()) break;
        shards.clear();
        for (const slurm::ShardFailure& f : failures) shards.push_back(f.shard);
        // The merge was cancelled by the failure (--kill-on-invalid-dep); make sure of it.
        const slurm::JobDetails merge = slurm::waitForJob(jobs.second, kCancelledMergeWaitSeconds);
        if (!merge.state.empty() && !slurm::finalState(merge.state)) slurm::cancelJob(jobs.second);
        if (attempt < plan.slurm->retries) {
            jobs = submit(work, shards);
            std::fprintf(stderr,
                         "onelight-bake: resubmitted %s (retry %u of %u) as array job %s, the "
                         "merge as job %s\n",
                         shardList(shards).c_str(), attempt + 1, plan.slurm->retries,
                         jobs.first.c_str(), jobs.second.c_str());
            continue;
        }
        std::string message = std::to_string(failures.size()) + " of " +
                              std::to_string(manifest.shardCount) + " shards failed: ";
        for (size_t i = 0; i < failures.size(); ++i)
            message += (i ? "; " : "") + slurm::describeFailure(failures[i]);
        throw world::Error(message + "; the merge job " + jobs.second + " was " +
                           (merge.state.empty() ? "ended" : "cancelled") +
                           " and no package was written; rerun the same command to bake only "
                           "the missing shards");
    }
    progress.finish();
    const slurm::JobDetails merge = slurm::waitForJob(jobs.second, kMergeWaitSeconds);
    const std::optional<slurm::MergeStamp> stamp = slurm::readMergeStamp(work);
    if (merge.state != "COMPLETED" && !(merge.state.empty() && stamp))
        throw world::Error("the merge job " + jobs.second + " ended " +
                           (merge.state.empty() ? "unseen" : merge.state) +
                           (merge.node.empty() ? "" : " on node " + merge.node) +
                           (merge.exitCode.empty() ? "" : " (exit " + merge.exitCode + ")") +
                           (merge.log.empty() ? "" : "; its log: " + merge.log) +
                           "; no package was written");
    if (!stamp || stamp->output != plan.output)
        throw world::Error(work.mergeStamp() +
                           ": missing or for another output after the merge "
                           "job " +
                           jobs.second + "; expected " + plan.output);
    printSummary(plan, work, manifest, jobs.second,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return 0;
}

}  // namespace

int runSlurmBake(BakePlan& plan) {
    plan.output = absolutePath(plan.output);
    const WorkFolder work{
        absolutePath(plan.slurm->work.empty()
                         ? std::filesystem::path(plan.output).replace_extension(".slurm").string()
                         : plan.slurm->work)};
    if (plan.slurm->emitScripts.empty()) slurm::requireSlurmClients();

    noteStage("importing the level");
    const world::SourceLevel source = world::importLevel(plan.input, plan.quake3);
    world::refuseOutputOverInput(plan.output, source.inputFiles);
    Manifest manifest;
    manifest.level = levelForNodes(plan.input);
    manifest.levelHash = slurm::hashFiles(source.inputFiles);
    manifest.output = plan.output;
    manifest.bakeArguments = plan.slurm->shardArguments;
    manifest.shardCount = plan.slurm->shards;

    slurm::makeWorkFolder(work);
    if (const std::optional<Manifest> found = slurm::readManifest(work)) {
        if (!slurm::sameBake(*found, manifest))
            throw world::Error(work.root + ": the work folder of another bake: " +
                               slurm::describeChange(*found, manifest) +
                               "; it is left as it is (its jobs may still run): remove it or "
                               "pass another --work");
    } else {
        slurm::writeManifest(work, manifest);
    }
    std::vector<uint32_t> missing;
    for (uint32_t i = 0; i < manifest.shardCount; ++i)
        if (!slurm::verifiedShard(work, manifest, i)) missing.push_back(i);
    if (!missing.empty()) compileIntoWorkFolder(source, plan, work, manifest);

    const slurm::BatchScripts scripts =
        slurm::batchScripts(work, world::ownExecutable(), plan.output, plan.slurm->job, missing);
    slurm::writeBatchScripts(work.scripts(), scripts);
    if (!plan.slurm->emitScripts.empty()) {
        slurm::writeBatchScripts(plan.slurm->emitScripts, scripts);
        std::printf(
            "wrote %s/shard.sh, merge.sh and submit.sh (%s of %u to bake); submit them "
            "with %s/submit.sh\n",
            plan.slurm->emitScripts.c_str(),
            missing.empty() ? "no shard" : shardList(missing).c_str(), manifest.shardCount,
            plan.slurm->emitScripts.c_str());
        return 0;
    }

    if (missing.size() < manifest.shardCount)
        std::printf("%u of %u shards already baked and verified in %s\n",
                    manifest.shardCount - uint32_t(missing.size()), manifest.shardCount,
                    work.root.c_str());
    std::pair<std::string, std::string> jobs;
    if (const std::optional<slurm::SubmittedJobs> earlier = submissionInFlight(work, missing)) {
        jobs = {earlier->arrayJob, earlier->mergeJob};
        std::printf(
            "the jobs of an earlier run are still queued or running: %s%s, the merge "
            "job %s; waiting for them\n",
            missing.empty() ? "no shard" : shardList(missing).c_str(),
            jobs.first.empty() ? "" : (" in array job " + jobs.first).c_str(), jobs.second.c_str());
    } else {
        std::error_code error;
        std::filesystem::remove(work.mergeStamp(), error);  // a previous run's: not this merge's
        jobs = submit(work, missing);
        if (missing.empty())
            std::printf("submitted the merge as job %s\n", jobs.second.c_str());
        else
            std::printf("submitted %s of %u as array job %s, the merge as job %s (after them)\n",
                        shardList(missing).c_str(), manifest.shardCount, jobs.first.c_str(),
                        jobs.second.c_str());
    }
    std::fflush(stdout);
    if (!plan.slurm->wait) {
        std::printf(
            "not waiting (--no-wait): the logs are in %s; rerun the same command without "
            "--no-wait to wait for these jobs (it submits nothing while they are queued or "
            "running)\n",
            work.logs().c_str());
        return 0;
    }
    return waitForBake(plan, work, manifest, missing, jobs);
}

}  // namespace onelight::bake
