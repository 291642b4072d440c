// The batch scripts of a Slurm bake, as written into WORK/scripts/ (and by --emit-scripts):
// shard.sh (one array task per shard: `onelight-bake slurm-task --shard $SLURM_ARRAY_TASK_ID`),
// merge.sh (`slurm-task --merge`) and submit.sh (the two sbatch calls, the merge after the whole
// array with afterok and --kill-on-invalid-dep=yes). The job options sit in #SBATCH lines; the
// array's indices and the dependency are given on sbatch's command line, as they change when a
// bake resumes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bake/slurm/work_folder.hpp"

namespace onelight::bake::slurm {

/// The job options every task of the bake asks for.
struct JobOptions {
    std::string partition;     // --partition; empty: the cluster's default
    std::string timeLimit;     // --time, as Slurm reads it ("30", "1:00:00", "1-0"); empty: none
    uint32_t cpusPerTask = 0;  // --cpus-per-task; 0: the cluster's default
};

struct BatchScripts {
    std::string shard, merge, submit;  // the text of each
};

/// The scripts for `work`: `bake` is the onelight-bake every node runs (an absolute path),
/// `output` the merged package, `shards` the array's indices to submit (submit.sh).
[[nodiscard]] BatchScripts batchScripts(const WorkFolder& work, const std::string& bake,
                                        const std::string& output, const JobOptions& options,
                                        const std::vector<uint32_t>& shards);

/// Writes shard.sh, merge.sh and submit.sh into `folder` (made if missing), each atomically and
/// executable. Throws world::Error.
void writeBatchScripts(const std::string& folder, const BatchScripts& scripts);

/// `text` in single quotes for bash.
[[nodiscard]] std::string shellQuoted(const std::string& text);

/// Slurm's --array list of `shards` (sorted): "0-3", "1,4-6".
[[nodiscard]] std::string arraySpec(const std::vector<uint32_t>& shards);

}  // namespace onelight::bake::slurm
