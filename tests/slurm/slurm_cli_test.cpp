// onelight-bake --slurm's bad input: each gets a one-line error naming the argument and what
// was expected, and a non-zero exit, before anything is submitted (no cluster needed).
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "run_command.hpp"
#include "tests/world/world_test_support.hpp"

namespace {

const std::string kBake = ONELIGHT_BAKE_EXE;

onelight::test::CommandResult bake(const std::string& arguments) {
    return onelight::test::runCommand(kBake + " " + arguments);
}

std::string level() {
    static const std::string path = onelight::test::writeTwoLampFloor("slurm-cli", 2, 4.0, true);
    return path;
}

void expectRefused(const std::string& arguments, int exitCode, const std::string& expected) {
    const onelight::test::CommandResult r = bake(arguments);
    EXPECT_EQ(r.exitCode, exitCode) << arguments << "\n" << r.output;
    EXPECT_NE(r.output.find(expected), std::string::npos) << arguments << "\n" << r.output;
}

TEST(SlurmCommandLine, ShardCountMustBeAPositiveInteger) {
    const std::string out = " -o " + level() + ".olpak";
    expectRefused(level() + out + " --slurm 0", 2,
                  "--slurm '0': expected a number of shards in [1, 10000]");
    expectRefused(level() + out + " --slurm 2.5", 2, "--slurm '2.5': expected");
    expectRefused(level() + out + " --slurm many", 2, "--slurm 'many': expected");
    expectRefused(level() + out + " --slurm", 2, "--slurm needs a value");
}

TEST(SlurmCommandLine, JobOptionsAreChecked) {
    const std::string base = level() + " -o " + level() + ".olpak --slurm 2";
    expectRefused(base + " --time soon", 2, "--time 'soon': expected a Slurm time limit");
    expectRefused(base + " --cpus-per-task 0", 2,
                  "--cpus-per-task '0': expected an integer in [1, 1024]");
    expectRefused(base + " --retries -1", 2, "--retries '-1': expected an integer in [0, 100]");
    expectRefused(base + " --partition", 2, "--partition needs a value");
    expectRefused(base + " --shard 0/2", 2, "--shard with --slurm");
    expectRefused(base + " --quality best", 2, "--quality 'best': expected draft");
}

// A bake whose options a shard cannot take is refused at submission: nothing imported, no work
// folder made, nothing compiled or submitted (sbatch is not even looked for).
TEST(SlurmCommandLine, AnErrorBudgetIsRefusedBeforeAnythingIsSubmitted) {
    const std::filesystem::path folder = onelight::test::freshFolder("slurm-budget");
    const std::string base = level() + " -o " + (folder / "out.olpak").string() +
                             " --slurm 2 --work " + (folder / "work").string();
    expectRefused(base + " --error-budget 5%", 2, "--error-budget with --slurm");
    expectRefused(base + " --retries 1 --emit-scripts " + (folder / "s").string(), 2,
                  "--retries with --emit-scripts");
    EXPECT_FALSE(std::filesystem::exists(folder / "work"));
    EXPECT_FALSE(std::filesystem::exists(folder / "s"));
    expectRefused(level() + " --partition bake", 2, "--partition is an option of the Slurm bake");
}

TEST(SlurmCommandLine, MissingSbatchIsNamed) {
    const onelight::test::CommandResult r = onelight::test::runCommand(
        "env PATH=/nonexistent " + kBake + " " + level() + " -o " + level() + ".olpak --slurm 2");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("sbatch: not found on PATH"), std::string::npos) << r.output;
}

TEST(SlurmCommandLine, AMissingLevelIsNamedBeforeAnythingIsSubmitted) {
    const onelight::test::CommandResult r =
        onelight::test::runCommand("env PATH=/nonexistent " + kBake +
                                   " /no/such/level.gltf -o /tmp/x.olpak --slurm 2 --emit-scripts "
                                   "/tmp/onelight-never-written");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("/no/such/level.gltf"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists("/tmp/onelight-never-written"));
}

TEST(SlurmCommandLine, HelpListsEveryOption) {
    const onelight::test::CommandResult r = bake("level.gltf --slurm 1 --help");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    for (const char* option : {"--slurm N", "--partition P", "--time T", "--cpus-per-task C",
                               "--work DIR", "--retries K", "--no-wait", "--emit-scripts DIR"}) {
        const size_t at = r.output.find(std::string("  ") + option);
        ASSERT_NE(at, std::string::npos) << option << "\n" << r.output;
        const std::string line = r.output.substr(at, r.output.find('\n', at) - at);
        EXPECT_TRUE(line.find("(default: ") != std::string::npos ||
                    line.find("(required)") != std::string::npos)
            << line;
    }
    const onelight::test::CommandResult task = bake("slurm-task --help");
    EXPECT_EQ(task.exitCode, 0) << task.output;
}

TEST(SlurmCommandLine, TheTaskRefusesAFolderWithoutManifest) {
    const std::filesystem::path folder = onelight::test::freshFolder("slurm-no-manifest");
    expectRefused("slurm-task --work " + folder.string() + " --shard 0", 1,
                  (folder / "manifest.json").string() + ": missing");
    expectRefused("slurm-task --work " + folder.string(), 2,
                  "expected one of --shard I and --merge");
}

TEST(SlurmCommandLine, EmittedScriptsSubmitTheArrayThenTheMerge) {
    const std::filesystem::path folder = onelight::test::freshFolder("slurm-emit");
    const onelight::test::CommandResult r =
        onelight::test::runCommand("env PATH=/nonexistent " + kBake + " " + level() + " -o " +
                                   (folder / "out.olpak").string() + " --slurm 3 --quality draft " +
                                   "--work " + (folder / "work").string() + " --emit-scripts " +
                                   (folder / "scripts").string() + " --partition bake");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* name : {"shard.sh", "merge.sh", "submit.sh"})
        EXPECT_TRUE(std::filesystem::exists(folder / "scripts" / name)) << name;
    EXPECT_TRUE(std::filesystem::exists(folder / "work" / "manifest.json"));
    EXPECT_TRUE(std::filesystem::exists(folder / "work" / "compiled.olpak"));
    EXPECT_FALSE(std::filesystem::exists(folder / "out.olpak"));
}

std::string fileText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The tasks run by hand, as a user who submits the emitted scripts would, without Slurm: the
// level compiled once by the command, each shard baked from it, the merge equal to a local bake
// byte for byte. A compiled level that no longer verifies fails the shard, named.
TEST(SlurmCommandLine, ShardsRunByHandBakeTheCompiledLevelAndMergeToTheLocalBake) {
    namespace fs = std::filesystem;
    const fs::path folder = onelight::test::freshFolder("slurm-by-hand");
    const std::string work = (folder / "work").string(), out = (folder / "out.olpak").string();
    const onelight::test::CommandResult emitted =
        onelight::test::runCommand("env PATH=/nonexistent " + kBake + " " + level() + " -o " + out +
                                   " --slurm 3 --quality draft --quiet --work " + work +
                                   " --emit-scripts " + (folder / "scripts").string());
    ASSERT_EQ(emitted.exitCode, 0) << emitted.output;
    EXPECT_NE(emitted.output.find("compiled the level once"), std::string::npos) << emitted.output;
    for (int shard : {2, 0, 1}) {
        const onelight::test::CommandResult r =
            bake("slurm-task --work " + work + " --shard " + std::to_string(shard));
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    const onelight::test::CommandResult merged =
        bake("slurm-task --work " + work + " --merge -o " + out);
    ASSERT_EQ(merged.exitCode, 0) << merged.output;
    const std::string local = (folder / "local.olpak").string();
    ASSERT_EQ(bake(level() + " -o " + local + " --quality draft --quiet").exitCode, 0);
    EXPECT_TRUE(fileText(out) == fileText(local)) << "the merged package differs";

    // A manifest edited to name another level, which does not parse: the error names the
    // manifest as well as the level.
    {
        const std::string manifestPath = work + "/manifest.json";
        const std::string original = fileText(manifestPath);
        std::string edited = original;
        const std::string broken = (folder / "broken.gltf").string();
        std::ofstream(broken) << "{ not json";
        const size_t at = edited.find(level());
        ASSERT_NE(at, std::string::npos) << edited;
        edited.replace(at, level().size(), broken);
        std::ofstream(manifestPath, std::ios::trunc) << edited;
        const onelight::test::CommandResult r = bake("slurm-task --work " + work + " --shard 1");
        EXPECT_NE(r.exitCode, 0);
        EXPECT_NE(r.output.find("broken.gltf"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("(as " + manifestPath + " names it)"), std::string::npos)
            << r.output;
        std::ofstream(manifestPath, std::ios::trunc) << original;
    }

    // A compiled level changed after its stamp: the shard refuses it.
    {
        std::fstream file(folder / "work" / "compiled.olpak",
                          std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(200);
        file.put('\x5a');
    }
    expectRefused("slurm-task --work " + work + " --shard 1", 1,
                  work + "/compiled.olpak: missing or does not verify");
}

}  // namespace
