// The subcommands of onelight-bake; each takes its arguments (after the subcommand name) and
// returns the process exit code: 0 success, 1 bad input or failure, 2 bad command line.
#pragma once

#include <string>
#include <vector>

namespace onelight::bake {

[[nodiscard]] int runCompileCommand(const std::vector<std::string>& arguments);
[[nodiscard]] int runBakeCommand(const std::vector<std::string>& arguments);       // LEVEL -o ...
[[nodiscard]] int runReferenceCommand(const std::vector<std::string>& arguments);  // reference ...
[[nodiscard]] int runMergeCommand(const std::vector<std::string>& arguments);      // merge ...
[[nodiscard]] int runExportCommand(const std::vector<std::string>& arguments);     // export ...
// LEVEL -o OUT --slurm N ...: the bake of `plan` (its slurm part set) as a Slurm job array of
// shards and a merge job; the command line's plan made by runBakeCommand.
struct BakePlan;
[[nodiscard]] int runSlurmBake(BakePlan& plan);
// slurm-task --work DIR (--shard I | --merge -o OUT): what a Slurm job of that bake runs.
[[nodiscard]] int runSlurmTaskCommand(const std::vector<std::string>& arguments);

// Each subcommand's help: synopsis, summary, every option with its default (-h or --help);
// the bake's and the Slurm bake's: bake_plan.hpp.
[[nodiscard]] std::string compileUsage();
[[nodiscard]] std::string referenceUsage();
[[nodiscard]] std::string mergeUsage();
[[nodiscard]] std::string exportUsage();
[[nodiscard]] std::string slurmTaskUsage();

}  // namespace onelight::bake
