// The subcommands of onelight-bake; each takes its arguments (after the subcommand name) and
// returns the process exit code: 0 success, 1 bad input or failure, 2 bad command line.
#pragma once

#include <string>
#include <vector>

namespace onelight::bake {

int runCompileCommand(const std::vector<std::string>& arguments);
int runBakeCommand(const std::vector<std::string>& arguments);       // LEVEL.gltf -o ...
int runReferenceCommand(const std::vector<std::string>& arguments);  // reference ...
int runMergeCommand(const std::vector<std::string>& arguments);      // merge ...

// Each subcommand's help: synopsis, summary, every option with its default (-h or --help).
std::string compileUsage();
std::string bakeUsage();
std::string referenceUsage();
std::string mergeUsage();

}  // namespace onelight::bake
