// `onelight LEVEL --replay SCRIPT [--headless] --capture-dir DIR`: plays a replay script on the
// fixed tick and writes its captures (NAME.png, NAME.exr, NAME.json) and a contact sheet of
// them all (contact_sheet.png). Headless, frames are rendered only where the script captures;
// in a window every tick is shown.
#pragma once

#include "assets/level_assets.hpp"
#include "command_line.hpp"

namespace onelight::game {

// Returns the process exit code: 0, or 1 after printing the failed line (`file:line: ...`).
[[nodiscard]] int runReplay(const CommandLine& commandLine, const assets::LoadedLevel& level);

}  // namespace onelight::game
