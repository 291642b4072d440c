// Frame-capture tests: the demo level's replays played by the `onelight` executable, headless on
// lavapipe with the validation layer on, every capture compared with its golden
// (tests/support/golden.hpp states the tolerance; a failure writes NAME_diff.png). The scripts'
// expect lines are checked by the replay itself: a failed one makes `onelight` exit 1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "golden.hpp"
#include "run_command.hpp"
#include "world/images/image_decode.hpp"
#include "world/images/image_files.hpp"

namespace {

namespace fs = std::filesystem;

using onelight::test::CommandResult;

CommandResult runOnelight(const std::string& arguments) {
    return onelight::test::runCommand(std::string(ONELIGHT_EXE) + " " + arguments);
}

std::string outputDir(const std::string& name) {
    fs::path dir = fs::path(ONELIGHT_TEST_OUTPUT) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
}

// Plays game/replays/NAME.replay at 320x180 into a fresh folder (named `folder`, default NAME);
// returns the folder.
std::string playReplay(const std::string& name, const std::string& folder = "") {
    std::string dir = outputDir(folder.empty() ? name : folder);
    CommandResult r =
        runOnelight(std::string(ONELIGHT_DEMO_PACKAGE) + " --replay " + ONELIGHT_REPLAYS + "/" +
                    name + ".replay --headless --size 320x180 --capture-dir " + dir);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return dir;
}

// Each capture in `dir` against golden/PREFIX_CAPTURE.png, a diff image beside it on failure.
void expectCapturesMatchGoldens(const std::string& dir, const std::string& prefix,
                                const std::vector<std::string>& captures) {
    for (const std::string& c : captures) {
        const onelight::world::DecodedImage png =
            onelight::world::readImageFile(dir + "/" + c + ".png");
        onelight::test::GoldenResult g = onelight::test::compareWithGolden(
            png.rgba, png.width, png.height,
            std::string(ONELIGHT_GAME_GOLDENS) + "/" + prefix + "_" + c + ".png",
            dir + "/" + c + "_diff.png");
        EXPECT_TRUE(g.ok) << g.message;
    }
}

// The OpenArena pk3s the Quake 3 replays need; empty when installed, else what is missing.
std::string missingOpenArena() {
    const std::string game = "/usr/share/games/openarena/baseoa/";
    for (const char* pk3 : {"pak0.pk3", "pak1-maps.pk3", "pak4-textures.pk3"})
        if (!fs::exists(game + pk3))
            return game + pk3 +
                   " is missing: install openarena-data, openarena-081-maps and "
                   "openarena-081-textures";
    return "";
}

// Every capture of the replay (not the contact sheet) against golden/REPLAY_CAPTURE.png.
void expectGoldens(const std::string& replay, const std::vector<std::string>& captures) {
    std::string dir = playReplay(replay);
    for (const std::string& c : captures) {
        ASSERT_TRUE(fs::exists(dir + "/" + c + ".exr")) << c;
        ASSERT_TRUE(fs::exists(dir + "/" + c + ".json")) << c;
    }
    expectCapturesMatchGoldens(dir, replay, captures);
    EXPECT_TRUE(fs::exists(dir + "/contact_sheet.png"));
}

// Mean linear luminance (cd/m^2) of the central quarter of a capture's EXR.
double centreLuminance(const std::string& exr) {
    const onelight::world::FloatImage image = onelight::world::readExrFile(exr);
    const uint32_t w = image.width, h = image.height;
    const std::vector<float>& rgba = image.rgba;
    double sum = 0.0;
    int count = 0;
    for (uint32_t y = h / 4; y < 3 * h / 4; ++y)
        for (uint32_t x = w / 4; x < 3 * w / 4; ++x, ++count) {
            const float* p = &rgba[(size_t(y) * w + x) * 4];
            sum += 0.2126 * double(p[0]) + 0.7152 * double(p[1]) + 0.0722 * double(p[2]);
        }
    return count ? sum / count : 0.0;
}

}  // namespace

TEST(DemoReplays, SunlitCourtyard) {
    expectGoldens("courtyard", {"courtyard", "courtyard_east"});
}

TEST(DemoReplays, SpotLitInterior) {
    expectGoldens("interior", {"interior"});
}

// The script expects crate_1's primary to be the sun in the yard and the spot in the room.
TEST(DemoReplays, MoverCrossesFromOnePrimaryToAnother) {
    expectGoldens("mover", {"crate_in_the_sun", "crate_under_the_spot"});
}

TEST(DemoReplays, FlashlightOnAndOff) {
    expectGoldens("flashlight", {"flashlight_off", "flashlight_on", "flashlight_off_again"});
    std::string dir = std::string(ONELIGHT_TEST_OUTPUT) + "/flashlight";
    double off = centreLuminance(dir + "/flashlight_off.exr");
    double on = centreLuminance(dir + "/flashlight_on.exr");
    double offAgain = centreLuminance(dir + "/flashlight_off_again.exr");
    EXPECT_GT(on, off * 1.01) << "the flashlight adds light where it points";
    EXPECT_NEAR(offAgain, off, off * 1e-6) << "off again is exactly off";
}

// The script expects 1, 2, 3, 4, then still 4 effect lights after five shots on five ticks.
TEST(DemoReplays, FiveShotsNeverMoreThanFourFlashes) {
    expectGoldens("shots", {"four_flashes", "flashes_gone"});
}

TEST(DemoReplays, GlossyReflection) {
    expectGoldens("glossy", {"glossy_floor"});
}

TEST(DemoReplays, TheSameReplayGivesTheSameFrames) {
    std::string first = playReplay("mover", "mover_first_run");
    std::string second = playReplay("mover", "mover_second_run");
    for (const char* c : {"crate_in_the_sun", "crate_under_the_spot"}) {
        const std::vector<uint8_t> a =
            onelight::world::readImageFile(first + "/" + c + ".png").rgba;
        const std::vector<uint8_t> b =
            onelight::world::readImageFile(second + "/" + c + ".png").rgba;
        EXPECT_TRUE(a == b) << c << " differs between two runs of the same replay";
    }
}

// --benchmark REPLAY draws every tick of the replay (the mover script: every tick to its quit at
// 4 s) and prints one line of key=value pairs; it writes no captures. Checked: the frame count
// is the ticks drawn, the times are positive and finite, the 95th percentile is not below the
// median, and the GPU time is not above the wall time a frame took.
TEST(DemoReplays, TheBenchmarkPrintsFrameTimesAScriptCanRead) {
    const std::string dir = outputDir("benchmark");
    const CommandResult r =
        runOnelight(std::string(ONELIGHT_DEMO_PACKAGE) + " --benchmark " + ONELIGHT_REPLAYS +
                    "/mover.replay --headless --size 64x36 --capture-dir " + dir);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const size_t at = r.output.find("onelight-benchmark ");
    ASSERT_NE(at, std::string::npos) << r.output;
    std::map<std::string, std::string> values;
    std::istringstream line(r.output.substr(at, r.output.find('\n', at) - at));
    for (std::string pair; line >> pair;)
        if (const size_t eq = pair.find('='); eq != std::string::npos)
            values[pair.substr(0, eq)] = pair.substr(eq + 1);
    for (const char* key : {"frames", "median_ms", "p95_ms", "gpu_median_ms", "gpu_p95_ms", "fps"})
        ASSERT_TRUE(values.count(key)) << key << " missing in: " << r.output;
    const int frames = std::stoi(values["frames"]);
    const double median = std::stod(values["median_ms"]), p95 = std::stod(values["p95_ms"]);
    const double gpu = std::stod(values["gpu_median_ms"]);
    EXPECT_GT(frames, 100);
    EXPECT_TRUE(std::isfinite(median) && median > 0.0);
    EXPECT_GE(p95, median);
    EXPECT_GT(gpu, 0.0);
    EXPECT_LE(gpu, p95);
    EXPECT_EQ(values["width"], "64");
    EXPECT_TRUE(fs::is_empty(dir)) << "a benchmark writes no captures";
}

// The game keeps its pipeline cache in $XDG_CACHE_HOME/onelight/pipelines.bin; a file that is not
// one (garbage, another device's) is not an error: the run makes its pipelines afresh and writes
// a cache of its own over it.
TEST(DemoReplays, TheGameKeepsItsPipelineCacheWhereXdgCacheHomeSays) {
    const std::string cache = outputDir("pipeline_cache");
    const fs::path file = fs::path(cache) / "onelight" / "pipelines.bin";
    // Mesa's own shader cache stays where ctest put it (its mesa_shader_cache under the suite's
    // XDG_CACHE_HOME): without it, both runs compile every shader afresh (28 s against 7 s on
    // lavapipe), which is Mesa's cache and not the game's.
    const char* suiteCache = std::getenv("XDG_CACHE_HOME");
    const std::string mesa =
        suiteCache ? std::string(" MESA_SHADER_CACHE_DIR=") + suiteCache : std::string();
    const std::string run = "env XDG_CACHE_HOME=" + cache + mesa + " " + std::string(ONELIGHT_EXE) +
                            " " + ONELIGHT_DEMO_PACKAGE + " --headless --size 64x36";
    const auto headerLength = [&] {
        std::ifstream in(file, std::ios::binary);
        uint32_t length = 0;
        in.read(reinterpret_cast<char*>(&length), sizeof(length));
        return in ? length : 0u;
    };
    CommandResult r = onelight::test::runCommand(run);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ASSERT_TRUE(fs::is_regular_file(file));
    EXPECT_GE(fs::file_size(file), 32u);  // at least VkPipelineCacheHeaderVersionOne
    EXPECT_EQ(headerLength(), 32u);
    {
        std::ofstream garbage(file, std::ios::binary | std::ios::trunc);
        garbage << std::string(100, 'x');
    }
    r = onelight::test::runCommand(run);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(headerLength(), 32u) << "the garbage was not replaced by this device's cache";
}

// Bad replays: one line `onelight: FILE:LINE: what was expected`, exit 1.
TEST(DemoReplays, BadScriptsGiveOneClearLineAndExitOne) {
    std::string dir = outputDir("bad_scripts");
    struct {
        const char* name;
        const char* text;
        const char* mustSay;
    } cases[] = {
        {"unknown_command", "level demo\nat 1 dance\n", ":2: unknown command 'dance'"},
        {"bad_number", "at 1.x fire\n", ":1: expected a time in seconds (a number), found '1.x'"},
        {"time_backwards", "at 2 fire\nat 1 fire\n", ":2: time 1 goes backwards"},
        {"unknown_entity", "at 1 expect primary crate_9 == sun\n", ":1: unknown entity 'crate_9'"},
        {"unknown_light", "at 1 expect primary crate_1 == moon\n", ":1: unknown light 'moon'"},
    };
    for (auto& c : cases) {
        std::string script = dir + "/" + c.name + ".replay";
        std::ofstream(script) << c.text;
        CommandResult r = runOnelight(std::string(ONELIGHT_DEMO_PACKAGE) + " --replay " + script +
                                      " --headless --capture-dir " + dir);
        EXPECT_EQ(r.exitCode, 1) << c.name << "\n" << r.output;
        EXPECT_NE(r.output.find("onelight: " + script + c.mustSay), std::string::npos)
            << c.name << "\n"
            << r.output;
    }
    CommandResult missing =
        runOnelight(dir + "/no_such_level.olpak --replay " + dir + "/bad_number.replay --headless");
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.output.find("onelight: " + dir + "/no_such_level.olpak: no such file"),
              std::string::npos)
        << missing.output;
}

// A Quake 3 map, imported, compiled and baked at draft quality by onelight-bake, then played: the
// replay walks the map on its own collision (its expect lines) and its captures match goldens.
TEST(Quake3Replay, Q3dm6ishBakesAndPlays) {
    if (const std::string missing = missingOpenArena(); !missing.empty()) GTEST_SKIP() << missing;
    const std::string dir = outputDir("q3dm6ish");
    const std::string package = dir + "/q3dm6ish.olpak";
    // The map's own visible set (q3map2's) in place of the sampled one: the frames do not depend
    // on the set (RenderBaked.CullingByTheVisibleSetChangesNoPixel), and sampling it is 19 of the
    // draft bake's 31 s (the sampled set's own tests: tests/bake/visibility_test.cpp).
    CommandResult bake = onelight::test::runCommand(
        std::string(ONELIGHT_BAKE_EXE) + " q3dm6ish --quality draft --own-visibility --quiet -o " +
        package);
    ASSERT_EQ(bake.exitCode, 0) << bake.output;
    CommandResult play =
        runOnelight(package + " --replay " + ONELIGHT_REPLAYS +
                    "/q3dm6ish.replay --headless --size 320x180 --capture-dir " + dir);
    ASSERT_EQ(play.exitCode, 0) << play.output;
    expectCapturesMatchGoldens(dir, "q3dm6ish", {"start", "walked", "back"});
    // The map's own q3map2 lightmaps from the first spawn, at a fixed exposure (--view q3map2).
    CommandResult view = runOnelight(package +
                                     " --headless --camera spawn0 --size 320x180 --ev100 4 "
                                     "--view q3map2 --capture " +
                                     dir + "/q3map2_spawn0");
    ASSERT_EQ(view.exitCode, 0) << view.output;
    const onelight::world::DecodedImage png =
        onelight::world::readImageFile(dir + "/q3map2_spawn0.png");
    onelight::test::GoldenResult g = onelight::test::compareWithGolden(
        png.rgba, png.width, png.height,
        std::string(ONELIGHT_GAME_GOLDENS) + "/q3dm6ish_q3map2_spawn0.png",
        dir + "/q3map2_spawn0_diff.png");
    EXPECT_TRUE(g.ok) << g.message;
}

namespace {

// Installed map MAP compiled (not baked: seconds instead of minutes; its frames show the
// primaries alone, which is what the goldens hold), then game/replays/MAP.replay played headless
// at 320x180: its expect lines must hold and its captures match golden/MAP_CAPTURE.png.
void expectCompiledMapReplay(const std::string& map, const std::vector<std::string>& captures) {
    const std::string dir = outputDir(map);
    const std::string package = dir + "/" + map + ".olpak";
    CommandResult compile = onelight::test::runCommand(std::string(ONELIGHT_BAKE_EXE) +
                                                       " compile " + map + " -o " + package);
    ASSERT_EQ(compile.exitCode, 0) << compile.output;
    CommandResult play = runOnelight(package + " --replay " + ONELIGHT_REPLAYS + "/" + map +
                                     ".replay --headless --size 320x180 --capture-dir " + dir);
    ASSERT_EQ(play.exitCode, 0) << play.output;
    expectCapturesMatchGoldens(dir, map, captures);
}

}  // namespace

// OpenArena's kaos as `./play` plays it headless (game/replays/kaos.replay): the map's own
// teleporter and jump pad, checked by the replay's expect lines on its imported brushes.
TEST(Quake3Replay, KaosTeleportsAndJumpsAsQuake3Does) {
    if (const std::string missing = missingOpenArena(); !missing.empty()) GTEST_SKIP() << missing;
    expectCompiledMapReplay("kaos", {"start", "teleported", "apex", "landed"});
}

// OpenArena's oa_dm2 with its movers (game/replays/oa_dm2.replay): the player takes an armour,
// then rides the map's plat up as its trigger raises it, checked by the replay's expect lines.
TEST(Quake3Replay, OaDm2TakesAnArmourAndRidesThePlatUp) {
    if (const std::string missing = missingOpenArena(); !missing.empty()) GTEST_SKIP() << missing;
    expectCompiledMapReplay("oa_dm2", {"start", "plat", "up"});
}

// A package that does not come from a Quake 3 map has no q3map2 lightmaps to show.
TEST(Quake3Replay, TheQ3map2ViewOfAnotherLevelIsRefused) {
    CommandResult r =
        runOnelight(std::string(ONELIGHT_DEMO_PACKAGE) + " --headless --size 32x18 --view q3map2");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("no q3map2 lightmaps"), std::string::npos) << r.output;
}
