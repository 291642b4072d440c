// Replay scripts: plain text, one command a line, run on a fixed tick so that the same script
// gives the same frames (docs/level-authoring.md, "Replay scripts").
//
//   # comment                      blank lines and comments are ignored
//   level demo                     the level to play (once, before any timed command)
//   tick 60                        tick rate in Hz (optional, default 60; before timed commands)
//   spawn player X Y Z yaw DEG pitch DEG
//   at T <command>                 T seconds from the start; times never go backwards
//   wait S                         moves the time cursor S seconds on (for commands without `at`)
//   key NAME down|up               W, A, S, D, SPACE, SHIFT, CTRL, F, E, Q, R, 0-9
//   look DYAW DPITCH               degrees, signed
//   flashlight on|off
//   fire
//   capture NAME                   writes NAME.png, NAME.exr and NAME.json
//   expect primary ENTITY == LIGHT
//   expect effect-lights N
//   expect player on-ground        the player stands on a floor (walking a level in a replay)
//   expect player moved D          at least D metres, horizontally, from where it started (the
//                                  level's spawn, or the last spawn command)
//   expect player in-air           the player stands on no floor
//   expect player feet X Y Z within D
//                                  the feet (not the eye) within D metres of (X, Y, Z)
//   expect player height MIN MAX   the feet's height (y) from MIN to MAX metres
//   expect player velocity X Y Z within D
//                                  the velocity within D m/s of (X, Y, Z)
//   expect player teleports N      exactly N teleports so far (also launches: jump pads, respawns:
//   expect player launches N       hurt triggers and falls below the level), counted from the
//   expect player respawns N       start of the replay
//   expect item NAME visible       a level item (e.g. weapon_rocketlauncher_1) is there to take
//   expect item NAME taken         ... is taken and not back yet
//   expect mover NAME rest|open|moving
//                                  a level mover (e.g. func_door_1): a door, plat or button at
//                                  rest, at its open end, or on its way; a train held at a
//                                  corner (rest) or on a leg (moving); others are at rest
//   expect player riding NAME      the player stands on mover NAME
//   quit
//
// Parsing checks the syntax, numbers and times; entity and light names are resolved (and
// reported with their line) by whoever runs the script.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace onelight::replay {

// Limits (docs/limits.md): a script longer, later, with more commands or larger values is
// rejected with its line.
inline constexpr size_t kMaxScriptBytes = size_t(16) << 20;  // 16 MiB
inline constexpr double kMaxScriptSeconds = 24.0 * 3600.0;   // the last command's time: a day
inline constexpr size_t kMaxScriptCommands = size_t(1) << 20;
inline constexpr double kMaxScriptCoordinate = 1e6;   // metres, as world::kMaxCoordinateMetres
inline constexpr double kMaxScriptDegrees = 36000.0;  // a yaw, pitch or look change

enum class CommandKind {
    kSpawn,
    kKey,
    kLook,
    kFlashlight,
    kFire,
    kCapture,
    kExpectPrimary,
    kExpectEffectLights,
    kExpectOnGround,
    kExpectMoved,
    kExpectInAir,
    kExpectFeet,       // values: x y z tolerance
    kExpectHeight,     // values: min max
    kExpectVelocity,   // values: x y z tolerance
    kExpectTeleports,  // count
    kExpectLaunches,   // count
    kExpectRespawns,   // count
    kExpectItem,       // name: the item; on: visible (else taken)
    kExpectMover,      // name: the mover; count: 0 rest, 1 open, 2 moving
    kExpectRiding,     // name: the mover the player stands on
    kQuit
};

struct Command {
    CommandKind kind;
    int line;              // 1-based line in the script, for error messages
    uint64_t tick;         // when it runs: round(time * tick rate)
    double time;           // seconds, as written
    std::string name;      // Spawn: "player"; Key: key; Capture: file stem; ExpectPrimary: entity
    std::string light;     // ExpectPrimary: the light's name
    bool on = false;       // Key: down; Flashlight: on; ExpectItem: visible
    float values[5] = {};  // Spawn: x y z yaw pitch; Look: dyaw dpitch; ExpectMoved: metres;
                           // ExpectFeet, ExpectVelocity: x y z tolerance; ExpectHeight: min max
    int count = 0;         // ExpectEffectLights, ExpectTeleports, ExpectLaunches, ExpectRespawns
};

struct Script {
    std::string path;
    std::string level;              // empty when the script names none
    double tickRate = 60.0;         // Hz
    std::vector<Command> commands;  // in time order (stable for equal times)
};

// A script error; what() is "PATH:LINE: what was expected".
struct ScriptError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Parses a script; throws ScriptError at the first problem.
[[nodiscard]] Script parseScript(std::string_view text, const std::string& path);

// Reads and parses the file at path; a missing file is a ScriptError too.
[[nodiscard]] Script loadScript(const std::string& path);

}  // namespace onelight::replay
