// What the onelight-bake subcommands share: number parsing for options and the one way a
// failure inside a command becomes an error line and exit code 1.
#pragma once

#include <functional>
#include <string>

namespace onelight::bake {

/// The whole of `text` as a number in [low, high]; false otherwise (no partial parses).
bool parse_number(const std::string& text, double low, double high, double& out);

/// Runs `command` and returns its exit code; an exception becomes "onelight-bake: error: ..."
/// on stderr and exit code 1: a world::CompileError as its message (it names file and place),
/// anything else prefixed with `input`, running out of memory as "out of memory".
int run_reporting_errors(const std::string& input, const std::function<int()>& command);

}  // namespace onelight::bake
