// The bake's command line (onelight-bake LEVEL [-o LEVEL.olpak] [OPTIONS] [--slurm N ...]) as one
// option table, and the plan resolved from it once, before anything is imported, compiled or
// submitted: the quality preset expanded into its settings, the error budget, the shards, the
// threads, the paths, and for a Slurm bake its jobs and the options every shard task is given.
// Combinations that cannot work are refused there. The local bake, the Slurm submission and the
// Slurm shard task all resolve their plan here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bake/bake_level.hpp"
#include "bake/cli/cli_common.hpp"
#include "bake/grid/light_grid.hpp"
#include "bake/lightmap/lightmap_bake.hpp"
#include "bake/probes/probe_capture.hpp"
#include "bake/slurm/batch_scripts.hpp"
#include "bake/slurm/work_folder.hpp"
#include "world/command_options.hpp"
#include "world/import/q3/q3_import.hpp"

namespace onelight::bake {

/// Every option of the bake, the Slurm bake's own included, each marked as given to every
/// Slurm shard task (it changes the shards' bytes) or as the submitting command's: help,
/// parsing and the shards' arguments all come from it.
[[nodiscard]] const world::CommandTable& bakeCommandTable();

/// The help of the bake (its options without the Slurm ones) and of the Slurm bake (those).
[[nodiscard]] std::string bakeUsage();
[[nodiscard]] std::string slurmUsage();

/// A Slurm bake's jobs (LEVEL -o OUT --slurm N).
struct SlurmPlan {
    uint32_t shards = 0;
    slurm::JobOptions job;
    std::string work;         // empty: OUT with .slurm
    std::string emitScripts;  // only write the batch scripts there
    uint32_t retries = 0;
    bool wait = true;
    std::vector<std::string> shardArguments;  // what every shard task bakes with (the table's
                                              // kToShards options as given)
};

/// The bake, resolved once from its parsed command line and checked.
struct BakePlan {
    std::string input, output, reportPath;  // output: LEVEL with .olpak when -o is not given
    BakeOptions options;
    world::Quake3Options quake3;
    int threads = 0;  // 0: every core
    // The quality preset expanded, its overrides applied: what the stages will use.
    LightmapSettings lightmap;
    GridSettings grid;
    ProbeCaptureSettings probes;
    std::optional<SlurmPlan> slurm;  // --slurm N
};

/// The plan of `parsed` (bakeCommandTable()'s). Throws world::Error, naming the options, on a
/// combination that cannot work: an error budget with --shard or --slurm (a budget's choices
/// need the whole level), --shard with --slurm, a Slurm option without --slurm, --retries
/// where nothing waits to resubmit.
[[nodiscard]] BakePlan resolveBakePlan(const world::ParsedOptions& parsed);

/// parseOptions(bakeCommandTable(), arguments), then resolveBakePlan (help not asked).
[[nodiscard]] BakePlan bakePlanOf(const std::vector<std::string>& arguments);

/// The arguments a Slurm shard task bakes part `shard` of `work` with: the level, its part's
/// package and report, --shard I/N, --quiet, and the manifest's forwarded options.
[[nodiscard]] std::vector<std::string> shardTaskArguments(const slurm::WorkFolder& work,
                                                          const slurm::Manifest& manifest,
                                                          uint32_t shard);

}  // namespace onelight::bake
