// Hostile use of the executables: outputs that name an input, shards that do not belong
// together, packages with a lying light grid, replays past their limits, and files that are not
// regular files. Each must exit non-zero with one clear line, lose no data, and never hang
// (every command runs under `timeout`).
#include <sys/stat.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "hostile_level.hpp"
#include "run_command.hpp"
#include "tests/world/package_patch.hpp"
#include "world/package/format.hpp"

namespace onelight::test {
namespace {

const std::string kBake = ONELIGHT_BAKE_EXE;
const std::string kOnelight = ONELIGHT_EXE;

std::string shellQuoted(const std::filesystem::path& p) {
    std::string text = p.string();
    text.insert(text.begin(), '\'');
    text.push_back('\'');
    return text;
}

// Runs with a time limit: exit code 124 means it hung.
CommandResult run(const std::string& commandLine) {
    return runCommand("timeout 120 " + commandLine);
}

std::vector<uint8_t> bytesOf(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

void expectFailure(const CommandResult& r, std::initializer_list<const char*> fragments) {
    EXPECT_NE(r.exitCode, 0) << r.output;
    EXPECT_NE(r.exitCode, 124) << "timed out: " << r.output;
    EXPECT_EQ(r.output.find("Segmentation"), std::string::npos) << r.output;
    for (const char* f : fragments) EXPECT_NE(r.output.find(f), std::string::npos) << r.output;
}

TEST(HostileCommandLine, NoCommandWritesOverItsInput) {
    const std::filesystem::path folder = hostileFolder("overwrite");
    const std::string gltf = writeTriangleLevel(folder);
    const std::vector<uint8_t> gltfBytes = bytesOf(gltf), binBytes = bytesOf(folder / "level.bin");
    std::filesystem::create_symlink(folder / "level.gltf", folder / "link.olpak");
    const std::string level = shellQuoted(gltf);
    for (const std::string& output :
         {shellQuoted(gltf), shellQuoted(folder / "level.bin"), shellQuoted(folder / "link.olpak"),
          shellQuoted(folder / "." / "level.bin")}) {
        for (const std::string& command :
             {kBake + " compile " + level + " -o " + output,
              kBake + " " + level + " --quality draft --quiet -o " + output,
              kBake + " reference " + level + " --camera view --spp 1 --size 8x8 -o " + output}) {
            SCOPED_TRACE(command);
            expectFailure(run(command), {"the output is the input", "nothing was written"});
        }
    }
    EXPECT_EQ(bytesOf(gltf), gltfBytes);
    EXPECT_EQ(bytesOf(folder / "level.bin"), binBytes);

    // merge: a part named as the output.
    const std::string part = shellQuoted(folder / "whole.olpak");
    ASSERT_EQ(run(kBake + " " + level + " --quality draft --quiet -o " + part).exitCode, 0);
    const std::vector<uint8_t> partBytes = bytesOf(folder / "whole.olpak");
    expectFailure(run(kBake + " merge " + part + " -o " + part), {"the output is the input"});
    EXPECT_EQ(bytesOf(folder / "whole.olpak"), partBytes);
}

TEST(HostileCommandLine, MergeNamesThePartThatDoesNotBelong) {
    const std::filesystem::path folder = hostileFolder("merge");
    const std::string level = shellQuoted(writeTriangleLevel(folder));
    const std::string a = shellQuoted(folder / "a.olpak"), b = shellQuoted(folder / "b.olpak");
    ASSERT_EQ(run(kBake + " " + level + " --quality draft --quiet --shard 0/2 -o " + a).exitCode,
              0);
    // The second shard with another grid: same counts, another origin and cell size.
    ASSERT_EQ(
        run(kBake + " " + level + " --quality draft --quiet --shard 1/2 --grid-cell 0.37 -o " + b)
            .exitCode,
        0);
    const CommandResult r =
        run(kBake + " merge " + a + " " + b + " -o " + shellQuoted(folder / "merged.olpak"));
    expectFailure(r, {"b.olpak", "shard 1/2"});
    EXPECT_FALSE(std::filesystem::exists(folder / "merged.olpak"));
    expectFailure(
        run(kBake + " merge " + a + " " + a + " -o " + shellQuoted(folder / "twice.olpak")),
        {"a.olpak", "is also"});
}

TEST(HostileCommandLine, APackageWithALyingGridIsRefusedNotACrash) {
    const std::filesystem::path folder = hostileFolder("grid");
    const std::string level = shellQuoted(writeTriangleLevel(folder));
    const std::filesystem::path package = folder / "level.olpak";
    ASSERT_EQ(
        run(kBake + " " + level + " --quality draft --quiet -o " + shellQuoted(package)).exitCode,
        0);
    std::vector<uint8_t> bytes = bytesOf(package);
    // dims 2^21 x 2^21 x 2^22: 2^64 cells, 0 after a 64-bit wrap, with valid CRCs.
    const package::SectionEntry grid = entry(bytes, package::kSectionLightGrid);
    const uint32_t dims[4] = {1u << 21, 1u << 21, 1u << 22, 0};
    std::memcpy(bytes.data() + grid.offset + offsetof(package::DiskLightGridHeader, dims), dims,
                sizeof dims);
    fixCrcs(bytes);
    const std::filesystem::path hostile = folder / "hostile.olpak";
    std::ofstream(hostile, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    expectFailure(run(kOnelight + " " + shellQuoted(hostile) + " --headless --size 32x32"),
                  {"hostile.olpak", "light_grid", "dims["});
    std::ofstream(folder / "one.replay") << "spawn player 0 1 2 yaw 0 pitch 0\nat 0.1 quit\n";
    expectFailure(run(kOnelight + " " + shellQuoted(hostile) +
                      " --headless --size 32x32 --replay " + shellQuoted(folder / "one.replay")),
                  {"hostile.olpak", "light_grid"});
}

TEST(HostileCommandLine, ReplaysPastTheirLimitsAndNonFilesEndQuickly) {
    const std::filesystem::path folder = hostileFolder("replay");
    const std::string level = shellQuoted(writeTriangleLevel(folder));
    const std::string package = shellQuoted(folder / "level.olpak");
    ASSERT_EQ(run(kBake + " compile " + level + " -o " + package).exitCode, 0);
    const std::pair<const char*, const char*> scripts[] = {
        {"at 1e15 quit\n", "expected at most 86400 s"},
        {"wait 1e300\nquit\n", "expected a script of at most 86400 s"},
        {"at 0 look 1e300 0\n", "from -36000 to 36000"},
        {"spawn player 1e30 0 0 yaw 0 pitch 0\n", "a coordinate in metres from -1e+06"}};
    int n = 0;
    for (const auto& [text, fragment] : scripts) {
        std::filesystem::path script = folder / "s";
        script += std::to_string(n++) + ".replay";
        std::ofstream(script) << text;
        SCOPED_TRACE(text);
        expectFailure(run(kOnelight + " " + package + " --headless --size 32x32 --replay " +
                          shellQuoted(script)),
                      {script.filename().c_str(), ":1:", fragment});
    }
    // A camera pose past the coordinate range is a clear error, not a black frame.
    expectFailure(run(kOnelight + " " + package + " --headless --size 32x32 --camera 1e30,0,0,0,0"),
                  {"--camera '1e30,0,0,0,0'", "within 1e6 m"});
    // A directory and a FIFO as the script.
    expectFailure(run(kOnelight + " " + package + " --headless --replay " + shellQuoted(folder)),
                  {"is a directory", "expected a replay script"});
    ASSERT_EQ(::mkfifo((folder / "fifo.replay").c_str(), 0600), 0);
    expectFailure(run(kOnelight + " " + package + " --headless --replay " +
                      shellQuoted(folder / "fifo.replay")),
                  {"fifo.replay", "is a FIFO"});
    // A megabyte-long word still gives a short message.
    std::ofstream(folder / "long.replay") << "at 0 " << std::string(1 << 20, 'x') << "\n";
    const CommandResult r = run(kOnelight + " " + package + " --headless --replay " +
                                shellQuoted(folder / "long.replay"));
    expectFailure(r, {"long.replay:1:", "unknown command", "(1048576 characters)"});
    EXPECT_LT(r.output.size(), 2000u);
    // A capture folder that is a file: named, with what was expected.
    std::ofstream(folder / "s0.replay") << "at 0 capture start\nat 0 quit\n";
    std::ofstream(folder / "afile") << "a file";
    expectFailure(run(kOnelight + " " + package + " --headless --size 32x32 --replay " +
                      shellQuoted(folder / "s0.replay") + " --capture-dir " +
                      shellQuoted(folder / "afile") + " 2>&1"),
                  {"--capture-dir '", "afile': cannot make that folder (",
                   "expected a folder, or a path where one can be made"});
}

// The runtime reads one image by its uri beside the package: the sky's (material textures come
// from the package's textures section). A FIFO there is refused, not waited on.
TEST(HostileCommandLine, AnImageBesideThePackageThatIsAFifoDoesNotHang) {
    const std::filesystem::path folder = hostileFolder("fifo-image");
    std::filesystem::create_directories(folder / "src");
    std::ofstream(folder / "src" / "sky.hdr") << "not read at compile";
    const std::string level = shellQuoted(writeTriangleLevel(folder / "src", [](nlohmann::json& j) {
        j["nodes"][0]["extras"] = {{"onelight", {{"sky", "sky.hdr"}}}};
    }));
    const std::string package = shellQuoted(folder / "src" / "level.olpak");
    ASSERT_EQ(run(kBake + " compile " + level + " -o " + package).exitCode, 0);
    std::filesystem::remove(folder / "src" / "sky.hdr");
    ASSERT_EQ(::mkfifo((folder / "src" / "sky.hdr").c_str(), 0600), 0);
    expectFailure(run(kOnelight + " " + package + " --headless --size 32x32"),
                  {"sky.hdr", "is a FIFO"});
}

TEST(HostileCommandLine, LongAndMultiLineNamesGiveOneShortLine) {
    // A 5000-character map name and one holding a newline: each error is one short line whose
    // long words are clipped with their length (the name appears twice here).
    const std::string longName(5000, 'a');
    for (const std::string& name : {longName, std::string("oa_dm1\nfoo")}) {
        const CommandResult r = run(kBake + " compile '" + name + "' -o /dev/null 2>&1");
        expectFailure(r, {"onelight-bake: error: ", "no map of that name"});
        std::string output = r.output;
        while (!output.empty() && output.back() == '\n') output.pop_back();
        EXPECT_EQ(output.find('\n'), std::string::npos) << output;
        EXPECT_LE(output.size(), 400u) << output;
    }
    EXPECT_NE(run(kBake + " compile '" + longName + "' 2>&1").output.find("(5001 characters)"),
              std::string::npos);
    EXPECT_NE(run(kBake + " compile 'oa_dm1\nfoo' 2>&1").output.find("oa_dm1?foo"),
              std::string::npos);
}

}  // namespace
}  // namespace onelight::test
