#include <gtest/gtest.h>

#include "replay/replay_script.hpp"

using namespace onelight::replay;

namespace {

// The message of the ScriptError that parsing `text` throws ("" when it parses).
std::string errorOf(const std::string& text) {
    try {
        (void)parseScript(text, "s.replay");
    } catch (const ScriptError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(ReplayScript, ParsesTheDesignExample) {
    Script s = parseScript(R"(level demo
spawn player 0 1.7 0 yaw 90 pitch 0
at 0.0  key W down
at 1.5  key W up
at 1.5  look +30 -5
at 2.0  flashlight on
at 2.5  fire
at 3.0  capture courtyard
at 3.0  expect primary crate_1 == sun
at 4.0  quit
)",
                           "demo.replay");
    EXPECT_EQ(s.level, "demo");
    ASSERT_EQ(s.commands.size(), 9u);
    const Command& spawn = s.commands[0];
    EXPECT_EQ(spawn.kind, CommandKind::kSpawn);
    EXPECT_EQ(spawn.tick, 0u);
    EXPECT_FLOAT_EQ(spawn.values[1], 1.7f);
    EXPECT_FLOAT_EQ(spawn.values[3], 90.0f);
    EXPECT_EQ(s.commands[2].tick, 90u);  // 1.5 s at 60 Hz
    EXPECT_FALSE(s.commands[2].on);
    EXPECT_FLOAT_EQ(s.commands[3].values[0], 30.0f);
    EXPECT_FLOAT_EQ(s.commands[3].values[1], -5.0f);
    EXPECT_EQ(s.commands[6].kind, CommandKind::kCapture);
    EXPECT_EQ(s.commands[6].name, "courtyard");
    EXPECT_EQ(s.commands[7].name, "crate_1");
    EXPECT_EQ(s.commands[7].light, "sun");
    EXPECT_EQ(s.commands[7].line, 9);
    EXPECT_EQ(s.commands[8].kind, CommandKind::kQuit);
    EXPECT_EQ(s.commands[8].tick, 240u);
}

TEST(ReplayScript, ExpectsAnItemVisibleOrTaken) {
    Script s = parseScript(
        "at 1 expect item weapon_rocketlauncher_1 taken\n"
        "at 2 expect item item_health_3 visible\n",
        "items.replay");
    ASSERT_EQ(s.commands.size(), 2u);
    EXPECT_EQ(s.commands[0].kind, CommandKind::kExpectItem);
    EXPECT_EQ(s.commands[0].name, "weapon_rocketlauncher_1");
    EXPECT_FALSE(s.commands[0].on);
    EXPECT_EQ(s.commands[1].name, "item_health_3");
    EXPECT_TRUE(s.commands[1].on);
    EXPECT_EQ(s.commands[1].tick, 120u);
}

TEST(ReplayScript, ExpectsAMoversStateAndThePlayerRidingIt) {
    Script s = parseScript(
        "at 1 expect mover func_door_1 rest\n"
        "at 1 expect mover func_plat_2 open\n"
        "at 1 expect mover func_train_1 moving\n"
        "at 2 expect player riding func_plat_2\n",
        "movers.replay");
    ASSERT_EQ(s.commands.size(), 4u);
    EXPECT_EQ(s.commands[0].kind, CommandKind::kExpectMover);
    EXPECT_EQ(s.commands[0].name, "func_door_1");
    EXPECT_EQ(s.commands[0].count, 0);
    EXPECT_EQ(s.commands[1].count, 1);
    EXPECT_EQ(s.commands[2].count, 2);
    EXPECT_EQ(s.commands[3].kind, CommandKind::kExpectRiding);
    EXPECT_EQ(s.commands[3].name, "func_plat_2");
    EXPECT_EQ(s.commands[3].tick, 120u);
}

TEST(ReplayScript, WaitMovesTheCursorAndTickRateScalesTicks) {
    Script s = parseScript(
        "tick 30\n# comment\n\nfire\nwait 0.5\nfire   # trailing comment\n"
        "expect effect-lights 2\nat 2 quit\n",
        "s.replay");
    ASSERT_EQ(s.commands.size(), 4u);
    EXPECT_EQ(s.commands[0].tick, 0u);
    EXPECT_EQ(s.commands[1].tick, 15u);
    EXPECT_EQ(s.commands[2].count, 2);
    EXPECT_EQ(s.commands[3].tick, 60u);
}

TEST(ReplayScript, BadInputNamesFileLineAndExpectation) {
    struct {
        const char* text;
        const char* error;
    } cases[] = {
        {"level demo\nat 1 dance\n", "s.replay:2: unknown command 'dance'"},
        {"at 1.x fire\n", "s.replay:1: expected a time in seconds (a number), found '1.x'"},
        {"at 2 fire\nat 1 fire\n",
         "s.replay:2: time 1 goes backwards (the previous command is at 2)"},
        {"look 30\n", "s.replay:1: expected a pitch change in degrees at the end of the line"},
        {"key W sideways\n", "s.replay:1: expected 'down' or 'up', found 'sideways'"},
        {"key Z down\n", "s.replay:1: expected a key"},
        {"fire now\n", "s.replay:1: unexpected 'now' after the command"},
        {"fire\nlevel demo\n", "s.replay:2: 'level' must come before any timed command"},
        {"expect primary crate sun\n", "s.replay:1: expected '==', found 'sun'"},
        {"expect effect-lights 7\n", "s.replay:1: expected a whole count from 0 to 5"},
        {"spawn monster 0 0 0 yaw 0 pitch 0\n", "s.replay:1: expected 'player', found 'monster'"},
        {"at -1 fire\n", "s.replay:1: expected a time of zero or more seconds"},
        {"at inf fire\n", "s.replay:1: expected a time in seconds (a number), found 'inf'"},
        {"capture ../etc/x\n", "s.replay:1: expected a capture name without '/' or '..'"},
        {"tick 0\n", "s.replay:1: expected a tick rate between 1 and 1000 Hz"},
        {"expect player flying\n",
         "s.replay:1: expected on-ground, in-air, moved, feet, height, velocity, teleports, "
         "launches, respawns or riding after 'expect player', found 'flying'"},
        {"expect player riding\n", "s.replay:1: expected a mover's name"},
        {"expect player feet 1 2 3\n", "s.replay:1: expected within at the end of the line"},
        {"expect player velocity 1 2 3 within -1\n",
         "s.replay:1: expected a tolerance of zero or more"},
        {"expect player height 2 1\n", "s.replay:1: expected the lowest height first (MIN <= MAX)"},
        {"expect player teleports 1.5\n", "s.replay:1: expected a whole count from 0 to 1000000"},
        {"expect player moved -1\n", "s.replay:1: expected a distance from 0 to 1e6 metres"},
        {"expect player moved\n", "s.replay:1: expected a distance in metres"},
        {"expect weather\n",
         "s.replay:1: expected 'primary', 'effect-lights', 'player', 'item' or 'mover' after "
         "'expect', found 'weather'"},
        {"expect mover func_door_1 ajar\n",
         "s.replay:1: expected 'rest', 'open' or 'moving' after the mover's name, found 'ajar'"},
        {"expect mover\n", "s.replay:1: expected a mover's name"},
        {"expect item weapon_shotgun_1 gone\n",
         "s.replay:1: expected 'visible' or 'taken' after the item's name, found 'gone'"},
        {"expect item\n", "s.replay:1: expected an item's name"},
    };
    for (auto& c : cases) {
        std::string e = errorOf(c.text);
        EXPECT_EQ(e.rfind(c.error, 0), 0u) << "script: " << c.text << "\nerror: " << e;
    }
}

TEST(ReplayScript, MissingFileIsAClearError) {
    try {
        (void)loadScript("/nonexistent/x.replay");
        FAIL() << "no error";
    } catch (const ScriptError& e) {
        EXPECT_STREQ(e.what(),
                     "/nonexistent/x.replay: cannot open (No such file or directory); expected a "
                     "replay script");
    }
}
