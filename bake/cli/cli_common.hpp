// What the onelight-bake subcommands share: the one way a command line is parsed (by the
// command's option table, world/command_options.hpp) and refused ("onelight-bake: error: ...",
// exit code 2), and the one way a failure inside a command becomes an error line and exit code 1.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "world/command_options.hpp"

namespace onelight::bake {

/// What LEVEL may be, for every subcommand's help.
inline const std::string kLevelMeaning =
    "LEVEL: a glTF (.gltf, .glb), a Quake 3 map (.bsp), PAK.pk3:maps/NAME.bsp, or the NAME of an "
    "installed OpenArena or Nexuiz map";

/// --patch-level N: how finely a Quake 3 map's curved patches are tessellated (the bake, compile
/// and reference take it).
[[nodiscard]] world::CommandOption patchLevelOption();

/// Parses `arguments` with `table` and hands them to `run`, returning its exit code. -h or --help
/// prints `help` (the table's own when empty) on stdout: exit code 0. A world::Error while parsing
/// or inside `run` (a combination refused) becomes "onelight-bake: error: ..." on stderr, exit
/// code 2; `run` reports the failures of the work itself (runReportingErrors).
[[nodiscard]] int runCommandLine(const world::CommandTable& table,
                                 const std::vector<std::string>& arguments,
                                 const std::function<int(const world::ParsedOptions&)>& run,
                                 const std::string& help = "");

/// Runs `command` and returns its exit code; an exception becomes "onelight-bake: error: ..."
/// on stderr and exit code 1: a world::Error as its message (it names file and place),
/// anything else prefixed with `input`, running out of memory as "out of memory".
[[nodiscard]] int runReportingErrors(const std::string& input, const std::function<int()>& command);

}  // namespace onelight::bake
