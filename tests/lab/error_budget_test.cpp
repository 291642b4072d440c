// onelight-bake --error-budget as a user runs it, on two levels that want opposite choices:
//   - an open, rough level under a sun: the budget drops its probes and most of its texels;
//   - a closed room with a glossy floor between coloured walls: the budget keeps its probes.
// Both packages are drawn by the runtime, which must use the choices (no probe fetched where
// they were dropped), and both frames must meet the budget against the path-traced reference,
// measured as the level report measures (onelight-lab frame-error: mean relative 8x8-block
// error). The choices round-trip through the package into the capture's JSON.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "run_command.hpp"
#include "world/gltf/gltf_builder.hpp"

namespace {

using nlohmann::json;
namespace fs = std::filesystem;
using onelight::test::CommandResult;
using onelight::test::runCommand;

constexpr uint32_t kWidth = 160, kHeight = 96;  // 20 x 12 error blocks
constexpr double kBudget = 0.05;
// Paths per pixel of the reference: a block's mean then averages 64 pixels x 256 paths, whose
// own noise (a few tenths of a percent on these levels) is far under the budget.
constexpr uint32_t kReferenceSpp = 256;

json vec(glm::vec3 v) {
    return json::array({v.x, v.y, v.z});
}

json material(const char* name, glm::vec3 colour, double roughness) {
    return {{"name", name},
            {"pbrMetallicRoughness",
             {{"baseColorFactor", {colour.x, colour.y, colour.z, 1.0}},
              {"metallicFactor", 0.0},
              {"roughnessFactor", roughness}}}};
}

void addCamera(onelight::world::GltfBuilder& g, glm::vec3 position, float pitchDegrees,
               float yawDegrees) {
    const int camera = g.addCamera(
        {{"name", "view"},
         {"type", "perspective"},
         {"perspective",
          {{"yfov", 1.0}, {"znear", 0.05}, {"aspectRatio", double(kWidth) / double(kHeight)}}}});
    const glm::quat look = glm::angleAxis(glm::radians(yawDegrees), glm::vec3(0.0f, 1.0f, 0.0f)) *
                           glm::angleAxis(glm::radians(pitchDegrees), glm::vec3(1.0f, 0.0f, 0.0f));
    g.addNode({{"name", "view"},
               {"translation", vec(position)},
               {"rotation", {look.x, look.y, look.z, look.w}},
               {"camera", camera}});
}

// 40 m of rough grey ground with three rough boxes, under a sun and a pale sky: the boxes give
// the automatic probes something to reflect, but a rough surface's reflection of them is close
// to what a uniform environment gives.
std::string writeOpenLevel(const fs::path& folder) {
    using namespace onelight::world;
    GltfBuilder g;
    const int ground = g.addMaterial(material("ground", {0.45f, 0.42f, 0.4f}, 0.8));
    const int stone = g.addMaterial(material("stone", {0.6f, 0.55f, 0.5f}, 0.8));
    MeshData floor = gridMesh("ground", 4, 40.0, 0.0);
    floor.material = ground;
    g.addNode({{"name", "ground"}, {"mesh", g.addMesh(floor)}});
    const glm::vec3 boxes[3][2] = {{{-6.0f, 0.0f, -12.0f}, {-2.0f, 2.5f, -8.0f}},
                                   {{1.0f, 0.0f, -16.0f}, {5.0f, 4.0f, -12.0f}},
                                   {{3.0f, 0.0f, -6.0f}, {5.0f, 1.0f, -4.0f}}};
    for (int i = 0; i < 3; ++i) {
        MeshData box = boxMesh("box" + std::to_string(i), boxes[i][0], boxes[i][1], 1, true);
        box.material = stone;
        g.addNode({{"name", "box" + std::to_string(i)}, {"mesh", g.addMesh(box)}});
    }
    const int sun = g.addLight({{"type", "directional"}, {"intensity", 20000.0}});
    const glm::quat down = glm::angleAxis(glm::radians(-50.0f), glm::vec3(1.0f, 0.0f, 0.0f)) *
                           glm::angleAxis(glm::radians(30.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    g.addNode({{"name", "sun"},
               {"rotation", {down.x, down.y, down.z, down.w}},
               {"extensions", {{"KHR_lights_punctual", {{"light", sun}}}}}});
    g.addNode({{"name", "settings"},
               {"extras", {{"onelight", {{"sky", 1500.0}, {"texels_per_metre", 4.0}}}}}});
    addCamera(g, {0.0f, 1.7f, 4.0f}, -12.0f, 0.0f);
    return g.write(folder, "open_level");
}

// A 6 x 3 x 6 m room seen from inside: a glossy floor reflects a red and a green wall, lit by a
// point light. What the floor reflects is anything but uniform.
std::string writeGlossyRoom(const fs::path& folder) {
    using namespace onelight::world;
    GltfBuilder g;
    const int white = g.addMaterial(material("white", {0.7f, 0.7f, 0.7f}, 1.0));
    const int red = g.addMaterial(material("red", {0.7f, 0.08f, 0.06f}, 1.0));
    const int green = g.addMaterial(material("green", {0.08f, 0.6f, 0.1f}, 1.0));
    const int floorMaterial = g.addMaterial(material("floor", {0.05f, 0.05f, 0.05f}, 0.15));
    auto inward = [](MeshData m) {
        for (size_t i = 0; i + 2 < m.indices.size(); i += 3)
            std::swap(m.indices[i + 1], m.indices[i + 2]);
        for (glm::vec3& n : m.normals) n = -n;
        return m;
    };
    MeshData room = inward(boxMesh("room", {-3.0f, 0.0f, -3.0f}, {3.0f, 3.0f, 3.0f}, 1, true));
    room.material = white;
    g.addNode({{"name", "room"}, {"mesh", g.addMesh(room)}});
    // Coloured slabs along the side walls.
    MeshData redWall = boxMesh("red_wall", {-2.9f, 0.0f, -3.0f}, {-2.8f, 3.0f, 3.0f}, 1, true);
    redWall.material = red;
    g.addNode({{"name", "red_wall"}, {"mesh", g.addMesh(redWall)}});
    MeshData greenWall = boxMesh("green_wall", {2.8f, 0.0f, -3.0f}, {2.9f, 3.0f, 3.0f}, 1, true);
    greenWall.material = green;
    g.addNode({{"name", "green_wall"}, {"mesh", g.addMesh(greenWall)}});
    MeshData floor = gridMesh("floor", 2, 6.0, 0.0);
    floor.material = floorMaterial;
    g.addNode({{"name", "floor"}, {"mesh", g.addMesh(floor)}});
    const int light = g.addLight({{"type", "point"}, {"intensity", 400.0}});
    g.addNode({{"name", "lamp"},
               {"translation", vec({0.0f, 2.6f, 0.0f})},
               {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
    g.addNode({{"name", "settings"},
               {"extras",
                {{"onelight",
                  {{"diffuse", "lambert"}, {"texels_per_metre", 8.0}, {"probe_spacing", 2.0}}}}}});
    addCamera(g, {0.0f, 1.2f, 2.7f}, -25.0f, 0.0f);
    return g.write(folder, "glossy_room");
}

std::string exe(const char* path) {
    return std::string(path) + " ";
}

json readJson(const fs::path& path) {
    std::ifstream in(path);
    return json::parse(in);
}

double frameError(const fs::path& frame, const fs::path& reference) {
    const CommandResult r = runCommand(exe(ONELIGHT_LAB_EXE) + "frame-error " + frame.string() +
                                       " " + reference.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    double error = -1.0;
    EXPECT_EQ(std::sscanf(r.output.c_str(), "error=%lf", &error), 1) << r.output;
    return error;
}

struct Baked {
    json report;        // the bake's report.json
    json capture;       // the runtime's capture JSON
    double error = -1;  // the frame against the reference
};

class ErrorBudget : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        folder_ = fs::temp_directory_path() /
                  ("onelight_error_budget_test_" + std::to_string(::getpid()));
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    // ONELIGHT_KEEP_TEST_OUTPUT=1 keeps the levels, packages, frames and references to look at.
    static void TearDownTestSuite() {
        if (!std::getenv("ONELIGHT_KEEP_TEST_OUTPUT")) fs::remove_all(folder_);
    }

    // Bakes `level` (with `bakeArgs`), draws its camera and, once per level, its reference.
    static Baked bakeAndMeasure(const std::string& level, const std::string& name,
                                const std::string& bakeArgs) {
        const fs::path package = folder_ / (name + ".olpak"), report = folder_ / (name + ".json");
        const CommandResult bake =
            runCommand(exe(ONELIGHT_BAKE_EXE) + level + " -o " + package.string() +
                       " --quality draft --quiet" + " --report " + report.string() + bakeArgs);
        EXPECT_EQ(bake.exitCode, 0) << bake.output;
        const std::string size =
            " --size " + std::to_string(kWidth) + "x" + std::to_string(kHeight);
        const fs::path reference = fs::path(level).replace_extension(".reference.exr");
        if (!fs::exists(reference)) {
            const CommandResult r =
                runCommand(exe(ONELIGHT_BAKE_EXE) + "reference " + level + " --camera view --spp " +
                           std::to_string(kReferenceSpp) + size + " -o " + reference.string());
            EXPECT_EQ(r.exitCode, 0) << r.output;
        }
        const fs::path capture = folder_ / (name + "_frame");
        const CommandResult frame =
            runCommand(exe(ONELIGHT_EXE) + package.string() + " --headless --camera view" + size +
                       " --capture " + capture.string());
        EXPECT_EQ(frame.exitCode, 0) << frame.output;
        Baked b;
        b.report = readJson(report);
        b.capture = readJson(capture.string() + ".json");
        b.error = frameError(capture.string() + ".exr", reference);
        std::printf("%s: error %.4f, probes %d in use, %s texels sampled, %s grid cells\n",
                    name.c_str(), b.error, b.capture.value("probes_in_use", -1),
                    b.report["lightmap"]["texels_sampled"].dump().c_str(),
                    b.report["light_grid"]["cells"].dump().c_str());
        return b;
    }
    static inline fs::path folder_;
};

TEST_F(ErrorBudget, AnOpenRoughLevelDropsItsProbesAndMostTexelsAndMeetsTheBudget) {
    const std::string level = writeOpenLevel(folder_);
    const Baked full = bakeAndMeasure(level, "open_full", "");
    const Baked budget = bakeAndMeasure(level, "open_budget", " --error-budget 5%");
    ASSERT_GT(full.report["probes"]["placed"].get<int>(), 0)
        << "the level must have probes to drop";
    EXPECT_GT(full.capture["probes_in_use"].get<int>(), 0);

    const json& choices = budget.report["error_budget"];
    EXPECT_DOUBLE_EQ(choices["budget"].get<double>(), double(float(kBudget)));
    EXPECT_EQ(budget.report["probes"]["baked"].get<int>(), 0) << choices.dump(2);
    EXPECT_LE(choices["predicted_error"].get<double>(), kBudget / 2);
    // Most texels: under half of those at the requested density, and of the full bake's (whose
    // pilot keeps the ground's density for the boxes' shadows, which the runtime draws per
    // pixel from this camera).
    const double requested = budget.report["lightmap"]["texels_sampled_at_requested_density"];
    const double sampled = budget.report["lightmap"]["texels_sampled"];
    EXPECT_LT(sampled, 0.5 * requested);
    EXPECT_LT(sampled, 0.5 * full.report["lightmap"]["texels_sampled"].get<double>());
    EXPECT_LT(budget.report["package_bytes"].get<double>(),
              full.report["package_bytes"].get<double>());

    // The runtime honours the choices stored in the package.
    EXPECT_EQ(budget.capture["probes_in_use"].get<int>(), 0);
    ASSERT_TRUE(budget.capture.contains("error_budget")) << budget.capture.dump(2);
    EXPECT_TRUE(budget.capture["error_budget"]["probes_dropped"].get<bool>());
    EXPECT_EQ(budget.capture["error_budget"]["texels_sampled"],
              budget.report["lightmap"]["texels_sampled"]);
    EXPECT_FALSE(full.capture.contains("error_budget"));

    EXPECT_LE(budget.error, kBudget);
    EXPECT_LE(full.error, kBudget);
}

TEST_F(ErrorBudget, AGlossyRoomKeepsItsProbesAndMeetsTheBudget) {
    const std::string level = writeGlossyRoom(folder_);
    const Baked budget = bakeAndMeasure(level, "room_budget", " --error-budget 0.05");
    const json& choices = budget.report["error_budget"];
    EXPECT_GT(budget.report["probes"]["baked"].get<int>(), 0) << choices.dump(2);
    // The prediction says why: dropping them would cost more than the probes' share.
    double probeError = -1.0;
    for (const json& c : choices["choices"])
        if (c["feature"] == "probes") probeError = c["predicted_error"];
    EXPECT_GT(probeError, kBudget / 4) << choices.dump(2);
    EXPECT_GT(budget.capture["probes_in_use"].get<int>(), 0);
    EXPECT_FALSE(budget.capture["error_budget"]["probes_dropped"].get<bool>());
    EXPECT_LE(budget.error, kBudget);

    // And the prediction is right that they matter: the same package drawn without them.
    const fs::path capture = folder_ / "room_no_probes";
    const CommandResult frame =
        runCommand(exe(ONELIGHT_EXE) + (folder_ / "room_budget.olpak").string() +
                   " --headless --camera view --no-probes --size " + std::to_string(kWidth) + "x" +
                   std::to_string(kHeight) + " --capture " + capture.string());
    ASSERT_EQ(frame.exitCode, 0) << frame.output;
    const double withoutProbes =
        frameError(capture.string() + ".exr", fs::path(level).replace_extension(".reference.exr"));
    std::printf("glossy room without probes: error %.4f (predicted cost %.4f)\n", withoutProbes,
                probeError);
    EXPECT_GT(withoutProbes, budget.error + kBudget / 4);
}

TEST_F(ErrorBudget, BadBudgetsAreRefusedNamingTheArgument) {
    const std::string level = writeOpenLevel(folder_);
    for (const char* bad : {"0", "1.5", "-0.1", "abc", "0%", "150%", "nan"}) {
        const CommandResult r =
            runCommand(exe(ONELIGHT_BAKE_EXE) + level + " -o " + (folder_ / "bad.olpak").string() +
                       " --error-budget " + bad);
        EXPECT_EQ(r.exitCode, 2) << bad << "\n" << r.output;
        EXPECT_NE(r.output.find("--error-budget '" + std::string(bad) + "'"), std::string::npos)
            << r.output;
    }
    const CommandResult sharded =
        runCommand(exe(ONELIGHT_BAKE_EXE) + level + " -o " + (folder_ / "bad.olpak").string() +
                   " --error-budget 5% --shard 0/2");
    EXPECT_EQ(sharded.exitCode, 2) << sharded.output;
    EXPECT_NE(sharded.output.find("--error-budget with --shard"), std::string::npos)
        << sharded.output;
    EXPECT_FALSE(fs::exists(folder_ / "bad.olpak"));
}

}  // namespace
