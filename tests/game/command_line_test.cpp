// onelight's help: -h and --help print the usage on stdout and exit 0, listing every option
// with its default, before any level is looked for.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "run_command.hpp"

namespace {
const std::string kOnelight = ONELIGHT_EXE;
}  // namespace

TEST(GameCommandLine, HelpExitsZeroAndListsEveryOptionWithItsDefault) {
    for (const char* ask : {"--help", "-h", "no_such_level.gltf --help"}) {
        const onelight::test::CommandResult r = onelight::test::runCommand(kOnelight + " " + ask);
        EXPECT_EQ(r.exitCode, 0) << ask << ": " << r.output;
        EXPECT_EQ(r.output.rfind("usage: onelight LEVEL", 0), 0u) << r.output;
        for (const char* flag :
             {"--headless", "--size WxH", "--camera", "--capture out/NAME", "--msaa N",
              "--frames N", "--flashlight", "--replay SCRIPT", "--capture-dir DIR", "--free-fly",
              "--view onelight|q3map2", "--ev100 EV", "--shadow-map-size N", "--shadow-distance M",
              "--no-probes"}) {
            const size_t at = r.output.find(std::string("\n  ") + flag);
            ASSERT_NE(at, std::string::npos) << flag << " is not listed\n" << r.output;
            const size_t next = r.output.find("\n  -", at + 1);
            EXPECT_NE(r.output.substr(at, next - at).find("default: "), std::string::npos)
                << flag << " has no default\n"
                << r.output;
        }
        EXPECT_NE(r.output.find("(default: 1280x720)"), std::string::npos) << r.output;
    }
}

TEST(GameCommandLine, AnUnknownOptionFailsAndPointsToTheHelp) {
    const onelight::test::CommandResult r = onelight::test::runCommand(kOnelight + " --nope");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("unexpected argument '--nope'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("onelight --help"), std::string::npos) << r.output;
}

TEST(GameCommandLine, AQualityOtherThanTheBakersIsNamed) {
    const onelight::test::CommandResult r =
        onelight::test::runCommand(kOnelight + " level.gltf --quality best");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("--quality 'best': expected draft, default or high"), std::string::npos)
        << r.output;
}

TEST(GameCommandLine, AViewOrExposureOutOfRangeIsNamed) {
    for (const auto& [arguments, expected] :
         {std::pair<std::string, std::string>{"x.olpak --view radiant",
                                              "--view 'radiant': expected onelight or q3map2"},
          {"x.olpak --ev100 99", "--ev100 '99': expected a number in [-10, 30]"},
          {"x.olpak --ev100 nan", "--ev100 'nan': expected a number in [-10, 30]"},
          {"x.olpak --shadow-map-size 32",
           "--shadow-map-size '32': expected an integer in [64, 8192]"},
          {"x.olpak --shadow-map-size 1k",
           "--shadow-map-size '1k': expected an integer in [64, 8192]"},
          {"x.olpak --shadow-distance 0.5",
           "--shadow-distance '0.5': expected metres, a number in [1, 10000]"},
          {"x.olpak --shadow-distance inf",
           "--shadow-distance 'inf': expected metres, a number in [1, 10000]"}}) {
        const onelight::test::CommandResult r =
            onelight::test::runCommand(kOnelight + " " + arguments);
        EXPECT_EQ(r.exitCode, 1) << r.output;
        EXPECT_NE(r.output.find(expected), std::string::npos) << r.output;
    }
}

// Every value is taken whole and in range; a missing value at the end and a combination that
// cannot work are named too.
TEST(GameCommandLine, JunkValuesAndConflictsAreNamed) {
    for (const auto& [arguments, expected] : std::vector<std::pair<std::string, std::string>>{
             {"x.olpak --size 0x5", "--size '0x5': expected WxH, each an integer in [1, 16384]"},
             {"x.olpak --size 640x480x", "--size '640x480x': expected WxH"},
             {"x.olpak --msaa 2x", "--msaa '2x': expected an integer in [1, 64]"},
             {"x.olpak --frames 1e3", "--frames '1e3': expected a count of frames"},
             {"x.olpak --frames -5", "--frames '-5': expected a count of frames"},
             {"x.olpak --render-scale nan", "--render-scale 'nan': expected a number in [0.25, 1]"},
             {"x.olpak --frames", "--frames needs a value"},
             {"x.olpak --benchmark a.replay --replay b.replay", "--benchmark with --replay"},
             {"x.olpak --headless --render-scale 0.5", "--render-scale applies to the window"},
             {"x.olpak y.olpak", "unexpected argument 'y.olpak'"},
             {"--headless", "no level given"}}) {
        const onelight::test::CommandResult r =
            onelight::test::runCommand(kOnelight + " " + arguments);
        EXPECT_EQ(r.exitCode, 1) << arguments << "\n" << r.output;
        EXPECT_NE(r.output.find(expected), std::string::npos) << arguments << "\n" << r.output;
    }
}
