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
    for (const std::string command : {"compile", "reference", "merge", "level.gltf"}) {
        const onelight::test::CommandResult r =
            onelight::test::runCommand(kBake + " " + command + " --help");
        EXPECT_EQ(r.exitCode, 0) << command << ": " << r.output;
        EXPECT_EQ(r.output.rfind("usage: onelight-bake", 0), 0u) << command << ": " << r.output;
    }
}

TEST(BakeCommandLine, AnUnknownOptionStillFailsWithTheUsage) {
    const onelight::test::CommandResult r = onelight::test::runCommand(kBake + " compile --nope");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("unexpected argument '--nope'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("usage: onelight-bake compile"), std::string::npos) << r.output;
}
