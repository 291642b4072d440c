// Static props (extras.onelight.prop, docs/level-authoring.md): a plank across the regions of two
// lamps is not split by primary; all of it takes the primary dominant at its lighting origin
// (its bounds' centre, or the one the node gives), and moving the origin changes the choice.
// Without the flag the same plank is split between the two lamps.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "tests/world/world_test_support.hpp"
#include "world/error.hpp"
#include "world/import/gltf_import.hpp"

namespace onelight::test {
namespace {

// A floor, two equal lamps 2 m up at x = -2.5 and x = +2.5, and a plank 4 m long along x at
// height 0.5 whose node carries `prop` (null: none) in extras.onelight; the plank's own
// material tells its surfaces apart. Its centre is at x = `centreX`.
std::string writePlank(const std::string& label, const nlohmann::json& prop, double centreX) {
    GltfBuilder gltf;
    gltf.addNode({{"name", "floor"}, {"mesh", gltf.addMesh(gridMesh("floor", 10, 10.0, 0.0))}});
    const int plankMaterial = gltf.addMaterial({{"name", "plank"}});
    MeshData plank = boxMesh("plank", {-2.0f, 0.4f, -0.2f}, {2.0f, 0.5f, 0.2f}, 4, true);
    plank.material = plankMaterial;
    nlohmann::json node = {
        {"name", "plank"}, {"mesh", gltf.addMesh(plank)}, {"translation", {centreX, 0.0, 0.0}}};
    if (!prop.is_null()) node["extras"] = {{"onelight", {{"prop", prop}}}};
    gltf.addNode(node);
    for (int i = 0; i < 2; ++i) {
        const int light = gltf.addLight({{"type", "point"}, {"intensity", 100.0}});
        gltf.addNode({{"name", i == 0 ? "west" : "east"},
                      {"translation", {i == 0 ? -2.5 : 2.5, 2.0, 0.0}},
                      {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
    }
    return gltf.write(freshFolder(label), label);
}

// The primaries (light names) of the plank's surfaces.
std::set<std::string> plankPrimaries(const world::CompiledLevel& level) {
    uint32_t plank = world::kNoIndex;
    for (uint32_t m = 0; m < level.materials.size(); ++m)
        if (level.materials[m].name == "plank") plank = m;
    EXPECT_NE(plank, world::kNoIndex);
    std::set<std::string> names;
    for (const world::Surface& s : level.surfaces)
        if (s.material == plank)
            names.insert(s.primaryLight == world::kNoIndex ? "none"
                                                           : level.lights[s.primaryLight].name);
    return names;
}

TEST(Props, APropTakesOnePrimaryChosenAtItsLightingOrigin) {
    // Not a prop: split between the lamps.
    EXPECT_EQ(plankPrimaries(compileFile(writePlank("plank_split", nullptr, 0.3)).level),
              (std::set<std::string>{"east", "west"}));
    // A prop centred a little east of the middle: all of it east's.
    EXPECT_EQ(plankPrimaries(compileFile(writePlank("plank_east", true, 0.3)).level),
              (std::set<std::string>{"east"}));
    EXPECT_EQ(plankPrimaries(compileFile(writePlank("plank_west", true, -0.3)).level),
              (std::set<std::string>{"west"}));
    // The same east-centred prop with its lighting origin moved to its west end (node space).
    const nlohmann::json westEnd = {{"lighting_origin", {-1.8, 0.45, 0.0}}};
    EXPECT_EQ(plankPrimaries(compileFile(writePlank("plank_moved", westEnd, 0.3)).level),
              (std::set<std::string>{"west"}));
}

TEST(Props, ABadPropKeyIsRefusedNamingTheNode) {
    const std::string bad = writePlank("plank_bad", "yes", 0.0);
    try {
        (void)world::importGltf(bad);
        FAIL() << "a prop of \"yes\" was accepted";
    } catch (const world::Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("prop"), std::string::npos) << message;
        EXPECT_NE(message.find("lighting_origin"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace onelight::test
