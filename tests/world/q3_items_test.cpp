// A Quake 3 map's items (world/import/q3/item_import.hpp): on a real OpenArena map, every pickup
// the entity lump places becomes a dynamic entity with its models' meshes, named CLASSNAME_N,
// at its origin, with the game's respawn time for its class.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>

#include "world/compile/compile_level.hpp"
#include "world/error.hpp"
#include "world/import/level_import.hpp"
#include "world/import/q3/item_import.hpp"
#include "world/import/q3/q3_import.hpp"

namespace onelight::world::q3 {
namespace {

TEST(Quake3Items, TheGameListsItsClassesWithTheirRespawnTimes) {
    ASSERT_NE(itemClassOf("weapon_rocketlauncher"), nullptr);
    EXPECT_TRUE(itemClassOf("weapon_rocketlauncher")->weapon);
    EXPECT_EQ(itemClassOf("weapon_rocketlauncher")->respawnSeconds, 5.0f);
    EXPECT_EQ(itemClassOf("item_armor_body")->respawnSeconds, 25.0f);
    EXPECT_EQ(itemClassOf("item_health_mega")->respawnSeconds, 35.0f);
    EXPECT_EQ(itemClassOf("ammo_rockets")->respawnSeconds, 40.0f);
    EXPECT_EQ(itemClassOf("holdable_medkit")->respawnSeconds, 60.0f);
    EXPECT_EQ(itemClassOf("item_quad")->respawnSeconds, 120.0f);
    EXPECT_FALSE(itemClassOf("item_health")->weapon);
    EXPECT_EQ(itemClassOf("item_health")->models[1], "models/powerups/health/medium_sphere.md3");
    EXPECT_EQ(itemClassOf("weapon_bogus"), nullptr);
    EXPECT_EQ(itemClassOf("info_player_deathmatch"), nullptr);
}

// aggressor (OpenArena 0.8.8) places 29 pickups; each is an entity with textured meshes about
// its origin, compiled into the package's dynamic meshes.
TEST(Quake3Items, ARealMapsPickupsBecomeDynamicEntitiesWithTheirModels) {
    if (defaultQuake3Folders().empty())
        GTEST_SKIP() << "OpenArena is not installed (openarena-data, openarena-088-data)";
    const SourceLevel level = importLevel("aggressor");
    std::map<std::string, uint32_t> meshesOf;  // entity name -> meshes
    std::set<std::string> names;
    size_t items = 0;
    for (const Entity& e : level.entities) {
        if (!(e.flags & kEntityItem)) continue;
        ++items;
        EXPECT_TRUE(e.flags & kEntityDynamic) << e.name;
        EXPECT_TRUE(names.insert(e.name).second) << "two items named " << e.name;
        const size_t cut = e.name.rfind('_');
        ASSERT_NE(cut, std::string::npos) << e.name;
        const ItemClass* item = itemClassOf(e.name.substr(0, cut));
        ASSERT_NE(item, nullptr) << e.name;
        EXPECT_EQ(e.itemRespawn, item->respawnSeconds) << e.name;
    }
    std::printf("[ items ] aggressor: %zu items\n", items);
    EXPECT_EQ(items, 29u);
    ASSERT_TRUE(names.count("weapon_rocketlauncher_1"));
    ASSERT_TRUE(names.count("item_health_4"));
    ASSERT_TRUE(names.count("item_armor_shard_4"));
    for (size_t i = 0; i < level.entities.size(); ++i) {
        const Entity& e = level.entities[i];
        if (e.name != "weapon_rocketlauncher_1") continue;
        // Its origin (-384 -96 -48) units: (x, z, -y) / 32 metres.
        EXPECT_NEAR(e.position.x, -12.0f, 1e-5f);
        EXPECT_NEAR(e.position.y, -1.5f, 1e-5f);
        EXPECT_NEAR(e.position.z, 3.0f, 1e-5f);
    }
    size_t itemMeshes = 0, textured = 0;
    for (const MeshInstance& m : level.instances) {
        if (!m.dynamic) continue;
        ASSERT_LT(m.entity, level.entities.size());
        const Entity& e = level.entities[m.entity];
        ASSERT_TRUE(e.flags & kEntityItem);
        ++itemMeshes;
        ++meshesOf[e.name];
        const Material& material = level.materials.at(m.material);
        textured += material.baseColorTexture != kNoIndex;
        // Untextured only where the shader draws by environment mapping: its image's mean.
        if (material.baseColorTexture == kNoIndex) {
            EXPECT_NE(material.baseColor, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)) << m.meshName;
        }
        // Placed at the item's origin; the vertices about it, within a metre and a half (a
        // weapon 1.5x its model).
        EXPECT_NEAR(m.worldFromLocal[3][0], e.position.x, 1e-6);
        for (const Vertex& v : m.vertices) {
            ASSERT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) &&
                        std::isfinite(v.position.z));
            EXPECT_LT(glm::length(v.position), 1.5f) << m.meshName;
            EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-3f) << m.meshName;
        }
        // Wound counter-clockwise about its normals on the whole.
        int agree = 0;
        for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
            const Vertex& a = m.vertices[m.indices[t]];
            const Vertex& b = m.vertices[m.indices[t + 1]];
            const Vertex& c = m.vertices[m.indices[t + 2]];
            agree += glm::dot(glm::cross(b.position - a.position, c.position - a.position),
                              a.normal + b.normal + c.normal) >= 0.0f
                         ? 1
                         : -1;
        }
        EXPECT_GE(agree, 0) << m.meshName;
    }
    EXPECT_GE(itemMeshes, items);
    // Most surfaces find their image; the health crosses draw by environment mapping alone (a
    // flat colour here) and their spheres, additive shells, are left out.
    std::printf("[ items ] %zu meshes, %zu textured\n", itemMeshes, textured);
    EXPECT_GE(textured * 4, itemMeshes * 3);
    EXPECT_EQ(meshesOf.size(), items);
    EXPECT_GE(meshesOf["item_health_1"], 1u);  // its cross (its sphere a shell, left out)

    // Compiled: each item owns its meshes in the package's dynamic meshes.
    const CompiledLevel compiled = compileLevel(level, CompileOptions{}).level;
    size_t owning = 0;
    for (const Entity& e : compiled.entities)
        if (e.flags & kEntityItem) owning += e.dynamicMeshCount > 0;
    EXPECT_EQ(owning, items);
}

}  // namespace
}  // namespace onelight::world::q3

namespace onelight::world::q3 {
namespace {

// A Nexuiz map's pickups take Nexuiz's models (its own classes, and the classes it shares with
// Quake 3 where the Quake 3 models are absent) and Nexuiz's respawn times.
TEST(Quake3Items, ANexuizMapsPickupsTakeNexuizModelsAndTimes) {
    const SourceLevel level = [] {
        try {
            return importLevel("bluesky");
        } catch (const Error&) {
            return SourceLevel{};
        }
    }();
    if (level.instances.empty()) GTEST_SKIP() << "Nexuiz is not installed (nexuiz-data)";
    size_t items = 0;
    std::set<std::string> classes;
    for (const Entity& e : level.entities) {
        if (!(e.flags & kEntityItem)) continue;
        ++items;
        classes.insert(e.name.substr(0, e.name.rfind('_')));
        const ItemClass* item = itemClassOf(e.name.substr(0, e.name.rfind('_')));
        ASSERT_NE(item, nullptr) << e.name;
        EXPECT_EQ(e.itemRespawn, item->nexuizRespawnSeconds) << e.name;
    }
    std::string list;
    for (const std::string& c : classes) list += " " + c;
    std::printf("[ items ] bluesky: %zu items of%s\n", items, list.c_str());
    EXPECT_GT(items, 5u);
    EXPECT_TRUE(classes.count("item_armor25")) << list;
    EXPECT_TRUE(classes.count("weapon_electro")) << list;
    for (const std::string& note : level.importNotes)
        EXPECT_EQ(note.find("item models no archive holds"), std::string::npos) << note;
}

}  // namespace
}  // namespace onelight::world::q3
