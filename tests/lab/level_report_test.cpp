// onelight-lab level-report as a user runs it, on a tiny level (a room and a Lambert-only
// floor, one point light, one camera): a row per knob with finite cost and error, Pareto flags
// that agree with the rule, the plots and the contact sheet, the budget, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <glm/gtc/quaternion.hpp>

#include "run_command.hpp"
#include "world/gltf/gltf_builder.hpp"
#include "world/images/image_decode.hpp"

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr uint32_t kWidth = 64, kHeight = 40;

json vec(glm::vec3 v) {
    return json::array({v.x, v.y, v.z});
}

// A room 4 m square and 2.5 m high seen from inside, a Lambert floor, a point light.
std::string writeTinyLevel(const fs::path& folder) {
    using namespace onelight::world;
    GltfBuilder g;
    const int wall = g.addMaterial({{"name", "wall"},
                                    {"pbrMetallicRoughness",
                                     {{"baseColorFactor", {0.7, 0.7, 0.7, 1.0}},
                                      {"metallicFactor", 0.0},
                                      {"roughnessFactor", 1.0}}}});
    const int floor = g.addMaterial({{"name", "floor"},
                                     {"pbrMetallicRoughness",
                                      {{"baseColorFactor", {0.5, 0.4, 0.3, 1.0}},
                                       {"metallicFactor", 0.0},
                                       {"roughnessFactor", 1.0}}}});
    MeshData room = boxMesh("room", {-2.0f, 0.0f, -2.0f}, {2.0f, 2.5f, 2.0f}, 1, true);
    for (size_t i = 0; i + 2 < room.indices.size(); i += 3)  // seen from inside
        std::swap(room.indices[i + 1], room.indices[i + 2]);
    for (glm::vec3& n : room.normals) n = -n;
    room.material = wall;
    g.addNode({{"name", "room"}, {"mesh", g.addMesh(room)}});
    MeshData ground = gridMesh("floor", 1, 4.0, 0.0);
    ground.material = floor;
    g.addNode({{"name", "floor"}, {"mesh", g.addMesh(ground)}});
    const int light = g.addLight({{"type", "point"}, {"intensity", 150.0}});
    g.addNode({{"name", "lamp"},
               {"translation", vec({0.3f, 2.0f, -0.5f})},
               {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
    g.addNode({{"name", "settings"},
               {"extras",
                {{"onelight",
                  {{"diffuse", "lambert"}, {"texels_per_metre", 4.0}, {"probe_spacing", 3.0}}}}}});
    const int camera = g.addCamera(
        {{"name", "view"},
         {"type", "perspective"},
         {"perspective",
          {{"yfov", 1.0}, {"znear", 0.05}, {"aspectRatio", double(kWidth) / double(kHeight)}}}});
    const glm::quat look = glm::angleAxis(glm::radians(-25.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    g.addNode({{"name", "view"},
               {"translation", vec({0.0f, 1.5f, 1.8f})},
               {"rotation", {look.x, look.y, look.z, look.w}},
               {"camera", camera}});
    return g.write(folder, "tiny_room");
}

onelight::test::CommandResult lab(const std::string& args) {
    return onelight::test::runCommand(std::string(ONELIGHT_LAB_EXE) + " " + args);
}

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Row {
    std::string camera, knob, value;
    double frameMs = 0, bakeSeconds = 0, error = 0, noise = 0;
    unsigned long long bytes = 0;
    bool front = false;
};

std::vector<Row> readCsv(const fs::path& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line.rfind("camera,knob,value,frame_ms,", 0), 0u) << line;
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream s(line);
        for (std::string field; std::getline(s, field, ',');) f.push_back(field);
        EXPECT_EQ(f.size(), 10u) << line;
        if (f.size() != 10) continue;
        Row r;
        r.camera = f[0];
        r.knob = f[1];
        r.value = f[2];
        r.frameMs = std::stod(f[3]);
        r.bakeSeconds = std::stod(f[5]);
        r.bytes = std::stoull(f[6]);
        r.error = std::stod(f[7]);
        r.noise = std::stod(f[8]);
        r.front = f[9] == "1";
        rows.push_back(r);
    }
    return rows;
}

// The rule the report states, written again here.
bool dominates(const Row& a, const Row& b) {
    return a.frameMs <= b.frameMs && a.bakeSeconds <= b.bakeSeconds && a.error <= b.error &&
           (a.frameMs < b.frameMs || a.bakeSeconds < b.bakeSeconds || a.error < b.error);
}

class LevelReport : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        // One folder per process: ctest runs each test as its own process, in parallel.
        folder_ = fs::temp_directory_path() /
                  ("onelight_level_report_test_" + std::to_string(::getpid()));
        fs::remove_all(folder_);
        fs::create_directories(folder_);
        level_ = writeTinyLevel(folder_);
    }
    static void TearDownTestSuite() { fs::remove_all(folder_); }
    static std::string sizeArgs() {
        return " --size " + std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --spp 8";
    }
    static inline fs::path folder_;
    static inline std::string level_;
};

TEST_F(LevelReport, ARowPerKnobWithFiniteCostsAndConsistentParetoFlags) {
    const fs::path out = folder_ / "report";
    const onelight::test::CommandResult r = lab(
        "level-report " + level_ + " --quick --timing-runs 2" + sizeArgs() + " -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("level-report ["), std::string::npos) << "no progress bar\n"
                                                                  << r.output;
    const std::vector<Row> rows = readCsv(out / "level_report.csv");
    for (const char* knob : {"baseline", "MSAA", "anisotropy", "probes", "shadow-map size",
                             "shadow distance m", "bake quality", "texels per metre", "grid cell m",
                             "probe spacing m", "probe face size", "error budget", "gloss mips"}) {
        int found = 0;
        for (const Row& row : rows) found += row.knob == knob ? 1 : 0;
        EXPECT_EQ(found, 1) << knob;
    }
    for (const Row& row : rows) {
        EXPECT_EQ(row.camera, "view");
        EXPECT_TRUE(std::isfinite(row.frameMs) && row.frameMs > 0.0) << row.knob;
        EXPECT_TRUE(std::isfinite(row.bakeSeconds) && row.bakeSeconds > 0.0) << row.knob;
        EXPECT_GT(row.bytes, 0u) << row.knob;
        EXPECT_TRUE(std::isfinite(row.error) && row.error >= 0.0) << row.knob;
        EXPECT_TRUE(std::isfinite(row.noise) && row.noise >= 0.0) << row.knob;
        // A frame that shows the room at all is far from an error of 1 (all black or white).
        EXPECT_LT(row.error, 0.9) << row.knob << " " << row.value;
    }
    // Runtime knobs reuse the baseline's package; bake knobs make their own.
    for (const Row& row : rows)
        if (row.knob == "MSAA" || row.knob == "probes") {
            EXPECT_EQ(row.bakeSeconds, rows[0].bakeSeconds) << row.knob;
            EXPECT_EQ(row.bytes, rows[0].bytes) << row.knob;
        }
    int onFront = 0;
    for (const Row& a : rows) {
        bool dominated = false;
        for (const Row& b : rows) dominated = dominated || (&a != &b && dominates(b, a));
        EXPECT_EQ(a.front, !dominated) << a.knob << " " << a.value;
        onFront += a.front ? 1 : 0;
    }
    EXPECT_GE(onFront, 1);

    const std::string readme = readText(out / "README.md");
    EXPECT_NE(readme.find("## Camera view"), std::string::npos) << readme;
    EXPECT_NE(readme.find("the least over 2 run(s)"), std::string::npos) << readme;
    EXPECT_NE(readme.find("| knob | value | frame ms |"), std::string::npos) << readme;
    EXPECT_NE(readme.find("not a runtime choice yet"), std::string::npos) << readme;
    // The budget's row is checked against its prediction.
    EXPECT_NE(readme.find("| budget | predicted | measured over the baseline | error | met |"),
              std::string::npos)
        << readme;
    EXPECT_NE(readme.find("| 5.0% | "), std::string::npos) << readme;
    for (const char* notANumber : {"| nan", "| -nan", "| inf", "| -inf"})
        EXPECT_EQ(readme.find(notANumber), std::string::npos) << notANumber << "\n" << readme;
    for (const char* png : {"cam0_view_error_vs_frame_ms.png", "cam0_view_error_vs_bake_s.png"}) {
        const auto image = onelight::world::readImageFile((out / png).string());
        EXPECT_EQ(image.width, 960u) << png;
    }
    const auto sheet = onelight::world::readImageFile((out / "cam0_view_sheet.png").string());
    EXPECT_EQ(sheet.width, 3 * kWidth);
    EXPECT_EQ(sheet.height, kHeight * rows.size());
    for (const auto& entry : fs::directory_iterator(out))  // no temporary left behind
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
    for (const auto& entry : fs::directory_iterator(folder_))  // the patched copies are gone
        EXPECT_EQ(entry.path().string().find(".level-report-"), std::string::npos) << entry.path();
}

TEST_F(LevelReport, TheBudgetStopsAfterTheBaselineAndSaysSo) {
    const fs::path out = folder_ / "budget";
    const onelight::test::CommandResult r =
        lab("level-report " + level_ + sizeArgs() + " --budget-minutes 0.0001 -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(readCsv(out / "level_report.csv").size(), 1u);
    EXPECT_NE(readText(out / "README.md").find("Stopped by --budget-minutes"), std::string::npos);
}

TEST_F(LevelReport, BadInputGivesOneLineNamingTheArgument) {
    const std::string o = " -o " + (folder_ / "bad").string();
    struct {
        std::string args, mustSay;
    } cases[] = {
        {"level-report " + (folder_ / "missing.gltf").string() + o, "missing.gltf"},
        {"level-report " + level_ + " --cameras nope" + o, "--cameras: no camera 'nope'"},
        {"level-report " + level_ + " --spp 0" + o, "--spp '0': expected an integer in [1, 65536]"},
        {"level-report " + level_ + " --spp 2.5" + o, "--spp '2.5': expected an integer"},
        {"level-report " + level_ + " --size 64" + o, "--size '64': expected WxH"},
        {"level-report " + level_ + " --size 64x0" + o, "--size '64x0': expected WxH"},
        {"level-report " + level_ + " --budget-minutes -1" + o,
         "--budget-minutes '-1': expected minutes"},
        {"level-report " + level_ + " --timing-runs 0" + o,
         "--timing-runs '0': expected an integer in [1, 20]"},
        {"level-report " + level_, "-o DIR is required"},
        {"level-report -o x", "no level (a .gltf or .glb) given"},
    };
    for (const auto& c : cases) {
        const onelight::test::CommandResult r = lab(c.args);
        EXPECT_EQ(r.exitCode, 1) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.mustSay), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }
    EXPECT_FALSE(fs::exists(folder_ / "bad")) << "bad input left an output folder";
}

}  // namespace
