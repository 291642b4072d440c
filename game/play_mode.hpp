// `onelight LEVEL` in a window: the game itself, the player walking the level (WASD, mouse look,
// space jumps, F the flashlight, the left button fires, Esc quits) on the fixed 60 Hz tick
// whatever the frame rate.
#pragma once

#include "assets/level_assets.hpp"
#include "command_line.hpp"

namespace onelight::game {

// Returns the process exit code.
[[nodiscard]] int runPlay(const CommandLine& commandLine, const assets::LoadedLevel& level);

}  // namespace onelight::game
