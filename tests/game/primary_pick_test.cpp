// The primary a dynamic object is drawn with is the one the game picked: the demo's crate moves
// from the sun's region into the door spot's and back (a mover, 8 s a round trip) while the game
// steps on its fixed tick and the renderer draws what the session hands it. At every drawn frame
// the renderer's primary for the crate equals the game's, and the game's pick changes both ways.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "render/renderer.hpp"
#include "session.hpp"
#include "vk/context.hpp"

namespace {

using namespace onelight;

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
        render::RendererOptions options;
        options.width = 160;
        options.height = 90;
        options.requestedMsaa = 1;
        render::createRenderer(renderer, ctx, level, options);
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

}  // namespace
