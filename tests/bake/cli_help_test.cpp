// onelight-bake's help: -h and --help print every command's usage on stdout and exit 0, and each
// option the commands parse is listed with its default.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "run_command.hpp"

namespace {

const std::string kBake = ONELIGHT_BAKE_EXE;

// The line of `help` that lists `flag`, or "" when none does.
std::string lineOf(const std::string& help, const std::string& flag) {
    size_t at = 0;
    while ((at = help.find("  " + flag, at)) != std::string::npos) {
        const size_t end = help.find('\n', at);
        const std::string line = help.substr(at, end - at);
        if (line.size() > flag.size() + 2 && line[flag.size() + 2] == ' ') return line;
        at = end;
    }
    return "";
}

}  // namespace

TEST(BakeCommandLine, HelpExitsZeroAndListsEveryOptionWithItsDefault) {
    for (const char* ask : {"--help", "-h"}) {
        const onelight::test::CommandResult r = onelight::test::runCommand(kBake + " " + ask);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        for (const char* command : {"onelight-bake LEVEL", "onelight-bake compile",
                                    "onelight-bake reference", "onelight-bake merge"})
            EXPECT_NE(r.output.find(std::string("usage: ") + command), std::string::npos)
                << command << "\n"
                << r.output;
        for (const char* flag :
             {"--quality Q", "--threads N", "--report PATH", "--shard i/N", "--sky CD_PER_M2",
              "--grid-cell M", "--texels-per-metre N", "--quiet", "--atlas-size N", "--camera NAME",
              "--spp N", "--size WxH", "-o PATH", "--patch-level N"}) {
            const std::string line = lineOf(r.output, flag);
            EXPECT_NE(line, "") << flag << " is not listed\n" << r.output;
            EXPECT_TRUE(line.find("(default: ") != std::string::npos ||
                        line.find("(required)") != std::string::npos)
                << line;
        }
        EXPECT_NE(lineOf(r.output, "--quality Q").find("(default: default)"), std::string::npos);
    }
}

TEST(BakeCommandLine, EverySubcommandTakesHelp) {
    for (const std::string command : {"compile", "reference", "merge", "export", "level.gltf"}) {
        const onelight::test::CommandResult r =
            onelight::test::runCommand(kBake + " " + command + " --help");
        EXPECT_EQ(r.exitCode, 0) << command << ": " << r.output;
        EXPECT_EQ(r.output.rfind("usage: onelight-bake", 0), 0u) << command << ": " << r.output;
    }
}

TEST(BakeCommandLine, AnUnknownOptionFailsWithOneLinePointingToTheHelp) {
    const onelight::test::CommandResult r = onelight::test::runCommand(kBake + " compile --nope");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_EQ(r.output,
              "onelight-bake: error: unexpected argument '--nope' (onelight-bake compile --help "
              "lists the options)\n");
}

// Every refusal: exit code 2 and one line naming the option, the value and what was expected,
// before any level is read (none of these levels exists).
TEST(BakeCommandLine, BadValuesAreRefusedNamingTheOption) {
    const std::string reference = "reference no_such.gltf --camera c -o out.exr ";
    for (const auto& [arguments, expected] : std::vector<std::pair<std::string, std::string>>{
             {reference + "--spp 12abc", "--spp '12abc': expected an integer in [1, 16777216]"},
             {reference + "--spp 0", "--spp '0': expected an integer in [1, 16777216]"},
             {reference + "--spp 1e3", "--spp '1e3': expected an integer"},
             {reference + "--spp 4 --threads -5",
              "--threads '-5': expected an integer in [1, 1024]"},
             {reference + "--spp 4 --size 640x", "--size '640x': expected WxH"},
             {reference + "--spp 4 --sky nan", "--sky 'nan': expected a number in [0, 1e+09]"},
             {reference + "--spp 4 --seed 4294967296", "--seed '4294967296': expected an integer"},
             {reference + "--spp", "--spp needs a value: expected an integer"},
             {"reference no_such.gltf -o out.exr --spp 4", "--camera NAME is required"},
             {"no_such.gltf --quality nonsense",
              "--quality 'nonsense': expected draft, default or high"},
             {"no_such.gltf --threads 0", "--threads '0': expected an integer in [1, 1024]"},
             {"no_such.gltf --texels-per-metre 16x", "--texels-per-metre '16x': expected a number"},
             {"no_such.gltf --error-budget 0", "--error-budget '0': expected a fraction in (0, 1]"},
             {"no_such.gltf --report", "--report needs a value"},
             {"no_such.gltf --nope", "unexpected argument '--nope'"},
             {"compile no_such.gltf --atlas-size 100.5",
              "--atlas-size '100.5': expected an integer"},
             {"merge -o out.olpak", "no part given"},
             {"export no_such.gltf", "-o PATH is required"},
             {"export no_such.gltf -o out.olpak",
              "-o 'out.olpak': expected a path ending in .gltf"},
             {"slurm-task --work /nonexistent --shard 1 --merge",
              "expected one of --shard I and --merge"},
             {"slurm-task --work /nonexistent --shard -1", "--shard '-1': expected an integer"}}) {
        const onelight::test::CommandResult r = onelight::test::runCommand(kBake + " " + arguments);
        EXPECT_EQ(r.exitCode, 2) << arguments << "\n" << r.output;
        EXPECT_EQ(r.output.rfind("onelight-bake: error: ", 0), 0u) << arguments << "\n" << r.output;
        EXPECT_NE(r.output.find(expected), std::string::npos) << arguments << "\n" << r.output;
        EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "one line\n" << r.output;
    }
}
