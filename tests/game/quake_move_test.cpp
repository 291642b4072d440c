// Quake 3's movement and triggers on collision brushes built in code (no drawn surface at all):
// clip brushes, the 18-unit step, the 0.7 slope limit, jump pads by AimAtTarget, teleporters,
// hurt triggers and falls, and the replay expectations that check them. Metres, Y up; a Quake
// unit is 1/32 m.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sim/replay_runner.hpp"
#include "sim/systems.hpp"

using namespace onelight;
using namespace onelight::game;

namespace {

constexpr float kUnit = 1.0f / 32.0f;

// Adds a convex brush bounded by `planes` (outward normals, distances).
void addBrush(world::LevelCollision& c, const std::vector<world::CollisionPlane>& planes,
              uint32_t contents = world::kContentsSolid) {
    world::CollisionBrush b{uint32_t(c.sidePlanes.size()), uint32_t(planes.size()), contents};
    for (const world::CollisionPlane& p : planes) {
        c.sidePlanes.push_back(uint32_t(c.planes.size()));
        c.planes.push_back(p);
    }
    c.brushes.push_back(b);
}

std::vector<world::CollisionPlane> boxPlanes(glm::vec3 lo, glm::vec3 hi) {
    return {{{1, 0, 0}, hi.x},   {{-1, 0, 0}, -lo.x}, {{0, 1, 0}, hi.y},
            {{0, -1, 0}, -lo.y}, {{0, 0, 1}, hi.z},   {{0, 0, -1}, -lo.z}};
}

void addBox(world::LevelCollision& c, glm::vec3 lo, glm::vec3 hi,
            uint32_t contents = world::kContentsSolid) {
    addBrush(c, boxPlanes(lo, hi), contents);
}

// A floor whose top is y = 0, 64 m wide.
void addFloor(world::LevelCollision& c) {
    addBox(c, {-32, -1, -32}, {32, 0, 32});
}

struct QuakeSim {
    world::LevelCollision collision;
    BrushWorld brushes;
    PlayerWorld world;
    ecs::Registry registry;
    ecs::Entity player = registry.create();
    Tuning tuning = quake3Tuning();
    InputState input;
    uint64_t tick = 0;

    // The player's feet at `feet`, looking down -z turned left by `yawDegrees`.
    QuakeSim(world::LevelCollision c, glm::vec3 feet, float yawDegrees = 0.0f)
        : collision(std::move(c)) {
        brushes = makeBrushWorld(collision);
        world.brushes = &brushes;
        registry.emplace<Name>(player, Name{"player"});
        registry.emplace<Transform>(player, Transform{feet});
        registry.emplace<Player>(player, Player{glm::radians(yawDegrees)});
        registry.emplace<TriggerEvents>(player);
    }
    void step(int ticks = 1) {
        for (int i = 0; i < ticks; ++i) {
            ecs::Tick t{tick++};
            playerSystem(registry, t, input, tuning, world);
            triggerSystem(registry, tuning, world);
            input.endTick();
        }
    }
    glm::vec3 feet() const { return registry.get<Transform>(player).position; }
    const Player& state() const { return registry.get<Player>(player); }
    const TriggerEvents& events() const { return registry.get<TriggerEvents>(player); }
};

// Walks forward (down -z) for `seconds` from z = 0 and returns the feet.
glm::vec3 walkForward(QuakeSim& sim, float seconds) {
    sim.input.keysDown.insert("W");
    sim.step(int(std::lround(seconds * 60.0f)));
    sim.input.keysDown.erase("W");
    return sim.feet();
}

}  // namespace

TEST(QuakeMove, RunsAtQuakeSpeedAndRestsAnEpsilonAboveTheFloor) {
    world::LevelCollision c;
    addFloor(c);
    QuakeSim sim(c, {0, 0.2f, 0});
    sim.step(60);  // falls and settles
    EXPECT_TRUE(sim.state().onGround);
    // Quake keeps the box SURFACE_CLIP_EPSILON (0.125 units) off the floor.
    EXPECT_NEAR(sim.feet().y, 0.125f * kUnit, 1e-5f);
    walkForward(sim, 1.0f);
    EXPECT_NEAR(glm::length(sim.state().velocity), 10.0f, 1e-3f);  // 320 units/s
}

TEST(QuakeMove, AClipBrushBlocksThePlayerThoughItDrawsNothing) {
    world::LevelCollision c;
    addFloor(c);
    // A player clip across the way at z = -3 .. -2.5, and nothing else: no surface at all.
    addBox(c, {-32, 0, -3}, {32, 4, -2.5f}, world::kContentsPlayerClip);
    QuakeSim sim(c, {0, 0.2f, 0});
    sim.step(10);
    const glm::vec3 feet = walkForward(sim, 2.0f);
    // The box's front (15 units ahead of the feet) stops an epsilon short of the clip.
    EXPECT_NEAR(feet.z, -2.5f + 15.0f * kUnit + 0.125f * kUnit, 1e-3f);
    EXPECT_TRUE(sim.state().onGround);
}

TEST(QuakeMove, AnEighteenUnitStepIsClimbedANineteenUnitStepIsNot) {
    for (const float units : {18.0f, 19.0f}) {
        world::LevelCollision c;
        addFloor(c);
        addBox(c, {-32, 0, -32}, {32, units * kUnit, -2});  // the step's edge at z = -2
        QuakeSim sim(c, {0, 0.2f, 0});
        sim.step(10);
        const glm::vec3 feet = walkForward(sim, 1.0f);
        std::printf("[ measured ] a %g-unit step: feet at y %.5f m (%.3f units), z %.4f m\n",
                    double(units), double(feet.y), double(feet.y / kUnit), double(feet.z));
        if (units == 18.0f) {
            EXPECT_NEAR(feet.y, (18.0f + 0.125f) * kUnit, 1e-4f) << "climbed onto the step";
            EXPECT_LT(feet.z, -4.0f);
        } else {
            EXPECT_NEAR(feet.y, 0.125f * kUnit, 1e-4f) << "stays below the step";
            EXPECT_NEAR(feet.z, -2.0f + (15.0f + 0.125f) * kUnit, 1e-3f);
        }
    }
}

namespace {

// A ramp rising towards -z with its surface's normal at `degrees` from vertical, through the
// origin: the half-space below the plane, boxed in.
world::LevelCollision rampAt(float degrees) {
    world::LevelCollision c;
    const float a = glm::radians(degrees);
    const glm::vec3 n(0.0f, std::cos(a), std::sin(a));  // up and towards +z: rises towards -z
    std::vector<world::CollisionPlane> planes = boxPlanes({-8, -20, -20}, {8, 20, 20});
    planes.push_back({n, 0.0f});
    addBrush(c, planes);
    return c;
}

// The ramp's surface height at z.
float rampHeight(float degrees, float z) {
    return -z * std::tan(glm::radians(degrees));
}

}  // namespace

TEST(QuakeMove, ASlopeUnderSeventyHundredthsIsWalkableAndASteeperOneSlides) {
    {
        const float degrees = 44.0f;  // normal.y = cos 44 = 0.719 >= 0.7
        QuakeSim sim(rampAt(degrees), {0, rampHeight(degrees, -2.0f) + 0.05f, -2.0f});
        sim.step(120);
        EXPECT_TRUE(sim.state().onGround);
        EXPECT_NEAR(sim.feet().z, -2.0f, 0.02f) << "stands still on a walkable slope";
        const glm::vec3 before = sim.feet();
        const glm::vec3 after = walkForward(sim, 0.5f);  // walks up it
        EXPECT_GT(after.y, before.y + 1.0f);
    }
    {
        const float degrees = 46.0f;  // normal.y = cos 46 = 0.695 < 0.7
        QuakeSim sim(rampAt(degrees), {0, rampHeight(degrees, -2.0f) + 0.05f, -2.0f});
        sim.step(30);
        EXPECT_FALSE(sim.state().onGround);
        EXPECT_GT(sim.feet().z, -1.5f) << "slides down a slope too steep to stand on";
        EXPECT_LT(sim.feet().y, rampHeight(degrees, -2.0f) - 0.5f);
    }
}

TEST(QuakeMove, AJumpRisesJumpVelocitySquaredOverTwiceGravityAndNeedsTheKeyReleased) {
    world::LevelCollision c;
    addFloor(c);
    QuakeSim sim(c, {0, 0.2f, 0});
    sim.step(10);
    const float ground = sim.feet().y;
    sim.input.keysDown.insert("SPACE");
    float apex = ground;
    int landings = 0;
    bool wasOnGround = true;
    for (int i = 0; i < 120; ++i) {
        sim.step();
        apex = std::max(apex, sim.feet().y);
        if (sim.state().onGround && !wasOnGround) ++landings;
        wasOnGround = sim.state().onGround;
    }
    // 270^2 / (2 * 800) = 45.56 units; sampled at 60 Hz the top is at most g dt^2 / 8 lower.
    const float expected = 270.0f * 270.0f / (2.0f * 800.0f) * kUnit;
    EXPECT_NEAR(apex - ground, expected, 25.0f / (60.0f * 60.0f) / 8.0f + 1e-4f);
    EXPECT_EQ(landings, 1) << "holding the key does not jump again";
}

TEST(QuakeTriggers, AJumpPadReachesItsTargetHeightAsAimAtTargetComputes) {
    world::LevelCollision c;
    addFloor(c);
    // A pad 64 units square and 8 high at z = -3; its target 6 m above and 4 m beyond it.
    world::Trigger pad;
    pad.kind = world::TriggerKind::kPush;
    pad.boundsMin = {-1, 0, -4};
    pad.boundsMax = {1, 0.25f, -2};
    pad.target = {0, 6.125f, -7};
    c.triggers.push_back(pad);
    QuakeSim sim(c, {0, 0.2f, 0});
    sim.step(10);
    sim.input.keysDown.insert("W");
    float launchY = 0.0f, apex = -1e9f;
    glm::vec3 atApex(0.0f);
    for (int i = 0; i < 240; ++i) {
        sim.step();
        if (sim.events().touchingPad != UINT32_MAX) {
            launchY = sim.feet().y;  // the last tick the pad set the velocity
            sim.input.keysDown.erase("W");
            apex = -1e9f;
        }
        if (sim.feet().y > apex) apex = sim.feet().y, atApex = sim.feet();
    }
    const glm::vec3 centre = 0.5f * (pad.boundsMin + pad.boundsMax);
    const float height = pad.target.y - centre.y;
    const float tolerance = sim.tuning.gravity * (1.0f / 3600.0f) / 8.0f;  // g dt^2 / 8
    std::printf(
        "[ measured ] jump pad: apex %.5f m above the launch, AimAtTarget's height %.5f "
        "m, difference %.6f m (tolerance g dt^2 / 8 = %.6f m)\n",
        double(apex - launchY), double(height), double(apex - launchY - height), double(tolerance));
    EXPECT_EQ(sim.events().jumpPadLaunches, 1u);
    EXPECT_NEAR(apex - launchY, height, tolerance + 1e-4f);
    EXPECT_LE(apex - launchY, height + 1e-4f);
}

TEST(QuakeTriggers, ATeleporterMovesThePlayerToItsDestinationWithItsYaw) {
    world::LevelCollision c;
    addFloor(c);
    world::Trigger gate;
    gate.kind = world::TriggerKind::kTeleport;
    gate.boundsMin = {-1, 0, -3};
    gate.boundsMax = {1, 3, -2.5f};
    gate.target = {10, 0.03125f, 10};
    gate.targetYaw = glm::radians(90.0f);  // looks down -x
    c.triggers.push_back(gate);
    QuakeSim sim(c, {0, 0.2f, 0});
    sim.step(10);
    sim.input.keysDown.insert("W");
    for (int i = 0; i < 120 && sim.events().teleports == 0; ++i) sim.step();
    ASSERT_EQ(sim.events().teleports, 1u);
    EXPECT_EQ(sim.feet(), gate.target);
    EXPECT_FLOAT_EQ(sim.state().yaw, gate.targetYaw);
    EXPECT_NEAR(sim.state().velocity.x, -12.5f, 1e-4f);  // 400 units/s along the facing
    EXPECT_NEAR(sim.state().velocity.z, 0.0f, 1e-4f);
    sim.input.keysDown.clear();
    sim.step(6);  // the knockback time keeps the exit speed: no friction for 0.16 s
    EXPECT_LT(sim.feet().x, 10.0f - 6.0f * 12.5f / 60.0f + 0.05f);
}

TEST(QuakeTriggers, AHurtTriggerAndAFallBelowTheWorldRespawn) {
    world::LevelCollision c;
    addBox(c, {-4, -1, -4}, {4, 0, 4});  // a small floor; off its edge the player falls
    world::Trigger hurt;
    hurt.kind = world::TriggerKind::kHurt;
    hurt.boundsMin = {-4, 0, -3};
    hurt.boundsMax = {4, 1, -2.5f};
    c.triggers.push_back(hurt);
    QuakeSim sim(c, {0, 0.2f, 0});
    sim.world.spawns = {{{0, 0, 1}, glm::radians(180.0f)}};  // looks down +z
    sim.world.fallLimitY = -10.0f;
    sim.step(10);
    sim.input.keysDown.insert("W");
    for (int i = 0; i < 120 && sim.events().respawns == 0; ++i) sim.step();
    ASSERT_EQ(sim.events().respawns, 1u);
    EXPECT_EQ(sim.feet(), glm::vec3(0, 9.0f * kUnit, 1));
    EXPECT_FLOAT_EQ(sim.state().yaw, glm::radians(180.0f));
    EXPECT_EQ(sim.state().velocity, glm::vec3(0.0f));
    // Now facing +z, walking off the floor's edge: the fall below -10 m respawns again.
    for (int i = 0; i < 240 && sim.events().respawns == 1; ++i) sim.step();
    EXPECT_EQ(sim.events().respawns, 2u);
    EXPECT_GT(sim.feet().y, 0.0f);
}

TEST(QuakeTriggers, ReplayExpectationsCheckPositionVelocityAndEvents) {
    world::LevelCollision c;
    addFloor(c);
    world::Trigger gate;
    gate.kind = world::TriggerKind::kTeleport;
    gate.boundsMin = {-1, 0, -3};
    gate.boundsMax = {1, 3, -2.5f};
    gate.target = {10, 0.03125f, 10};
    c.triggers.push_back(gate);
    QuakeSim sim(c, {0, 0.2f, 0});
    const std::string text = R"(spawn player 0 1.6 0 yaw 0 pitch 0
at 0.5 expect player on-ground
at 0.5 expect player height 0 0.01
at 0.5 expect player feet 0 0 0 within 0.01
at 0.5 expect player teleports 0
at 0.6 key W down
at 0.8 expect player velocity 0 0 -10 within 0.01
at 1.5 expect player teleports 1
at 1.5 expect player launches 0
at 1.5 expect player respawns 0
at 1.5 expect player feet 10 0 4 within 2
at 1.6 expect player teleports 2
)";
    ReplayRunner runner = makeReplayRunner(replay::parseScript(text, "q.replay"), {}, sim.registry);
    std::string failure;
    try {
        for (uint64_t t = 0; t < 200 && !replayFinished(runner); ++t) {
            applyReplayInput(runner, t, sim.input, sim.registry, sim.player, sim.tuning);
            sim.step();
            (void)finishReplayTick(runner, t, sim.registry);
        }
    } catch (const ReplayFailure& e) {
        failure = e.what();
    }
    // Everything holds up to the last line, which expects a second teleport.
    EXPECT_NE(failure.find("q.replay:12: expected 2 teleports, found 1"), std::string::npos)
        << failure;
}
