// The demo game's systems on a level compiled in memory: a 20 m floor and a wall.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/systems.hpp"
#include "world/compile/compile_level.hpp"
#include "world/source_level.hpp"

using namespace onelight;
using namespace onelight::game;

namespace {

world::MeshInstance quad(const char* name, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    world::MeshInstance m;
    m.nodeName = m.meshName = name;
    m.material = 0;
    glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    for (glm::vec3 p : {a, b, c, d}) {
        world::Vertex v;
        v.position = p;
        v.normal = n;
        m.vertices.push_back(v);
    }
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

// Floor y = 0 over x, z in [-10, 10]; a wall in the plane z = -5 facing +z, 3 m high.
world::CompiledLevel floorAndWall() {
    world::SourceLevel source;
    source.sourcePath = "memory";
    source.materials.push_back(world::Material{});
    source.instances.push_back(
        quad("floor", {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}, {-10, 0, -10}));
    source.instances.push_back(quad("wall", {-10, 0, -5}, {10, 0, -5}, {10, 3, -5}, {-10, 3, -5}));
    return world::compileLevel(source, world::CompileOptions{}).level;
}

struct Sim {
    world::CompiledLevel level = floorAndWall();
    world::BspView bsp = world::bspView(level);
    ecs::Registry registry;
    ecs::Entity player = registry.create();
    Tuning tuning;
    InputState input;
    uint64_t tick = 0, shots = 0;

    explicit Sim(glm::vec3 feet, float yawDegrees = 0.0f) {
        registry.emplace<Transform>(player, Transform{feet});
        registry.emplace<Player>(player, Player{glm::radians(yawDegrees)});
        registry.emplace<Flashlight>(player);
    }
    void step(int ticks) {
        for (int i = 0; i < ticks; ++i) {
            ecs::Tick t{tick++};
            playerSystem(registry, t, input, tuning, &bsp);
            effectLightSystem(registry, t, input, tuning, shots);
            input.endTick();
        }
    }
    glm::vec3 feet() { return registry.get<Transform>(player).position; }
};

}  // namespace

TEST(GameSim, WalkingForwardCoversWalkSpeedPerSecondOnTheFloor) {
    Sim sim({0, 0.0f, 5});
    sim.step(10);  // settle on the floor
    float z0 = sim.feet().z;
    sim.input.keysDown = {"W"};
    sim.step(30);  // half a second, yaw 0 looks down -z
    EXPECT_NEAR(z0 - sim.feet().z, 0.5f * sim.tuning.walkSpeed, 0.01f);
    EXPECT_NEAR(sim.feet().y, 0.0f, 0.01f);
    EXPECT_TRUE(sim.registry.get<Player>(sim.player).onGround);
}

TEST(GameSim, TheWallStopsThePlayerWithoutPenetration) {
    Sim sim({0, 0, 0});
    sim.input.keysDown = {"W"};
    for (int i = 0; i < 180; ++i) {
        sim.step(1);
        ASSERT_GE(sim.feet().z, -5.0f + sim.tuning.bodyRadius - 1e-3f) << "tick " << i;
    }
    EXPECT_NEAR(sim.feet().z, -5.0f + sim.tuning.bodyRadius, 0.01f);
}

TEST(GameSim, WalkingDiagonallyIntoTheWallSlidesAlongIt) {
    Sim sim({0, 0, -4.0f}, 45.0f);  // facing -z and -x
    sim.input.keysDown = {"W"};
    sim.step(60);
    EXPECT_NEAR(sim.feet().z, -5.0f + sim.tuning.bodyRadius, 0.01f);
    // Along the wall it keeps the tangential part of 4 m/s for most of the second.
    EXPECT_LT(sim.feet().x, -2.0f);
}

TEST(GameSim, GravityLandsThePlayerOnTheFloor) {
    Sim sim({3, 2.0f, 3});
    sim.step(60);
    EXPECT_NEAR(sim.feet().y, 0.0f, 0.01f);
    EXPECT_TRUE(sim.registry.get<Player>(sim.player).onGround);
    EXPECT_NEAR(sim.feet().x, 3.0f, 1e-4f);
}

TEST(GameSim, MouseLookTurnsAndClampsPitch) {
    Sim sim({0, 0, 0});
    sim.input.lookYawDegrees = 90;
    sim.input.lookPitchDegrees = 200;
    sim.step(1);
    const Player& p = sim.registry.get<Player>(sim.player);
    EXPECT_NEAR(p.yaw, glm::radians(90.0f), 1e-6f);
    EXPECT_NEAR(p.pitch, glm::radians(89.0f), 1e-6f);
    glm::vec3 d = viewDirection(glm::radians(90.0f), 0.0f);  // yaw 90 looks down -x
    EXPECT_NEAR(d.x, -1.0f, 1e-6f);
}

TEST(GameSim, ShuttlesFollowTheirPathAsAFunctionOfTime) {
    world::CompiledLevel level;
    world::Entity box;
    box.flags = world::kEntityDynamic | world::kEntityMover;
    level.entities.push_back(box);
    world::Mover shuttle;
    shuttle.entity = 0;
    shuttle.pos1 = {1, 0.5f, 0};
    shuttle.pos2 = {11, 0.5f, 0};
    shuttle.period = 4.0f;
    level.movers.movers.push_back(shuttle);
    ecs::Registry registry;
    ecs::Entity crate = registry.create();
    registry.emplace<Transform>(crate);
    MoverWorld movers = startMovers(level, {crate});
    BrushWorld brushes;
    const auto xAtTick = [&](uint64_t tick) {
        moverSystem(registry, ecs::Tick{tick}, movers, brushes, Tuning{}, PlayerWorld{},
                    ecs::kNullEntity);
        return registry.get<Transform>(crate).position.x;
    };
    EXPECT_NEAR(xAtTick(0), 1.0f, 1e-5f);     // at the start
    EXPECT_NEAR(xAtTick(60), 6.0f, 1e-4f);    // 1 s, a quarter period: half way
    EXPECT_NEAR(xAtTick(120), 11.0f, 1e-4f);  // 2 s, half a period: at the far end
    EXPECT_NEAR(xAtTick(240), 1.0f, 1e-4f);   // 4 s: back at the start
    EXPECT_NEAR(registry.get<Transform>(crate).position.y, 0.5f, 1e-6f);
}

TEST(GameSim, FiveShotsInARowNeverMakeMoreThanFourFlashes) {
    Sim sim({0, 0, 0});
    for (int shot = 0; shot < 5; ++shot) {
        sim.input.fire = true;
        sim.step(1);
        EXPECT_LE(sim.registry.pool<GunFlash>().size(), 4u) << "after shot " << shot;
    }
    // At tick 4 the first flash is 66 ms old and gone; the second is 50 ms old and lives.
    EXPECT_EQ(sim.registry.pool<GunFlash>().size(), 4u);
    uint64_t oldest = UINT64_MAX;
    for (auto [e, f] : sim.registry.view<GunFlash>().each()) oldest = std::min(oldest, f.serial);
    EXPECT_EQ(oldest, 1u);
    sim.step(4);  // 60 ms later every flash is gone
    EXPECT_EQ(sim.registry.pool<GunFlash>().size(), 0u);
}

TEST(GameSim, FiveSimultaneousShotsKeepTheNewestFour) {
    Sim sim({0, 0, 0});
    Tuning quick = sim.tuning;
    for (int shot = 0; shot < 5; ++shot) {
        InputState fire;
        fire.fire = true;
        effectLightSystem(sim.registry, ecs::Tick{0}, fire, quick, sim.shots);
    }
    ASSERT_EQ(sim.registry.pool<GunFlash>().size(), 4u);
    for (auto [e, f] : sim.registry.view<GunFlash>().each()) EXPECT_GE(f.serial, 1u);
}

TEST(GameSim, FlashlightTogglesAndFollowsReplayOrders) {
    Sim sim({0, 0, 0});
    sim.input.toggleFlashlight = true;
    sim.step(1);
    EXPECT_TRUE(sim.registry.get<Flashlight>(sim.player).on);
    sim.input.setFlashlight = true;
    sim.input.flashlightValue = true;
    sim.step(1);
    EXPECT_TRUE(sim.registry.get<Flashlight>(sim.player).on);
    sim.input.toggleFlashlight = true;
    sim.step(1);
    EXPECT_FALSE(sim.registry.get<Flashlight>(sim.player).on);
}

// Light 0 dominates for x < 0 and light 1 for x > 0 (equal at x = 0).
static world::PrimaryScore lightsEitherSideOfX() {
    return [](uint32_t light, glm::vec3 p) { return light == 0 ? std::exp(-p.x) : std::exp(p.x); };
}

TEST(GameSim, PrimarySelectionHasHysteresisAtABoundary) {
    ecs::Registry r;
    ecs::Entity crate = r.create();
    r.emplace<Transform>(crate, Transform{{-3, 0, 0}});
    r.emplace<DynamicLighting>(crate);
    const uint32_t lights[] = {0, 1};
    const world::PrimaryScore score = lightsEitherSideOfX();
    primarySelectionSystem(r, ecs::Tick{}, lights, score);
    EXPECT_EQ(r.get<DynamicLighting>(crate).pick.primary, 0u);
    // Jitter across the boundary: +-2 cm moves, each re-evaluated; no flicker.
    int switches = 0;
    uint32_t last = 0;
    for (int i = 0; i < 100; ++i) {
        r.get<Transform>(crate).position.x = (i % 2 ? 0.02f : -0.02f);
        primarySelectionSystem(r, ecs::Tick{}, lights, score);
        switches += r.get<DynamicLighting>(crate).pick.primary != last;
        last = r.get<DynamicLighting>(crate).pick.primary;
    }
    EXPECT_EQ(switches, 0);
    // Crossing decisively: light 1 beats light 0 by more than the ratio at once.
    r.get<Transform>(crate).position.x = 1.0f;
    primarySelectionSystem(r, ecs::Tick{}, lights, score);
    EXPECT_EQ(r.get<DynamicLighting>(crate).pick.primary, 1u);
    // Resting just past the boundary, moving a little each tick: it switches after
    // kPrimarySwitchEvaluations evaluations even though the margin stays small.
    r.get<Transform>(crate).position.x = -0.05f;
    primarySelectionSystem(r, ecs::Tick{}, lights, score);
    EXPECT_EQ(r.get<DynamicLighting>(crate).pick.primary, 1u);
    for (int i = 1; i < world::kPrimarySwitchEvaluations; ++i) {
        r.get<Transform>(crate).position.x = -0.05f - 0.02f * i;
        primarySelectionSystem(r, ecs::Tick{}, lights, score);
    }
    EXPECT_EQ(r.get<DynamicLighting>(crate).pick.primary, 0u);
}

// A switch cross-fades (world::kPrimaryFadeSeconds): the old primary's weight falls from 1 to
// 0 over the fade, a tick at a time; switching back mid-fade turns the fade round where it
// stood, so the light never jumps.
TEST(GameSim, APrimarySwitchCrossFadesAndTurnsRoundWithoutAJump) {
    ecs::Registry r;
    ecs::Entity crate = r.create();
    r.emplace<Transform>(crate, Transform{{-3, 0, 0}});
    r.emplace<DynamicLighting>(crate);
    const uint32_t lights[] = {0, 1};
    const world::PrimaryScore score = lightsEitherSideOfX();
    const double dt = 1.0 / 60.0;
    primarySelectionSystem(r, ecs::Tick{0, dt}, lights, score);
    const DynamicLighting& lit = r.get<DynamicLighting>(crate);
    EXPECT_EQ(lit.pick.primary, 0u);
    EXPECT_EQ(lit.fadingFrom, world::kNoIndex);  // the first pick does not fade in
    EXPECT_FLOAT_EQ(primaryWeight(lit, 0.0), 1.0f);
    // Crossing decisively at tick 10: light 1 takes over, light 0 fades out over 0.25 s.
    r.get<Transform>(crate).position.x = 1.0f;
    primarySelectionSystem(r, ecs::Tick{10, dt}, lights, score);
    EXPECT_EQ(lit.pick.primary, 1u);
    EXPECT_EQ(lit.fadingFrom, 0u);
    const double t0 = 10 * dt;
    EXPECT_FLOAT_EQ(primaryWeight(lit, t0), 0.0f);
    EXPECT_NEAR(primaryWeight(lit, t0 + 0.125), 0.5f, 1e-5f);
    EXPECT_FLOAT_EQ(primaryWeight(lit, t0 + double(world::kPrimaryFadeSeconds)), 1.0f);
    // Back to light 0 at 0.1 s into the fade (light 1 at weight 0.4): light 0 now starts at
    // 0.6, where it stood, and rises.
    const uint64_t back = 10 + 6;  // 0.1 s later
    r.get<Transform>(crate).position.x = -1.0f;
    primarySelectionSystem(r, ecs::Tick{back, dt}, lights, score);
    EXPECT_EQ(lit.pick.primary, 0u);
    EXPECT_EQ(lit.fadingFrom, 1u);
    EXPECT_NEAR(primaryWeight(lit, back * dt), 0.6f, 1e-4f);
    // After the fade the old primary is forgotten at the next evaluation.
    r.get<Transform>(crate).position.x = -1.1f;
    primarySelectionSystem(r, ecs::Tick{back + 60, dt}, lights, score);
    EXPECT_EQ(lit.fadingFrom, world::kNoIndex);
    EXPECT_FLOAT_EQ(primaryWeight(lit, (back + 60) * dt), 1.0f);
}

// An object lit from a fixed origin (an item's rest: its bob is for show) keeps its pick while
// what is drawn moves across a boundary between two lights.
TEST(GameSim, AFixedLightingOriginKeepsThePickWhereverTheObjectIsDrawn) {
    ecs::Registry r;
    ecs::Entity item = r.create();
    r.emplace<Transform>(item, Transform{{-0.05f, 0, 0}});
    DynamicLighting fixed;
    fixed.fixedOrigin = true;
    fixed.origin = {-0.05f, 0, 0};
    r.emplace<DynamicLighting>(item, fixed);
    const uint32_t lights[] = {0, 1};
    const world::PrimaryScore score = lightsEitherSideOfX();
    for (uint64_t t = 0; t < 600; ++t) {
        // Drawn swinging 30 cm either side of the boundary at x = 0.
        r.get<Transform>(item).position.x = 0.3f * std::sin(0.1f * float(t));
        primarySelectionSystem(r, ecs::Tick{t}, lights, score);
        ASSERT_EQ(r.get<DynamicLighting>(item).pick.primary, 0u) << "tick " << t;
    }
    // Picked where it is drawn instead, the same swing switches it.
    r.get<DynamicLighting>(item).fixedOrigin = false;
    int switches = 0;
    uint32_t last = 0;
    for (uint64_t t = 600; t < 1200; ++t) {
        r.get<Transform>(item).position.x = 0.3f * std::sin(0.1f * float(t));
        primarySelectionSystem(r, ecs::Tick{t}, lights, score);
        switches += r.get<DynamicLighting>(item).pick.primary != last;
        last = r.get<DynamicLighting>(item).pick.primary;
    }
    EXPECT_GT(switches, 2);
}
