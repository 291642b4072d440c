// Bakes on a real single-node Slurm: tests/slurm/local_slurm.sh starts munged, slurmctld and
// slurmd on localhost with all their state in a temporary folder, and stops them by PID after
// each test. Skips (ctest reports it) when the Slurm packages are not installed.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.hpp"
#include "tests/world/world_test_support.hpp"

namespace {

namespace fs = std::filesystem;
using onelight::test::CommandResult;
using onelight::test::runCommand;

const std::string kBake = ONELIGHT_BAKE_EXE;
const std::string kLocalSlurm = ONELIGHT_LOCAL_SLURM;

std::vector<char> fileBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool slurmInstalled() {
    for (const char* tool : {"munged", "slurmctld", "slurmd", "sbatch", "squeue", "scontrol"})
        if (runCommand(std::string("command -v ") + tool).exitCode != 0) return false;
    return true;
}

/// A small room: a floor, a glossy metal box on it that casts shadows and asks for probes, and
/// `lamps` point lights (1 or 2). Written to the same path whatever `lamps` is.
std::string writeLevel(int lamps) {
    onelight::test::GltfBuilder gltf;
    gltf.addNode({{"name", "floor"},
                  {"mesh", gltf.addMesh(onelight::test::gridMesh("floor", 6, 6.0, 0.0))}});
    onelight::test::MeshData box =
        onelight::test::boxMesh("box", glm::vec3(-0.5f, 0.0f, -0.5f), glm::vec3(0.5f), 2, true);
    box.material = gltf.addMaterial(
        {{"pbrMetallicRoughness", {{"metallicFactor", 1.0}, {"roughnessFactor", 0.3}}}});
    gltf.addNode({{"name", "box"}, {"mesh", gltf.addMesh(box)}});
    for (int i = 0; i < lamps; ++i) {
        const int light = gltf.addLight({{"type", "point"}, {"intensity", 100.0}});
        gltf.addNode({{"name", "lamp" + std::to_string(i)},
                      {"translation", {i == 0 ? -1.5 : 1.5, 2.0, 0.5}},
                      {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
    }
    return gltf.write(onelight::test::freshFolder("slurm-level"), "room");
}

/// How many submissions the controller knows: an array job counts once, whatever its tasks.
int submissionCount() {
    const CommandResult r = runCommand(
        "scontrol show job -o | awk '{ id = \"\"; for (i = 1; i <= NF; ++i) { if ($i ~ "
        "/^ArrayJobId=/) id = $i; if (id == \"\" && $i ~ /^JobId=/) id = $i } print id }' | "
        "sort -u | wc -l");
    return std::atoi(r.output.c_str());
}

/// How many jobs (array tasks count one each, once they run) the controller knows.
int jobCount() {
    const CommandResult r = runCommand("scontrol show job -o | grep -c '^JobId='");
    return std::atoi(r.output.c_str());
}

class SlurmBake : public ::testing::Test {
protected:
    void SetUp() override {
        if (!slurmInstalled())
            GTEST_SKIP() << "Slurm is not installed: the packages slurmctld slurmd slurm-client "
                            "munge (scripts/packages.txt; scripts/setup.sh installs them as root)";
        // Short: munged's socket path must fit a sockaddr_un.
        cluster_ = "/tmp/onelight-slurm-" + std::to_string(getpid());
        fs::remove_all(cluster_);
        const CommandResult started = runCommand(kLocalSlurm + " start " + cluster_.string());
        started_ = true;
        ASSERT_EQ(started.exitCode, 0) << started.output;
        setenv("SLURM_CONF", (cluster_ / "slurm.conf").c_str(), 1);
        folder_ = onelight::test::freshFolder("slurm-bake");
        level_ = writeLevel(2);
    }
    void TearDown() override {
        if (!started_) return;
        const CommandResult stopped = runCommand(kLocalSlurm + " stop " + cluster_.string());
        EXPECT_EQ(stopped.exitCode, 0) << stopped.output;
        unsetenv("SLURM_CONF");
        if (HasFailure()) return;
        fs::remove_all(cluster_);
        fs::remove_all(folder_);
        fs::remove_all(fs::path(level_).parent_path());
    }
    /// A local bake of the level: what every Slurm bake must equal byte for byte.
    /// `density`: --uniform-density (fast) or "" (the density pilot, which runs in the compile).
    std::vector<char> localBake(const std::string& density = "--uniform-density") {
        const fs::path out = folder_ / "local.olpak";
        const CommandResult r = runCommand(kBake + " " + level_ + " -o " + out.string() +
                                           " --quality draft --quiet " + density);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return fileBytes(out);
    }
    CommandResult slurmBake(const std::string& extra, const std::string& environment = "",
                            const std::string& density = "--uniform-density") {
        return runCommand(environment + " " + kBake + " " + level_ + " -o " +
                          (folder_ / "slurm.olpak").string() + " --quality draft --quiet " +
                          density + " --work " + (folder_ / "work").string() + " " + extra);
    }

    fs::path cluster_, folder_;
    std::string level_;
    bool started_ = false;
};

std::string fileText(const fs::path& path) {
    const std::vector<char> bytes = fileBytes(path);
    return {bytes.begin(), bytes.end()};
}

// With the density pilot, which the compile runs: the level is compiled once, here, and the
// shards bake from the work folder's compiled level without compiling it again.
TEST_F(SlurmBake, FourShardsEqualALocalBake) {
    const fs::path report = folder_ / "report.json";
    const CommandResult r = slurmBake("--slurm 4 --report " + report.string(), "", "");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("compiled the level once into " + (folder_ / "work").string() +
                            "/compiled.olpak"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("submitted shards 0-3 of 4 as array job"), std::string::npos)
        << r.output;
    // The local bake's summary, the compile, and each shard's node, time and estimated share.
    for (const char* line : {"lightmaps", "total", "s, once, before the shards", "shard 0",
                             "shard 3", "of the divided work by estimate", "balance", "merge"})
        EXPECT_NE(r.output.find(line), std::string::npos) << line << "\n" << r.output;
    EXPECT_TRUE(fileBytes(folder_ / "slurm.olpak") == localBake(""));
    // The compile's report holds the texture stage and the compile; no shard's does.
    EXPECT_NE(fileText(folder_ / "work" / "compiled.json").find("\"name\": \"compile\""),
              std::string::npos);
    double estimated = 0.0, all = 0.0;
    for (int i = 0; i < 4; ++i) {
        const std::string shard =
            fileText(folder_ / "work" / "shards" / ("shard-" + std::to_string(i) + ".json"));
        EXPECT_EQ(shard.find("\"name\": \"compile\""), std::string::npos) << shard;
        EXPECT_EQ(shard.find("\"name\": \"textures\""), std::string::npos) << shard;
        const std::string key = "\"estimated_core_seconds\": ",
                          allKey = "\"estimated_core_seconds_all_shards\": ";
        const size_t at = shard.find(key);
        ASSERT_NE(at, std::string::npos) << shard;
        estimated += std::atof(shard.c_str() + at + key.size());
        const size_t total = shard.find(allKey);
        ASSERT_NE(total, std::string::npos) << shard;
        all = std::atof(shard.c_str() + total + allKey.size());
    }
    // The shards' estimated shares add up to the whole divided work.
    EXPECT_GT(all, 0.0);
    EXPECT_NEAR(estimated, all, 1e-6 * all);
    // The report gives the compile's node and time, each shard's, and the merge's.
    const std::string text = fileText(report);
    size_t nodes = 0;
    for (size_t at = 0; (at = text.find("\"node\": \"localhost\"", at)) != std::string::npos; ++at)
        ++nodes;
    EXPECT_EQ(nodes, 5u) << text;  // four shards and the merge; the compile ran here
    EXPECT_NE(text.find("\"compile\": {\n    \"node\": \""), std::string::npos) << text;
    for (const char* key : {"\"compile\"", "\"shards\"", "\"stage_seconds\"", "\"merge\"",
                            "\"wall_seconds\"", "\"estimated_core_seconds\""})
        EXPECT_NE(text.find(key), std::string::npos) << key;
    // The parts gathered every texel they sampled and some of their neighbours' (the denoiser's
    // windows across their edges), and the summary says how many against a whole bake.
    const nlohmann::json whole = nlohmann::json::parse(text);
    const uint64_t sampled = whole["lightmap"]["texels_sampled"],
                   gathered = whole["lightmap"]["texels_gathered"];
    EXPECT_GT(sampled, 0u);
    EXPECT_GT(gathered, sampled);
    EXPECT_LT(gathered, 4 * sampled);
    EXPECT_NE(r.output.find("x a whole bake's final gathers (" + std::to_string(gathered) +
                            " texels for " + std::to_string(sampled)),
              std::string::npos)
        << r.output;
    for (int i = 0; i < 4; ++i)
        EXPECT_TRUE(fs::exists(folder_ / "work" / "shards" /
                               ("shard-" + std::to_string(i) + ".stamp.json")));
}

TEST_F(SlurmBake, AFailedShardCancelsTheMergeAndARerunBakesOnlyIt) {
    const CommandResult failed = slurmBake("--slurm 4", "ONELIGHT_SLURM_FAIL_SHARD=2");
    EXPECT_EQ(failed.exitCode, 1) << failed.output;
    // Named: the shard, its node and its log; the merge cancelled; no package.
    EXPECT_NE(failed.output.find("1 of 4 shards failed: shard 2 (job "), std::string::npos)
        << failed.output;
    EXPECT_NE(failed.output.find("on node localhost"), std::string::npos) << failed.output;
    const fs::path logs = folder_ / "work" / "logs";
    EXPECT_NE(failed.output.find("its log: " + logs.string() + "/shard-2.job-"), std::string::npos)
        << failed.output;
    EXPECT_NE(failed.output.find("was cancelled and no package was written"), std::string::npos)
        << failed.output;
    EXPECT_FALSE(fs::exists(folder_ / "slurm.olpak"));
    const size_t merge = failed.output.find("the merge as job ");
    ASSERT_NE(merge, std::string::npos) << failed.output;
    const std::string mergeJob =
        failed.output.substr(merge + 17, failed.output.find(' ', merge + 17) - merge - 17);
    const CommandResult state = runCommand("scontrol show job -o " + mergeJob);
    EXPECT_NE(state.output.find("JobState=CANCELLED"), std::string::npos) << state.output;
    // The failed task's log says why.
    bool logSaysWhy = false;
    for (const fs::directory_entry& e : fs::directory_iterator(logs))
        if (e.path().filename().string().rfind("shard-2.", 0) == 0) {
            const std::vector<char> text = fileBytes(e.path());
            logSaysWhy = std::string(text.begin(), text.end()).find("failing on purpose") !=
                         std::string::npos;
        }
    EXPECT_TRUE(logSaysWhy);

    // Without the fault: only shard 2 and the merge are submitted, and the package equals a
    // local bake's.
    const fs::path stamp0 = folder_ / "work" / "shards" / "shard-0.stamp.json";
    const fs::file_time_type stamp0Time = fs::last_write_time(stamp0);
    const fs::path compiled = folder_ / "work" / "compiled.olpak";
    const fs::file_time_type compiledTime = fs::last_write_time(compiled);
    const int jobsBefore = jobCount();
    const CommandResult rerun = slurmBake("--slurm 4");
    ASSERT_EQ(rerun.exitCode, 0) << rerun.output;
    EXPECT_NE(rerun.output.find("3 of 4 shards already baked and verified"), std::string::npos)
        << rerun.output;
    EXPECT_NE(rerun.output.find("submitted shard 2 of 4 as array job"), std::string::npos)
        << rerun.output;
    EXPECT_EQ(jobCount() - jobsBefore, 2) << "one shard task and the merge";
    EXPECT_TRUE(fs::last_write_time(stamp0) == stamp0Time) << "shard 0 was baked again";
    EXPECT_NE(rerun.output.find("the compiled level in " + compiled.string() +
                                " verifies: not compiled again"),
              std::string::npos)
        << rerun.output;
    EXPECT_TRUE(fs::last_write_time(compiled) == compiledTime) << "compiled again";
    EXPECT_TRUE(fileBytes(folder_ / "slurm.olpak") == localBake());
}

TEST_F(SlurmBake, RetriesResubmitAShardThatFailedOnce) {
    const CommandResult r = slurmBake("--slurm 2 --retries 1", "ONELIGHT_SLURM_FAIL_SHARD=1,once");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("shard 1 (job "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("resubmitted shard 1 (retry 1 of 1)"), std::string::npos) << r.output;
    EXPECT_TRUE(fileBytes(folder_ / "slurm.olpak") == localBake());
}

TEST_F(SlurmBake, NoWaitReturnsTheJobIdsAndARerunWaitsForThemWithoutSubmitting) {
    // The node drained: the jobs stay queued until the rerun below is waiting for them.
    const CommandResult drained =
        runCommand("scontrol update NodeName=localhost State=DRAIN Reason=onelight-test");
    ASSERT_EQ(drained.exitCode, 0) << drained.output;
    const CommandResult submitted = slurmBake("--slurm 2 --no-wait");
    ASSERT_EQ(submitted.exitCode, 0) << submitted.output;
    EXPECT_NE(submitted.output.find("submitted shards 0-1 of 2 as array job"), std::string::npos)
        << submitted.output;
    EXPECT_NE(submitted.output.find("not waiting (--no-wait)"), std::string::npos)
        << submitted.output;
    EXPECT_FALSE(fs::exists(folder_ / "slurm.olpak"));
    const int submissionsBefore = submissionCount();
    ASSERT_EQ(submissionsBefore, 2) << "the array and the merge";
    const CommandResult rerun =
        slurmBake("--slurm 2",
                  "(sleep 2; scontrol update NodeName=localhost State=RESUME) >/dev/null 2>&1 &");
    ASSERT_EQ(rerun.exitCode, 0) << rerun.output;
    EXPECT_NE(rerun.output.find("the jobs of an earlier run are still queued or running"),
              std::string::npos)
        << rerun.output;
    EXPECT_EQ(submissionCount(), submissionsBefore) << "the rerun submitted jobs\n" << rerun.output;
    EXPECT_TRUE(fileBytes(folder_ / "slurm.olpak") == localBake());
}

TEST_F(SlurmBake, AChangedLevelIsRefusedWithTheReason) {
    const CommandResult first = slurmBake("--slurm 2 --emit-scripts " + (folder_ / "s").string());
    ASSERT_EQ(first.exitCode, 0) << first.output;
    // The same level name with other content: one lamp less.
    const std::string other = writeLevel(1);
    ASSERT_EQ(other, level_);
    const CommandResult changed = slurmBake("--slurm 2");
    EXPECT_EQ(changed.exitCode, 1) << changed.output;
    EXPECT_NE(changed.output.find("the level's content changed"), std::string::npos)
        << changed.output;
    EXPECT_NE(changed.output.find("remove it or pass another --work"), std::string::npos)
        << changed.output;
    const CommandResult settings =
        runCommand(kBake + " " + level_ + " -o " + (folder_ / "slurm.olpak").string() +
                   " --quality default --slurm 2 --work " + (folder_ / "work").string());
    EXPECT_EQ(settings.exitCode, 1) << settings.output;
}

}  // namespace
