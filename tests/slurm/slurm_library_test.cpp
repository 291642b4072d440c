// The Slurm bake's library without a cluster: parsing what squeue and scontrol print, the array
// lists and scripts given to sbatch, the work folder's manifest and the verification of a
// shard's stamp, and the bound on every wait for a client command.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "bake/slurm/batch_scripts.hpp"
#include "bake/slurm/content_hash.hpp"
#include "bake/slurm/scheduler.hpp"
#include "bake/slurm/work_folder.hpp"
#include "error_message.hpp"

namespace onelight::bake::slurm {
namespace {

/// A fresh empty folder under the system temp folder, removed again at the end of the test.
struct TempFolder {
    std::filesystem::path path;
    explicit TempFolder(const std::string& label)
        : path(std::filesystem::temp_directory_path() /
               ("onelight-slurm-" + label + "-" + std::to_string(getpid()))) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;
};

void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

Manifest testManifest() {
    Manifest m;
    m.level = "/levels/room.gltf";
    m.levelHash = 0x1234;
    m.bakeArguments = {"--quality", "draft"};
    m.shardCount = 4;
    return m;
}

TEST(SlurmArraySpec, JoinsRunsOfShards) {
    EXPECT_EQ(arraySpec({0, 1, 2, 3}), "0-3");
    EXPECT_EQ(arraySpec({2}), "2");
    EXPECT_EQ(arraySpec({1, 4, 5, 6, 9}), "1,4-6,9");
    EXPECT_EQ(arraySpec({}), "");
}

TEST(SlurmScheduler, ParsesOneLinePerArrayTask) {
    const std::vector<TaskState> tasks = parseTaskStates(
        "0|COMPLETED|node1\n1|RUNNING|node2\n2|PENDING|\n3|FAILED|node1 \n"
        "garbage\n[4-7]|PENDING|\n");
    ASSERT_EQ(tasks.size(), 4u);
    EXPECT_EQ(tasks[0].shard, 0u);
    EXPECT_EQ(tasks[0].state, "COMPLETED");
    EXPECT_EQ(tasks[0].node, "node1");
    EXPECT_EQ(tasks[2].node, "");
    EXPECT_EQ(tasks[3].state, "FAILED");
    EXPECT_EQ(tasks[3].node, "node1");
}

TEST(SlurmScheduler, ParsesScontrolsJobLine) {
    const JobDetails d = parseJobDetails(
        "JobId=5 ArrayJobId=1 ArrayTaskId=2 JobName=onelight-shard JobState=FAILED "
        "Reason=NonZeroExitCode Dependency=(null) ExitCode=1:0 NodeList=n7 "
        "StdOut=/work/logs/shard-2.job-1.log Power=\n");
    EXPECT_EQ(d.state, "FAILED");
    EXPECT_EQ(d.reason, "NonZeroExitCode");
    EXPECT_EQ(d.exitCode, "1:0");
    EXPECT_EQ(d.node, "n7");
    EXPECT_EQ(d.log, "/work/logs/shard-2.job-1.log");
    EXPECT_EQ(parseJobDetails("JobId=9 JobState=PENDING NodeList=(null)").node, "");
}

TEST(SlurmScheduler, TellsFailedFromFinalStates) {
    for (const char* s :
         {"FAILED", "CANCELLED", "CANCELLED+", "TIMEOUT", "NODE_FAIL", "OUT_OF_MEMORY"})
        EXPECT_TRUE(failedState(s)) << s;
    for (const char* s : {"COMPLETED", "PENDING", "RUNNING", "COMPLETING", ""})
        EXPECT_FALSE(failedState(s)) << s;
    EXPECT_TRUE(finalState("COMPLETED"));
    EXPECT_FALSE(finalState("RUNNING"));
}

TEST(SlurmScripts, TheMergeWaitsForEveryShardAndDiesWithAFailedOne) {
    const WorkFolder work{"/shared/work dir"};
    JobOptions options;
    options.partition = "bake";
    options.timeLimit = "1:00:00";
    options.cpusPerTask = 8;
    const BatchScripts s = batchScripts(work, "/opt/onelight/onelight-bake", "/shared/out.olpak",
                                        options, {0, 1, 2, 3});
    EXPECT_NE(s.shard.find("#SBATCH --partition=bake\n"), std::string::npos) << s.shard;
    EXPECT_NE(s.shard.find("#SBATCH --time=1:00:00\n"), std::string::npos) << s.shard;
    EXPECT_NE(s.shard.find("#SBATCH --cpus-per-task=8\n"), std::string::npos) << s.shard;
    EXPECT_NE(s.shard.find("--work '/shared/work dir' --shard \"$SLURM_ARRAY_TASK_ID\""),
              std::string::npos)
        << s.shard;
    EXPECT_NE(s.merge.find("--merge -o '/shared/out.olpak'"), std::string::npos) << s.merge;
    EXPECT_NE(s.submit.find("--array=0-3"), std::string::npos) << s.submit;
    EXPECT_NE(s.submit.find("--dependency=afterok:$array --kill-on-invalid-dep=yes"),
              std::string::npos)
        << s.submit;
    EXPECT_EQ(shellQuoted("it's"), "'it'\\''s'");
}

TEST(SlurmWorkFolder, ManifestRoundTripsAndNamesWhatChanged) {
    const TempFolder folder("manifest");
    const WorkFolder work{folder.path.string()};
    makeWorkFolder(work);
    EXPECT_FALSE(readManifest(work).has_value());
    const Manifest m = testManifest();
    writeManifest(work, m);
    const std::optional<Manifest> read = readManifest(work);
    ASSERT_TRUE(read.has_value());
    EXPECT_TRUE(sameBake(*read, m));
    EXPECT_EQ(read->settingsHash(), m.settingsHash());

    Manifest edited = m;
    edited.levelHash = 0x5678;
    EXPECT_FALSE(sameBake(m, edited));
    EXPECT_NE(describeChange(m, edited).find("content changed"), std::string::npos);
    Manifest other = m;
    other.bakeArguments = {"--quality", "high"};
    EXPECT_NE(describeChange(m, other).find("settings changed"), std::string::npos);
    EXPECT_NE(m.settingsHash(), other.settingsHash());
    other = m;
    other.shardCount = 8;
    EXPECT_NE(m.settingsHash(), other.settingsHash());

    writeText(work.manifest(), "{\"format\": \"something else\"}");
    const std::string error = test::errorMessage([&] { (void)readManifest(work); });
    EXPECT_NE(error.find(work.manifest()), std::string::npos) << error;
}

TEST(SlurmWorkFolder, AShardVerifiesOnlyWithItsPackageLevelAndSettings) {
    const TempFolder folder("stamp");
    const WorkFolder work{folder.path.string()};
    makeWorkFolder(work);
    const Manifest m = testManifest();
    EXPECT_FALSE(verifiedShard(work, m, 1).has_value());  // nothing baked
    writeText(work.shardPackage(1), "part one of four");
    writeShardStamp(work, m, 1, "node7", 2.5);
    const std::optional<ShardStamp> stamp = verifiedShard(work, m, 1);
    ASSERT_TRUE(stamp.has_value());
    EXPECT_EQ(stamp->node, "node7");
    EXPECT_DOUBLE_EQ(stamp->seconds, 2.5);
    EXPECT_FALSE(verifiedShard(work, m, 2).has_value());  // another shard's stamp is not this

    Manifest edited = m;
    edited.levelHash = 0x9999;
    EXPECT_FALSE(verifiedShard(work, edited, 1).has_value());
    Manifest other = m;
    other.bakeArguments = {"--quality", "high"};
    EXPECT_FALSE(verifiedShard(work, other, 1).has_value());

    writeText(work.shardPackage(1), "part One of four");  // same size, other bytes
    EXPECT_FALSE(verifiedShard(work, m, 1).has_value());
    writeText(work.shardPackage(1), "part one of four");
    EXPECT_TRUE(verifiedShard(work, m, 1).has_value());
    writeText(work.shardStamp(1), "{ not json");
    EXPECT_FALSE(verifiedShard(work, m, 1).has_value());
}

TEST(SlurmContentHash, DependsOnEveryByteAndTheOrderOfFiles) {
    const TempFolder temp("hash");
    const std::filesystem::path& folder = temp.path;
    writeText((folder / "a").string(), "abc");
    writeText((folder / "b").string(), "abd");
    const uint64_t ab = hashFiles({(folder / "a").string(), (folder / "b").string()});
    EXPECT_NE(ab, hashFiles({(folder / "b").string(), (folder / "a").string()}));
    EXPECT_NE(hashText("abc"), hashText("abd"));
    EXPECT_EQ(hashHex(0xab), "00000000000000ab");
    const std::string error = test::errorMessage([&] { (void)hashFiles({"/no/such/level.gltf"}); });
    EXPECT_NE(error.find("/no/such/level.gltf"), std::string::npos) << error;
    // Any one bit flipped anywhere in a file of three megabytes and a bit (it is read a
    // megabyte at a time, eight bytes at a step): the top bit of a word, a byte at a chunk's
    // edge, the loose bytes at the end.
    std::vector<uint8_t> big(3 * (1 << 20) + 5);
    for (size_t i = 0; i < big.size(); ++i) big[i] = uint8_t(i * 131u >> 3);
    const std::string path = (folder / "big").string();
    auto hashOf = [&](const std::vector<uint8_t>& bytes) {
        std::FILE* file = std::fopen(path.c_str(), "wb");
        std::fwrite(bytes.data(), 1, bytes.size(), file);
        std::fclose(file);
        return hashFiles({path});
    };
    const uint64_t original = hashOf(big);
    EXPECT_EQ(original, hashOf(big));
    for (const auto& [at, bit] : {std::pair<size_t, int>{7, 7},
                                  {8, 0},
                                  {(1 << 20) - 1, 7},
                                  {1 << 20, 0},
                                  {2 * (1 << 20) + 15, 7},
                                  {big.size() - 1, 3}}) {
        std::vector<uint8_t> changed = big;
        changed[at] ^= uint8_t(1u << bit);
        EXPECT_NE(hashOf(changed), original) << "byte " << at << " bit " << bit;
    }
    // One byte longer, with the same leading bytes.
    std::vector<uint8_t> longer = big;
    longer.push_back(0);
    EXPECT_NE(hashOf(longer), original);
    // Not a regular file: refused by name, never read.
    const std::string dir = test::errorMessage([&] { (void)hashFiles({folder.string()}); });
    EXPECT_NE(dir.find(folder.string()), std::string::npos) << dir;
}

TEST(SlurmScheduler, ACommandThatDoesNotAnswerIsKilledInTime) {
    const auto start = std::chrono::steady_clock::now();
    const std::string error = test::errorMessage([] {
        (void)runSchedulerCommand({"sleep", "30"}, 0.5);
    });
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_NE(error.find("sleep: no answer within"), std::string::npos) << error;
    EXPECT_LT(seconds, 5.0);
}

TEST(SlurmScheduler, CapturesOutputAndExitCodeAndNamesAMissingCommand) {
    const world::ChildResult r =
        runSchedulerCommand({"sh", "-c", "echo out; echo err >&2; exit 3"}, 10.0);
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_EQ(r.out, "out\n");
    EXPECT_EQ(r.err, "err\n");
    const std::string error =
        test::errorMessage([] { (void)runSchedulerCommand({"no-such-sbatch-here"}, 10.0); });
    EXPECT_NE(error.find("no-such-sbatch-here: cannot run it"), std::string::npos) << error;
    EXPECT_NE(error.find("slurm-client"), std::string::npos) << error;
}

}  // namespace
}  // namespace onelight::bake::slurm
