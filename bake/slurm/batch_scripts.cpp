#include "bake/slurm/batch_scripts.hpp"

#include <sys/stat.h>

#include <filesystem>

#include "world/error.hpp"
#include "world/file_write.hpp"

namespace onelight::bake::slurm {
namespace {

std::string sbatchLines(const std::string& jobName, const std::string& log,
                        const JobOptions& options) {
    std::string text = "#SBATCH --job-name=" + jobName + "\n#SBATCH --output=" + log + "\n";
    if (!options.partition.empty()) text += "#SBATCH --partition=" + options.partition + "\n";
    if (!options.timeLimit.empty()) text += "#SBATCH --time=" + options.timeLimit + "\n";
    if (options.cpusPerTask > 0)
        text += "#SBATCH --cpus-per-task=" + std::to_string(options.cpusPerTask) + "\n";
    return text;
}

}  // namespace

std::string shellQuoted(const std::string& text) {
    std::string quoted = "'";
    for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::string arraySpec(const std::vector<uint32_t>& shards) {
    std::string spec;
    for (size_t i = 0; i < shards.size();) {
        size_t j = i;
        while (j + 1 < shards.size() && shards[j + 1] == shards[j] + 1) ++j;
        if (!spec.empty()) spec += ',';
        spec += std::to_string(shards[i]);
        if (j > i) {
            spec += '-';
            spec += std::to_string(shards[j]);
        }
        i = j + 1;
    }
    return spec;
}

BatchScripts batchScripts(const WorkFolder& work, const std::string& bake,
                          const std::string& output, const JobOptions& options,
                          const std::vector<uint32_t>& shards) {
    BatchScripts s;
    // %a: the array task (the shard), %A: the array job, %j: the job.
    s.shard = "#!/bin/bash\n" +
              sbatchLines("onelight-shard", work.logs() + "/shard-%a.job-%A.log", options) +
              "# One shard of a onelight bake: array task I bakes --shard I/N of the level in\n"
              "# the manifest of the work folder (submit with sbatch --array=0-(N-1)).\n"
              "set -eu\n"
              "exec " +
              shellQuoted(bake) + " slurm-task --work " + shellQuoted(work.root) +
              " --shard \"$SLURM_ARRAY_TASK_ID\"\n";
    s.merge = "#!/bin/bash\n" +
              sbatchLines("onelight-merge", work.logs() + "/merge.job-%j.log", options) +
              "# The merge of a onelight bake's shards into the package, after every shard\n"
              "# (submit with --dependency=afterok:ARRAY_JOB --kill-on-invalid-dep=yes).\n"
              "set -eu\n"
              "exec " +
              shellQuoted(bake) + " slurm-task --work " + shellQuoted(work.root) + " --merge -o " +
              shellQuoted(output) + "\n";
    s.submit =
        "#!/bin/bash\n"
        "# Submits the shards as a job array and the merge after them; a failed shard\n"
        "# cancels the merge. Prints the two job ids.\n"
        "set -eu\n"
        "here=$(cd \"$(dirname \"$0\")\" && pwd)\n"
        "array=$(sbatch --parsable --array=" +
        arraySpec(shards) +
        " \"$here/shard.sh\")\n"
        "array=${array%%;*}\n"
        "merge=$(sbatch --parsable --dependency=afterok:$array --kill-on-invalid-dep=yes "
        "\"$here/merge.sh\")\n"
        "echo \"shards: job array $array; merge: job ${merge%%;*}\"\n";
    return s;
}

void writeBatchScripts(const std::string& folder, const BatchScripts& scripts) {
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (!std::filesystem::is_directory(folder))
        throw world::Error(folder + ": cannot make the folder (" + error.message() +
                           "); expected a writable folder for the batch scripts");
    const std::pair<const char*, const std::string*> files[] = {
        {"shard.sh", &scripts.shard}, {"merge.sh", &scripts.merge}, {"submit.sh", &scripts.submit}};
    for (const auto& [name, text] : files) {
        const std::string path = folder + "/" + name;
        world::writeFileAtomically(path, *text);
        if (chmod(path.c_str(), 0755) != 0)
            throw world::Error(path + ": cannot make it executable");
    }
}

}  // namespace onelight::bake::slurm
