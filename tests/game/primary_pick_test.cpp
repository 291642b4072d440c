// The primary a dynamic object is drawn with is the one the game picked: the demo's crate moves
// from the sun's region into the door spot's and back (a mover, 8 s a round trip) while the game
// steps on its fixed tick and the renderer draws what the session hands it. At every drawn frame
// the renderer's primary for the crate equals the game's, and the game's pick changes both ways.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "render/renderer.hpp"
#include "session.hpp"
#include "tests/support/run_command.hpp"
#include "tests/world/q3_test_maps.hpp"
#include "tests/world/world_test_support.hpp"
#include "vk/context.hpp"

namespace {

using namespace onelight;

// A small frame (160x90, no MSAA): enough to draw and ask what was drawn with.
render::RendererOptions smallView() {
    render::RendererOptions options;
    options.width = 160;
    options.height = 90;
    options.requestedMsaa = 1;
    return options;
}

TEST(GamePrimaryPick, TheRendererDrawsThePickTheGameReports) {
    const assets::LoadedLevel level = assets::loadLevel(ONELIGHT_DEMO_PACKAGE);

    game::Session session;
    game::startSession(session, level);
    // Stand where game/replays/mover.replay does: the crate's whole path in view.
    game::Transform& feet = session.registry.get<game::Transform>(session.player);
    feet.position = {-2.0f, 0.0f, 2.0f};
    game::Player& player = session.registry.get<game::Player>(session.player);
    player.yaw = glm::radians(-82.0f);
    player.pitch = glm::radians(-4.0f);

    ecs::Entity crate = ecs::kNullEntity;
    for (auto [e, name, link] : session.registry.view<game::Name, game::LevelEntity>().each())
        if (name.value == "crate_1") crate = e;
    ASSERT_NE(crate, ecs::kNullEntity);
    const uint32_t entity = session.registry.get<game::LevelEntity>(crate).index;

    render::RenderDeviceFeatures features;
    vk::Context ctx;
    vk::createContext(ctx, render::renderContextOptions(features, {}));
    std::vector<uint32_t> picks;  // the game's pick at each drawn frame
    {
        render::Renderer renderer;
        render::createRenderer(renderer, ctx, level, smallView());
        std::vector<render::DynamicTransform> transforms;
        const int ticks = int(9.0 / session.tickSeconds);  // past one round trip
        for (int tick = 0; tick < ticks; ++tick) {
            game::stepSession(session);
            if (tick % 12 != 0) continue;
            render::drawFrame(renderer, game::frameInputsOf(session, transforms));
            const uint32_t picked = session.registry.get<game::DynamicLighting>(crate).pick.primary;
            ASSERT_NE(picked, world::kNoIndex) << "tick " << tick;
            EXPECT_EQ(render::drawnPrimary(renderer, entity), picked)
                << "tick " << tick << ": drawn with light "
                << render::drawnPrimary(renderer, entity) << ", the game picked " << picked;
            picks.push_back(picked);
        }
        render::destroyRenderer(renderer);
    }
    vk::destroyContext(ctx);
    EXPECT_EQ(ctx.validationCounts.errors.load(), 0u);

    // Both ways across the boundary: sun, door spot, sun.
    std::vector<std::string> sequence;
    for (uint32_t p : picks)
        if (sequence.empty() || sequence.back() != level.level.lights[p].name)
            sequence.push_back(level.level.lights[p].name);
    ASSERT_GE(sequence.size(), 3u);
    EXPECT_EQ(sequence[0], "sun");
    EXPECT_EQ(sequence[1], "door_spot");
    EXPECT_EQ(sequence[2], "sun");
}

// A Quake 3 map's mover is drawn with the primary the game picks as it moves: a map written here
// with two lamps over a floor, 16 m apart, and a door that slides from under the one to under the
// other (lip -478: 512 units, 5.12 s at 100 u/s), baked at draft, seen whole from the spawn. At
// every drawn frame the renderer's primary for the door is the game's pick, which goes from the
// first lamp to the second as it crosses, and its lighting origin follows its bounds' centre.
TEST(GamePrimaryPick, AQuakeMoverCrossingTwoLampsIsDrawnWithTheGamesPick) {
    test::Quake3BspBuilder map;
    map.shaders[0].contentFlags = 1;
    map.addBoxModel({{{-512, -768, -16}, {512, 256, 0}}});
    map.addBoxModel({{{-272, -16, 0}, {-240, 16, 64}}});
    map.entities =
        "{\n\"classname\" \"worldspawn\"\n}\n"
        "{\n\"classname\" \"info_player_deathmatch\"\n\"origin\" \"0 -700 24\"\n"
        "\"angle\" \"90\"\n}\n"
        "{\n\"classname\" \"light\"\n\"origin\" \"-256 0 160\"\n\"light\" \"400\"\n"
        "\"targetname\" \"west\"\n}\n"
        "{\n\"classname\" \"light\"\n\"origin\" \"256 0 160\"\n\"light\" \"400\"\n"
        "\"targetname\" \"east\"\n}\n"
        "{\n\"classname\" \"func_door\"\n\"model\" \"*1\"\n\"angle\" \"0\"\n"
        "\"lip\" \"-478\"\n\"speed\" \"100\"\n\"targetname\" \"slider\"\n\"wait\" \"30\"\n}\n";
    const std::string bsp = map.write("mover_pick_map", "slider");
    const std::string package = (test::freshFolder("mover_pick") / "slider.olpak").string();
    const test::CommandResult baked = test::runCommand(std::string(ONELIGHT_BAKE_EXE) + " " + bsp +
                                                       " --quality draft --quiet -o " + package);
    ASSERT_EQ(baked.exitCode, 0) << baked.output;
    const assets::LoadedLevel level = assets::loadLevel(package);
    uint32_t primaries = 0;
    for (const world::Light& l : level.level.lights)
        primaries += l.role == world::LightRole::kPrimary;
    ASSERT_EQ(primaries, 2u) << "each lamp the brightest on half the floor";

    game::Session session;
    game::startSession(session, level);
    ASSERT_EQ(session.movers.motion.size(), 1u);
    ecs::Entity door = session.movers.entityOf[0];
    const uint32_t entity = level.level.movers.movers[0].entity;
    game::useMover(session.movers, 0, 0.0);

    render::RenderDeviceFeatures features;
    vk::Context ctx;
    vk::createContext(ctx, render::renderContextOptions(features, {}));
    std::vector<uint32_t> picks;
    {
        render::Renderer renderer;
        render::createRenderer(renderer, ctx, level, smallView());
        std::vector<render::DynamicTransform> transforms;
        const int ticks = int(6.0 / session.tickSeconds);  // past its 5.12 s slide
        for (int tick = 0; tick < ticks; ++tick) {
            game::stepSession(session);
            if (tick % 15 != 0) continue;
            const game::DynamicLighting& lit = session.registry.get<game::DynamicLighting>(door);
            // Its lighting origin: its box's centre, where the door is now.
            const glm::vec3 centre =
                session.movers.motion[0].pose.origin + glm::vec3(-256.0f, 32.0f, 0.0f) / 32.0f;
            EXPECT_LT(glm::distance(lit.origin, centre), 1e-3f) << "tick " << tick;
            render::drawFrame(renderer, game::frameInputsOf(session, transforms));
            ASSERT_NE(lit.pick.primary, world::kNoIndex) << "tick " << tick;
            EXPECT_EQ(render::drawnPrimary(renderer, entity), lit.pick.primary) << "tick " << tick;
            picks.push_back(lit.pick.primary);
        }
        render::destroyRenderer(renderer);
    }
    vk::destroyContext(ctx);
    EXPECT_EQ(ctx.validationCounts.errors.load(), 0u);
    EXPECT_EQ(game::moverPhase(session.movers, 0), game::MoverPhase::kAtPos2);
    ASSERT_FALSE(picks.empty());
    EXPECT_NE(picks.front(), picks.back()) << "the pick switched as the door crossed";
    const glm::vec3 first = level.level.lights[picks.front()].position;
    const glm::vec3 last = level.level.lights[picks.back()].position;
    EXPECT_LT(first.x, 0.0f) << "the west lamp first";
    EXPECT_GT(last.x, 0.0f) << "the east lamp last";
}

}  // namespace
