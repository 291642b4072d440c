// Items as the game runs them (game/sim/items.hpp): Quake 3's turn and bob against their closed
// forms, the drop to the floor through brushes, the player's touch taking an item, and its
// return after its respawn time (never with a negative one).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/items.hpp"

using namespace onelight;
using namespace onelight::game;

namespace {

constexpr float kUnit = 1.0f / 32.0f;

// A floor brush whose top is y = 0, and a pillar from (2, 0, 2) to (3, 3, 3).
world::LevelCollision floorAndPillar() {
    world::LevelCollision c;
    auto addBox = [&](glm::vec3 lo, glm::vec3 hi) {
        const world::CollisionPlane planes[] = {{{1, 0, 0}, hi.x}, {{-1, 0, 0}, -lo.x},
                                                {{0, 1, 0}, hi.y}, {{0, -1, 0}, -lo.y},
                                                {{0, 0, 1}, hi.z}, {{0, 0, -1}, -lo.z}};
        world::CollisionBrush b{uint32_t(c.sidePlanes.size()), 6u, world::kContentsSolid};
        for (const world::CollisionPlane& p : planes) {
            c.sidePlanes.push_back(uint32_t(c.planes.size()));
            c.planes.push_back(p);
        }
        c.brushes.push_back(b);
    };
    addBox({-32, -1, -32}, {32, 0, 32});
    addBox({2, 0, 2}, {3, 3, 3});
    return c;
}

TEST(Items, TurnOnceIn2048MillisecondsAndBobByTheGamesCosine) {
    EXPECT_FLOAT_EQ(itemYaw(0.0), 0.0f);
    EXPECT_NEAR(itemYaw(1.024), std::numbers::pi_v<float>, 1e-6f);
    EXPECT_NEAR(itemYaw(0.512), 0.5f * std::numbers::pi_v<float>, 1e-6f);
    EXPECT_FLOAT_EQ(itemYaw(2.048), 0.0f);  // a whole turn
    // 4 + 4 cos((t_ms + 1000) x (0.005 + n x 0.00001)) units.
    for (const uint32_t n : {0u, 7u, 300u})
        for (const double t : {0.0, 0.25, 3.7}) {
            const double scale = 0.005 + n * 0.00001;
            const double units = 4.0 + 4.0 * std::cos((t * 1000.0 + 1000.0) * scale);
            EXPECT_NEAR(itemBob(t, n), float(units / 32.0), 1e-6f) << n << " " << t;
            EXPECT_GE(itemBob(t, n), 0.0f);
            EXPECT_LE(itemBob(t, n), 8.0f * kUnit + 1e-6f);
        }
}

TEST(Items, DropToTheFloorUnlessSuspendedAndStayOutOfBrushes) {
    const world::LevelCollision collision = floorAndPillar();
    const BrushWorld brushes = makeBrushWorld(collision);
    glm::vec3 rest;
    ASSERT_TRUE(dropItem(&brushes, {0, 2, 0}, false, rest));
    // Its box (15 units each way) rests on the floor: the origin 15 units up, less the
    // trace's stop short of the plane (an eighth of a unit).
    EXPECT_NEAR(rest.y, kItemRadius, 0.2f * kUnit);
    EXPECT_NEAR(rest.x, 0.0f, 1e-6f);
    ASSERT_TRUE(dropItem(&brushes, {0, 2, 0}, true, rest));
    EXPECT_EQ(rest, glm::vec3(0, 2, 0));
    // On top of the pillar, and inside it (the game leaves such an item out).
    ASSERT_TRUE(dropItem(&brushes, {2.5f, 5, 2.5f}, false, rest));
    EXPECT_NEAR(rest.y, 3.0f + kItemRadius, 0.2f * kUnit);
    EXPECT_FALSE(dropItem(&brushes, {2.5f, 1, 2.5f}, false, rest));
    EXPECT_FALSE(dropItem(&brushes, {2.5f, 1, 2.5f}, true, rest));
    // Without brushes (a glTF level) it stays.
    ASSERT_TRUE(dropItem(nullptr, {1, 2, 3}, false, rest));
    EXPECT_EQ(rest, glm::vec3(1, 2, 3));
}

struct ItemWorld {
    ecs::Registry registry;
    ecs::Entity player, item;
    ItemWorld(glm::vec3 itemAt, float respawnSeconds) {
        player = registry.create();
        registry.emplace<Transform>(player, Transform{{10, 0, 10}});
        item = registry.create();
        registry.emplace<Transform>(item, Transform{itemAt});
        registry.emplace<Item>(item, Item{itemAt, respawnSeconds, 3});
    }
    void run(uint64_t tick) { itemSystem(registry, ecs::Tick{tick, 1.0 / 60.0}, player); }
    Item& state() { return registry.get<Item>(item); }
};

TEST(Items, TheTouchTakesAnItemWhichComesBackAfterItsRespawnTime) {
    ItemWorld w({0, kItemRadius, 0}, 5.0f);
    w.run(0);
    EXPECT_TRUE(w.state().present);
    // It turns and bobs about its rest.
    EXPECT_FLOAT_EQ(w.registry.get<Transform>(w.item).yaw, itemYaw(0.0));
    EXPECT_FLOAT_EQ(w.registry.get<Transform>(w.item).position.y, kItemRadius + itemBob(0.0, 3));
    // The game's reach along its x: 44 units on one side, 50 on the other.
    w.registry.get<Transform>(w.player).position = {44.5f * kUnit, 0, 0};
    w.run(1);
    EXPECT_TRUE(w.state().present);
    w.registry.get<Transform>(w.player).position = {-50.5f * kUnit, 0, 0};
    w.run(1);
    EXPECT_TRUE(w.state().present);
    w.registry.get<Transform>(w.player).position = {0, 0, 36.5f * kUnit};
    w.run(1);
    EXPECT_TRUE(w.state().present);
    // Within it: taken on that tick.
    w.registry.get<Transform>(w.player).position = {43.5f * kUnit, 0, 0};
    w.run(2);
    EXPECT_FALSE(w.state().present);
    EXPECT_EQ(w.state().timesTaken, 1u);
    // The player walks away; back 5 s (300 ticks) after the take, not a tick sooner.
    w.registry.get<Transform>(w.player).position = {10, 0, 10};
    w.run(301);
    EXPECT_FALSE(w.state().present);
    w.run(302);
    EXPECT_TRUE(w.state().present);
    // Standing on its spot, the player takes it again the tick it returns.
    w.registry.get<Transform>(w.player).position = {0, 0, 0};
    w.run(303);
    EXPECT_FALSE(w.state().present);
    EXPECT_EQ(w.state().timesTaken, 2u);
}

// The reach in height: the player's origin (24 units above its feet) within 36 units of the
// item's, so a player standing on the item's floor reaches it and one 2 m above does not.
TEST(Items, ThePlayerReachesAnItemByTheGamesRule) {
    const glm::vec3 rest(0, kItemRadius, 0);
    EXPECT_TRUE(playerTouchesItem({0, 0, 0}, rest));
    EXPECT_TRUE(playerTouchesItem({0, (36.0f - 24.0f + 15.0f - 0.5f) * kUnit, 0}, rest));
    EXPECT_FALSE(playerTouchesItem({0, (36.0f - 24.0f + 15.0f + 0.5f) * kUnit, 0}, rest));
    EXPECT_FALSE(playerTouchesItem({0, 2, 0}, rest));
    EXPECT_TRUE(playerTouchesItem({-49.5f * kUnit, 0, 35.5f * kUnit}, rest));
    EXPECT_FALSE(playerTouchesItem({44.5f * kUnit, 0, 0}, rest));
}

TEST(Items, ANegativeRespawnNeverComesBack) {
    ItemWorld w({0, kItemRadius, 0}, -1.0f);
    w.registry.get<Transform>(w.player).position = {0, 0, 0};
    w.run(0);
    EXPECT_FALSE(w.state().present);
    w.registry.get<Transform>(w.player).position = {10, 0, 10};
    for (uint64_t t = 1; t < 100000; t += 997) w.run(t);
    EXPECT_FALSE(w.state().present);
    EXPECT_EQ(w.state().timesTaken, 1u);
}

}  // namespace
