// A Quake 3 map's movers from the BSP to the game: a map written here with a door, a plat, a
// train and a button-driven door, imported and compiled as any map, then run by the game's
// systems (game/sim/movers.hpp) against the times and places Quake 3's rules give
// (g_mover.c). Metres, Y up; a Quake unit is 1/32 m; a map point (x, y, z) is (x, z, -y) / 32.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/movers.hpp"
#include "sim/systems.hpp"
#include "tests/world/q3_test_maps.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/compile/compile_level.hpp"
#include "world/import/q3/q3_import.hpp"

using namespace onelight;
using namespace onelight::game;

namespace {

constexpr float kUnit = 1.0f / 32.0f;

glm::vec3 level(float x, float y, float z) {
    return glm::vec3(x, z, -y) * kUnit;
}

/*
   The map (units, Z up): a floor 1024 square, top z = 0.
   Door *1: a slab x 256..272, y -64..64, z 0..128, opening up ("angle" -1), lip 8: it rises
     (128 + 2) - 8 = 122 units at 400 u/s: 305 ms. Its trigger spans x 256 - 2 - 120 ..
     272 + 2 + 120 (its thinnest axis grown 120 units each way).
   Plat *2: a column x -320..-192, y -64..64, z 0..128: it rests lowered by 130 - 8 = 122 units
     (its top at z 6) and rises at 200 u/s (610 ms) when the player stands over it.
   Train *3: a 64-unit cube about its origin brush, origin (0, 512, 64); corners (0, 512, 64)
     -> (0, 704, 64) -> back; 100 u/s: 1.92 s a leg, holding 1 s at the first.
   Button *4 (x 400..416, y 200..216, z 32..48, pushed along +x, "target" "gate") opens door *5
     ("targetname" "gate", a slab x 480..496, y 128..256, z 0..128, which has no trigger of its
     own). With `shootableButton` the button has health: a shot uses it, a touch does not.
*/
std::string craftedMap(const std::string& folder, bool shootableButton) {
    test::Quake3BspBuilder map;
    map.shaders[0].contentFlags = 1;  // solid
    map.addBoxModel({{{-512, -512, -16}, {512, 512, 0}}});
    map.addBoxModel({{{256, -64, 0}, {272, 64, 128}}});
    map.addBoxModel({{{-320, -64, 0}, {-192, 64, 128}}});
    map.addBoxModel({{{-32, -32, -8}, {32, 32, 8}}});
    map.addBoxModel({{{400, 200, 32}, {416, 216, 48}}});
    map.addBoxModel({{{480, 128, 0}, {496, 256, 128}}});
    map.entities =
        "{\n\"classname\" \"worldspawn\"\n}\n"
        "{\n\"classname\" \"info_player_deathmatch\"\n\"origin\" \"0 0 24\"\n}\n"
        "{\n\"classname\" \"light\"\n\"origin\" \"0 0 400\"\n\"light\" \"2000\"\n}\n"
        "{\n\"classname\" \"func_door\"\n\"model\" \"*1\"\n\"angle\" \"-1\"\n}\n"
        "{\n\"classname\" \"func_plat\"\n\"model\" \"*2\"\n}\n"
        "{\n\"classname\" \"func_train\"\n\"model\" \"*3\"\n\"origin\" \"0 512 64\"\n"
        "\"target\" \"c1\"\n}\n"
        "{\n\"classname\" \"path_corner\"\n\"targetname\" \"c1\"\n\"target\" \"c2\"\n"
        "\"origin\" \"0 512 64\"\n\"wait\" \"1\"\n}\n"
        "{\n\"classname\" \"path_corner\"\n\"targetname\" \"c2\"\n\"target\" \"c1\"\n"
        "\"origin\" \"0 704 64\"\n}\n"
        "{\n\"classname\" \"func_button\"\n\"model\" \"*4\"\n\"angle\" \"0\"\n"
        "\"target\" \"gate\"\n" +
        std::string(shootableButton ? "\"health\" \"1\"\n" : "") +
        "}\n"
        "{\n\"classname\" \"func_door\"\n\"model\" \"*5\"\n\"angle\" \"-1\"\n"
        "\"targetname\" \"gate\"\n\"wait\" \"3\"\n}\n";
    return map.write(folder, "movers");
}

world::CompiledLevel compiledCraftedMap(bool shootableButton = false) {
    const std::string bsp =
        craftedMap(shootableButton ? "movers_shot_map" : "movers_map", shootableButton);
    world::Quake3Options options;
    options.gameFolders = {test::freshFolder("movers_game").string()};
    const world::SourceLevel source = world::importQuake3(bsp, options);
    return world::compileLevel(source, world::CompileOptions{}).level;
}

uint32_t moverNamed(const world::CompiledLevel& level, const std::string& name) {
    for (uint32_t i = 0; i < level.movers.movers.size(); ++i)
        if (level.entities[level.movers.movers[i].entity].name == name) return i;
    ADD_FAILURE() << "no mover " << name;
    return 0;
}

// The game's systems in stepSession's order on the crafted map, a player at `feet`.
struct MoverGame {
    world::CompiledLevel level;
    BrushWorld brushes;
    PlayerWorld world;
    ecs::Registry registry;
    ecs::Entity player = registry.create();
    MoverWorld movers;
    Tuning tuning = quake3Tuning();
    InputState input;
    uint64_t tick = 0;

    explicit MoverGame(glm::vec3 feet, bool shootableButton = false)
        : level(compiledCraftedMap(shootableButton)),
          brushes(makeBrushWorld(level.collision, level.movers.movers.size())) {
        world.brushes = &brushes;
        registry.emplace<Transform>(player, Transform{feet});
        registry.emplace<Player>(player);
        registry.emplace<TriggerEvents>(player);
        std::vector<ecs::Entity> entities;
        for (size_t i = 0; i < level.movers.movers.size(); ++i) {
            const ecs::Entity e = registry.create();
            registry.emplace<Transform>(e);
            registry.emplace<DynamicLighting>(e);
            entities.push_back(e);
        }
        movers = startMovers(level, entities);
    }
    void step(int ticks = 1) {
        for (int i = 0; i < ticks; ++i) {
            ecs::Tick t{tick++};
            moverSystem(registry, t, movers, brushes, tuning, world, player);
            playerSystem(registry, t, input, tuning, world);
            shotSystem(registry, input, tuning, movers, brushes);
            triggerSystem(registry, tuning, world, &movers);
            input.endTick();
        }
    }
    void stepSeconds(double seconds) { step(int(std::lround(seconds * 60.0))); }
    double now() const { return double(tick - 1) / 60.0; }  // the last tick's time
    glm::vec3 feet() const { return registry.get<Transform>(player).position; }
    glm::vec3 origin(uint32_t mover) const { return movers.motion[mover].pose.origin; }
};

TEST(QuakeMovers, TheMapsMoversImportWithTheGamesNumbers) {
    const world::CompiledLevel level = compiledCraftedMap();
    ASSERT_EQ(level.movers.movers.size(), 5u);
    const world::Mover& door = level.movers.movers[moverNamed(level, "func_door_1")];
    EXPECT_EQ(door.kind, world::MoverKind::kDoor);
    EXPECT_NEAR(glm::length(door.pos2 - door.pos1), 122.0f * kUnit, 1e-5f);
    EXPECT_NEAR((door.pos2 - door.pos1).y, 122.0f * kUnit, 1e-5f) << "opens up";
    EXPECT_FLOAT_EQ(door.travelSeconds, 0.305f);  // 122 / 400 s, whole milliseconds
    EXPECT_FLOAT_EQ(door.wait, 2.0f);
    const world::Mover& plat = level.movers.movers[moverNamed(level, "func_plat_1")];
    EXPECT_NEAR(plat.pos1.y, -122.0f * kUnit, 1e-5f) << "rests lowered";
    EXPECT_NEAR(plat.pos2.y, 0.0f, 1e-6f) << "rises to where it was built";
    EXPECT_FLOAT_EQ(plat.travelSeconds, 0.61f);
    const world::Mover& train = level.movers.movers[moverNamed(level, "func_train_1")];
    ASSERT_EQ(train.pointCount, 2u);
    EXPECT_NEAR(level.movers.path[train.firstPoint].legSeconds, 1.92f, 1e-6f);
    EXPECT_FLOAT_EQ(level.movers.path[train.firstPoint].wait, 1.0f);
    const world::Mover& gate = level.movers.movers[moverNamed(level, "func_door_2")];
    const world::Mover& button = level.movers.movers[moverNamed(level, "func_button_1")];
    EXPECT_EQ(button.target, gate.name);
    EXPECT_NE(gate.name, world::kNoIndex);
    // The door's, the plat's and the button's triggers; the named gate has none.
    uint32_t doorTriggers = 0, platTriggers = 0;
    for (const world::Trigger& t : level.collision.triggers) {
        doorTriggers += t.kind == world::TriggerKind::kUseMover;
        platTriggers += t.kind == world::TriggerKind::kRaisePlat;
    }
    EXPECT_EQ(doorTriggers, 2u);
    EXPECT_EQ(platTriggers, 1u);
    // Each mover's surfaces are its own dynamic meshes, out of the static geometry: the static
    // triangles are the world's floor box alone.
    EXPECT_EQ(level.indices.size(), 12u * 3u);
    for (const world::Mover& m : level.movers.movers)
        EXPECT_GT(level.entities[m.entity].dynamicMeshCount, 0u);
}

TEST(QuakeMovers, ADoorOpensAsThePlayerComesNearHoldsAndCloses) {
    MoverGame game(level(100, 0, 0));
    const uint32_t door = moverNamed(game.level, "func_door_1");
    game.step(10);
    EXPECT_EQ(moverPhase(game.movers, door), MoverPhase::kAtPos1) << "out of its trigger's reach";
    // Into the trigger (x >= 134 - 16 for the player's box): walk +x (yaw -90 looks down +x).
    game.registry.get<Player>(game.player).yaw = glm::radians(-90.0f);
    game.input.keysDown.insert("W");
    double opened = -1.0;
    for (int t = 0; t < 120 && opened < 0.0; ++t) {
        game.step();
        if (moverPhase(game.movers, door) == MoverPhase::kAtPos2) opened = game.tick / 60.0;
    }
    game.input.keysDown.erase("W");
    ASSERT_GT(opened, 0.0) << "the door opened";
    EXPECT_NEAR(game.origin(door).y, 122.0f * kUnit, 1e-4f);
    // Open 2 s after the player leaves its trigger, then 305 ms back down.
    game.registry.get<Transform>(game.player).position = level(-100, 0, 0);
    game.stepSeconds(2.0 + 0.305 + 0.1);
    EXPECT_EQ(moverPhase(game.movers, door), MoverPhase::kAtPos1);
    EXPECT_NEAR(game.origin(door).y, 0.0f, 1e-5f);
}

TEST(QuakeMovers, ThePlatRisesWithThePlayerOnItAndComesDownAfterItLeaves) {
    // Standing on the lowered plat (its top at z 6): over its trigger.
    MoverGame game(level(-256, 0, 6) + glm::vec3(0.0f, 0.05f, 0.0f));
    const uint32_t plat = moverNamed(game.level, "func_plat_1");
    game.step(30);
    EXPECT_NE(moverPhase(game.movers, plat), MoverPhase::kAtPos1) << "stood on, it rises";
    game.stepSeconds(1.0);
    EXPECT_EQ(moverPhase(game.movers, plat), MoverPhase::kAtPos2);
    EXPECT_TRUE(game.registry.get<Player>(game.player).onGround);
    EXPECT_EQ(game.registry.get<Player>(game.player).groundMover, plat) << "rides the plat";
    EXPECT_NEAR(game.feet().y, 128.0f * kUnit, 2.0f * kUnit) << "carried to the top";
    // It stays up while ridden ...
    game.stepSeconds(3.0);
    EXPECT_EQ(moverPhase(game.movers, plat), MoverPhase::kAtPos2);
    // ... and comes down 1 s after the player steps off it.
    game.registry.get<Transform>(game.player).position = level(0, 0, 0);
    game.stepSeconds(1.0 + 0.61 + 0.1);
    EXPECT_EQ(moverPhase(game.movers, plat), MoverPhase::kAtPos1);
}

TEST(QuakeMovers, TheTrainFollowsItsCornersAndCarriesItsRider) {
    MoverGame game(level(0, 0, 0));
    const uint32_t train = moverNamed(game.level, "func_train_1");
    const glm::vec3 first = level(0, 512, 64), second = level(0, 704, 64);
    game.step();
    EXPECT_NEAR(glm::distance(game.origin(train), first), 0.0f, 1e-5f) << "held at c1";
    // 1 s held, then 1.92 s to c2 at a steady speed.
    game.stepSeconds(1.96);
    const float along = float((game.now() - 1.0) / 1.92);
    EXPECT_NEAR(glm::distance(game.origin(train), first + (second - first) * along), 0.0f, 1e-4f);
    game.stepSeconds(0.96);
    EXPECT_NEAR(glm::distance(game.origin(train), second), 0.0f, 1e-4f);
    // A rider on its top goes with it: set on the train at c2, it comes back to c1 with it.
    game.registry.get<Transform>(game.player).position =
        second + glm::vec3(0.0f, 8.0f * kUnit, 0.0f);
    game.stepSeconds(1.92 + 0.05);
    EXPECT_EQ(game.registry.get<Player>(game.player).groundMover, train);
    EXPECT_NEAR(game.feet().x, first.x, 0.05f);
    EXPECT_NEAR(game.feet().z, first.z, 0.1f) << "carried back to c1";
}

TEST(QuakeMovers, AButtonPressedOpensTheDoorItTargets) {
    MoverGame game(level(360, 208, 0));
    const uint32_t button = moverNamed(game.level, "func_button_1");
    const uint32_t gate = moverNamed(game.level, "func_door_2");
    game.step(5);
    EXPECT_EQ(moverPhase(game.movers, gate), MoverPhase::kAtPos1);
    game.registry.get<Player>(game.player).yaw = glm::radians(-90.0f);  // looks down +x
    game.input.keysDown.insert("W");
    game.stepSeconds(1.0);
    game.input.keysDown.erase("W");
    EXPECT_NE(moverPhase(game.movers, button), MoverPhase::kAtPos1) << "pressed";
    // The button moves 16 + 2 - 4 = 14 units at 40 u/s (350 ms), then opens the gate.
    game.stepSeconds(1.0);
    EXPECT_NE(moverPhase(game.movers, gate), MoverPhase::kAtPos1) << "the gate opens";
    game.stepSeconds(1.0);
    EXPECT_EQ(moverPhase(game.movers, gate), MoverPhase::kAtPos2);
}

// G_Damage on a mover: a button with health is used by a shot at rest, and makes no touch
// trigger (SP_func_button); a shot stopped by the world, or meeting a mover without health,
// uses nothing.
TEST(QuakeMovers, AShootableButtonIsUsedByAShotNotByATouch) {
    MoverGame game(level(360, 208, 0), true);
    const uint32_t button = moverNamed(game.level, "func_button_1");
    const uint32_t gate = moverNamed(game.level, "func_door_2");
    EXPECT_TRUE(game.level.movers.movers[button].flags & world::kMoverShootable);
    EXPECT_FALSE(game.level.movers.movers[gate].flags & world::kMoverShootable);
    Player& player = game.registry.get<Player>(game.player);
    player.yaw = glm::radians(-90.0f);  // looks down +x
    game.step(5);
    game.input.keysDown.insert("W");  // walks into it
    game.stepSeconds(1.0);
    game.input.keysDown.erase("W");
    game.stepSeconds(1.0);
    EXPECT_EQ(moverPhase(game.movers, button), MoverPhase::kAtPos1) << "a touch does nothing";
    EXPECT_EQ(moverPhase(game.movers, gate), MoverPhase::kAtPos1);
    // At the floor (the world's brush first): nothing.
    player.pitch = glm::radians(-60.0f);
    game.input.fire = true;
    game.step();
    game.stepSeconds(0.5);
    EXPECT_EQ(moverPhase(game.movers, button), MoverPhase::kAtPos1) << "the floor took the shot";
    // At the button: the eye (z 50) aims at its face's centre (z 40).
    const glm::vec3 eye = eyeOf(game.registry.get<Transform>(game.player), game.tuning);
    const glm::vec3 aim = level(400, 208, 40) - eye;
    player.pitch = std::atan2(aim.y, glm::length(glm::vec2(aim.x, aim.z)));
    EXPECT_EQ(shootMovers(game.movers, game.brushes, eye, glm::normalize(aim), 100.0f), button);
    game.movers.pendingUses.clear();  // the probe above asked for a use: the tick's shot does
    game.input.fire = true;
    game.step();
    game.step();
    EXPECT_NE(moverPhase(game.movers, button), MoverPhase::kAtPos1) << "shot, it is pressed";
    game.stepSeconds(1.0);
    EXPECT_NE(moverPhase(game.movers, gate), MoverPhase::kAtPos1) << "and opens the gate";
}

// The first door has no health: shot, it stays (its trigger alone opens it).
TEST(QuakeMovers, ADoorWithoutHealthIgnoresShots) {
    MoverGame game(level(0, 0, 0));
    const uint32_t door = moverNamed(game.level, "func_door_1");
    Player& player = game.registry.get<Player>(game.player);
    player.yaw = glm::radians(-90.0f);  // down +x, at the slab 256 units away, outside its trigger
    game.step(5);
    const glm::vec3 eye = eyeOf(game.registry.get<Transform>(game.player), game.tuning);
    EXPECT_EQ(shootMovers(game.movers, game.brushes, eye, glm::vec3(1.0f, 0.0f, 0.0f), 100.0f),
              door)
        << "the shot meets it";
    EXPECT_TRUE(game.movers.pendingUses.empty());
    game.input.fire = true;
    game.step();
    game.stepSeconds(0.5);
    EXPECT_EQ(moverPhase(game.movers, door), MoverPhase::kAtPos1);
}

TEST(QuakeMovers, ADoorClosingOnThePlayerTurnsRound) {
    // The gate: no trigger of its own (the first door would stay open while the player stands
    // in its trigger, as the game's does).
    MoverGame game(level(100, 0, 0));
    const uint32_t gate = moverNamed(game.level, "func_door_2");
    useMover(game.movers, gate, 0.0);
    game.stepSeconds(0.5);
    ASSERT_EQ(moverPhase(game.movers, gate), MoverPhase::kAtPos2);
    // The player stands in the doorway, under the open gate, when it comes down after its 3 s.
    const glm::vec3 doorway = level(488, 192, 0);
    game.registry.get<Transform>(game.player).position = doorway;
    game.stepSeconds(3.0);
    EXPECT_EQ(game.movers.blocks, 0u);
    game.stepSeconds(0.4);
    EXPECT_GT(game.movers.blocks, 0u) << "the player was in its way";
    EXPECT_NE(moverPhase(game.movers, gate), MoverPhase::kAtPos1) << "it went back up";
    EXPECT_GT(game.origin(gate).y, 56.0f * kUnit) << "never lower than the player's head";
    EXPECT_NEAR(game.feet().x, doorway.x, 1e-4f) << "the player was not moved";
}

TEST(QuakeMovers, TheSameTicksGiveTheSameMovers) {
    const auto run = [] {
        MoverGame game(level(-256, 0, 6) + glm::vec3(0.0f, 0.05f, 0.0f));
        game.stepSeconds(6.0);
        std::vector<float> state;
        for (const MoverMotion& m : game.movers.motion)
            state.insert(state.end(), {m.pose.origin.x, m.pose.origin.y, m.pose.origin.z});
        state.push_back(game.feet().y);
        return state;
    };
    EXPECT_EQ(run(), run());
}

}  // namespace
