// Replay scripts driving the simulation (no level geometry: the player moves freely).
#include <gtest/gtest.h>

#include "sim/replay_runner.hpp"
#include "sim/systems.hpp"

using namespace onelight;
using namespace onelight::game;

namespace {

// A tiny game: a player and a crate that moves from x = -5 to x = +5 and back every 4 s; light
// 0 ("sun") wins for x < 0, light 1 ("lamp") for x > 0.
// A level of one entity, the crate, shuttling from `from` by `offset` and back every `period`.
world::CompiledLevel shuttleLevel(glm::vec3 from, glm::vec3 offset, float period) {
    world::CompiledLevel level;
    world::Entity crate;
    crate.name = "crate_1";
    crate.flags = world::kEntityDynamic | world::kEntityMover;
    crate.position = from;
    level.entities.push_back(crate);
    world::Mover shuttle;
    shuttle.entity = 0;
    shuttle.pos1 = from;
    shuttle.pos2 = from + offset;
    shuttle.period = period;
    level.movers.movers.push_back(shuttle);
    return level;
}

struct MiniGame {
    world::CompiledLevel level = shuttleLevel({-5, 0, 0}, {10, 0, 0}, 4.0f);
    ecs::Registry registry;
    ecs::Entity player = registry.create();
    ecs::Entity crate = registry.create();
    MoverWorld movers;
    BrushWorld brushes;
    PlayerWorld world;
    Tuning tuning;
    InputState input;
    uint64_t shots = 0;
    std::vector<std::string> lights = {"sun", "lamp"};

    MiniGame() {
        registry.emplace<Name>(player, Name{"player"});
        registry.emplace<Transform>(player);
        registry.emplace<Player>(player);
        registry.emplace<Flashlight>(player);
        registry.emplace<Name>(crate, Name{"crate_1"});
        registry.emplace<Transform>(crate);
        registry.emplace<DynamicLighting>(crate);
        movers = startMovers(level, {crate});
    }

    // Runs the script to its end; returns the captures requested, with their ticks.
    std::vector<std::pair<uint64_t, std::string>> run(const std::string& text) {
        ReplayRunner runner =
            makeReplayRunner(replay::parseScript(text, "t.replay"), lights, registry);
        const uint32_t candidates[] = {0, 1};
        world::PrimaryScore score = [](uint32_t l, glm::vec3 p) {
            return l == 0 ? std::exp(-p.x) : std::exp(p.x);
        };
        std::vector<std::pair<uint64_t, std::string>> captures;
        for (uint64_t tick = 0; tick < 100000; ++tick) {
            ecs::Tick t{tick};
            applyReplayInput(runner, tick, input, registry, player, tuning);
            playerSystem(registry, t, input, tuning, nullptr);
            moverSystem(registry, t, movers, brushes, tuning, world, player);
            effectLightSystem(registry, t, input, tuning, shots);
            primarySelectionSystem(registry, t, candidates, score);
            input.endTick();
            ReplayAfterTick after = finishReplayTick(runner, tick, registry);
            for (auto& c : after.captures) captures.emplace_back(tick, c);
            if (after.quit || replayFinished(runner)) break;
        }
        return captures;
    }
};

const char* kScript = R"(level mini
spawn player 0 1.7 0 yaw 0 pitch 0
at 0.0 key W down
at 0.5 key W up
at 0.5 look +90 0
at 0.5 expect primary crate_1 == sun
at 1.0 flashlight on
at 1.0 fire
at 1.0 expect effect-lights 2
at 1.2 expect effect-lights 1
at 1.5 capture middle
at 2.5 expect primary crate_1 == lamp
at 3.0 capture end
at 3.0 quit
)";

}  // namespace

TEST(ReplayRunner, DrivesTheGameAndChecksExpectations) {
    MiniGame g;
    auto captures = g.run(kScript);
    ASSERT_EQ(captures.size(), 2u);
    EXPECT_EQ(captures[0], (std::pair<uint64_t, std::string>{90, "middle"}));
    EXPECT_EQ(captures[1], (std::pair<uint64_t, std::string>{180, "end"}));
    // Walked 0.5 s at 4 m/s down -z (free fall aside), then turned 90 degrees.
    EXPECT_NEAR(g.registry.get<Transform>(g.player).position.z, -2.0f, 0.07f);
    EXPECT_NEAR(g.registry.get<Player>(g.player).yaw, glm::radians(90.0f), 1e-6f);
    EXPECT_TRUE(g.registry.get<Flashlight>(g.player).on);
}

TEST(ReplayRunner, TheSameScriptGivesTheSameState) {
    MiniGame a, b;
    a.run(kScript);
    b.run(kScript);
    EXPECT_EQ(a.registry.get<Transform>(a.player).position,
              b.registry.get<Transform>(b.player).position);
    EXPECT_EQ(a.registry.get<Transform>(a.crate).position,
              b.registry.get<Transform>(b.crate).position);
}

TEST(ReplayRunner, AFailedExpectationNamesTheLineAndBothValues) {
    MiniGame g;
    try {
        g.run("at 0.2 expect primary crate_1 == lamp\n");
        FAIL() << "no failure";
    } catch (const ReplayFailure& e) {
        EXPECT_STREQ(e.what(), "t.replay:1: expected primary crate_1 == lamp, found sun");
    }
    MiniGame h;
    try {
        h.run("fire\nexpect effect-lights 3\n");
        FAIL() << "no failure";
    } catch (const ReplayFailure& e) {
        EXPECT_STREQ(e.what(),
                     "t.replay:2: expected 3 effect lights, found 1 (1 gun flashes, 0 flashlight)");
    }
}

TEST(ReplayRunner, ThePlayerExpectationsMeasureTheWalkFromTheLastSpawn) {
    // 0.5 s of W at 4 m/s is 2 m from the spawn; without level geometry the player falls.
    const std::string walk =
        "spawn player 3 1.7 0 yaw 0 pitch 0\nat 0 key W down\nat 0.5 key W up\n";
    MiniGame g;
    EXPECT_NO_THROW(g.run(walk + "at 0.6 expect player moved 1.9\n"));
    MiniGame h;
    try {
        h.run(walk + "at 0.6 expect player moved 2.5\n");
        FAIL() << "no failure";
    } catch (const ReplayFailure& e) {
        EXPECT_EQ(
            std::string(e.what()).rfind("t.replay:4: expected the player to have moved 2.5", 0), 0u)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("found 2.0"), std::string::npos) << e.what();
    }
    MiniGame k;
    try {
        k.run(walk + "at 0.6 expect player on-ground\n");
        FAIL() << "no failure";
    } catch (const ReplayFailure& e) {
        EXPECT_NE(std::string(e.what()).find("in the air"), std::string::npos) << e.what();
    }
}

TEST(ReplayRunner, UnknownNamesFailBeforeAnythingRuns) {
    MiniGame g;
    EXPECT_THROW(
        {
            try {
                (void)makeReplayRunner(
                    replay::parseScript("at 1 expect primary crate_9 == sun\n", "t.replay"),
                    g.lights, g.registry);
            } catch (const ReplayFailure& e) {
                EXPECT_STREQ(e.what(), "t.replay:1: unknown entity 'crate_9'");
                throw;
            }
        },
        ReplayFailure);
    EXPECT_THROW(
        makeReplayRunner(replay::parseScript("expect primary crate_1 == moon\n", "t.replay"),
                         g.lights, g.registry),
        ReplayFailure);
}
