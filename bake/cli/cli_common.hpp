// What the onelight-bake subcommands share: number parsing for options and the one way a
// failure inside a command becomes an error line and exit code 1.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "world/compiled_level.hpp"
#include "world/import/q3/q3_import.hpp"

namespace onelight::bake {

/// One option of a subcommand, as its help lists it.
struct CliOption {
    std::string flag;          // e.g. "--quality Q"
    std::string meaning;       // what it sets
    std::string defaultValue;  // what applies without it; kRequired, or "" for none (-h)
};
inline const std::string kRequired = "required";

/// A subcommand's help: the synopsis, what it does, then every option with its default, one a
/// line, aligned.
[[nodiscard]] std::string formatUsage(const std::string& synopsis, const std::string& summary,
                                      const std::vector<CliOption>& options);

/// What LEVEL may be, for every subcommand's help.
inline const std::string kLevelMeaning =
    "LEVEL: a glTF (.gltf, .glb), a Quake 3 map (.bsp), PAK.pk3:maps/NAME.bsp, or the NAME of an "
    "installed OpenArena map";

/// --patch-level N: how finely a Quake 3 map's curved patches are tessellated.
[[nodiscard]] CliOption patchLevelOption();

/// Reads --patch-level's value into `options`; false (and `options` unchanged) unless it is an
/// integer in [1, 64].
[[nodiscard]] bool parsePatchLevel(const std::string& text, world::Quake3Options& options);

/// `value` as the shortest text that reads it back ("%g").
[[nodiscard]] std::string formatNumber(double value);

/// When `arguments` ask for help (-h or --help anywhere), prints `usage` on stdout and returns
/// true: the command then exits 0.
[[nodiscard]] bool printedHelp(const std::vector<std::string>& arguments, const std::string& usage);

/// The whole of `text` as a number in [low, high]; false otherwise (no partial parses).
[[nodiscard]] bool parseNumber(const std::string& text, double low, double high, double& out);

/// Runs `command` and returns its exit code; an exception becomes "onelight-bake: error: ..."
/// on stderr and exit code 1: a world::Error as its message (it names file and place),
/// anything else prefixed with `input`, running out of memory as "out of memory".
[[nodiscard]] int runReportingErrors(const std::string& input, const std::function<int()>& command);

}  // namespace onelight::bake
