// The subcommands of onelight-bake; each takes its arguments (after the subcommand name) and
// returns the process exit code: 0 success, 1 bad input or failure, 2 bad command line.
#pragma once

#include <string>
#include <vector>

namespace onelight::bake {

int run_compile_command(const std::vector<std::string>& arguments);
int run_bake_command(const std::vector<std::string>& arguments);       // LEVEL.gltf -o ...
int run_reference_command(const std::vector<std::string>& arguments);  // reference ...
int run_merge_command(const std::vector<std::string>& arguments);      // merge ...

// Each subcommand's help: synopsis, summary, every option with its default (-h or --help).
std::string compile_usage();
std::string bake_usage();
std::string reference_usage();
std::string merge_usage();

}  // namespace onelight::bake
