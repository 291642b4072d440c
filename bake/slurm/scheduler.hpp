// What the Slurm bake asks the scheduler, through its client commands, each call bounded in
// time (runSchedulerCommand, world/process/child_process.hpp): submit the shard array and the merge
// (sbatch), the state of each shard's task (squeue, one line per array task; accounting, sacct, is
// not needed), the details of a failed task (scontrol show job: node, exit code, log) and
// cancelling a job (scancel).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "world/process/child_process.hpp"

namespace onelight::bake::slurm {

/// Seconds any one client command may take before it counts as an unreachable controller.
constexpr double kSchedulerTimeoutSeconds = 60.0;

/// The client commands the bake runs; throws world::Error naming the first one missing on PATH.
void requireSlurmClients();

/// Runs client command `argv` (argv[0] looked up on PATH) and waits at most `timeoutSeconds` for
/// it. Throws world::Error when it cannot be run or does not exit in time (it is then killed);
/// its exit code and output are the caller's to judge.
[[nodiscard]] world::ChildResult runSchedulerCommand(
    const std::vector<std::string>& argv, double timeoutSeconds = kSchedulerTimeoutSeconds);

/// sbatch --parsable [ARGUMENTS...] SCRIPT; returns the job id. Throws world::Error with
/// sbatch's own message when it refuses.
[[nodiscard]] std::string submitJob(const std::vector<std::string>& arguments,
                                    const std::string& script);

/// One task of an array job as squeue lists it.
struct TaskState {
    uint32_t shard = 0;  // the array index
    std::string state;   // PENDING, RUNNING, COMPLETED, FAILED, CANCELLED, TIMEOUT, ...
    std::string node;    // where it runs or ran; empty while pending
};

/// Parses `squeue -h -r --states=all -o "%K|%T|%N"` lines; skips lines that do not parse.
[[nodiscard]] std::vector<TaskState> parseTaskStates(const std::string& text);
/// The tasks of array job `jobId` that the controller still knows.
[[nodiscard]] std::vector<TaskState> queryArrayTasks(const std::string& jobId);

/// One job as `scontrol show job -o` prints it.
struct JobDetails {
    std::string state, reason, exitCode, node, log;  // JobState Reason ExitCode NodeList StdOut
};
/// Parses the first line of `scontrol show job -o` output (KEY=VALUE words).
[[nodiscard]] JobDetails parseJobDetails(const std::string& text);
/// The job, or an all-empty JobDetails when the controller no longer knows it.
[[nodiscard]] JobDetails queryJob(const std::string& jobId);

/// Whether a job in `state` has ended without success.
[[nodiscard]] bool failedState(const std::string& state);
/// Whether a job in `state` will not change any more.
[[nodiscard]] bool finalState(const std::string& state);

/// scancel JOB (an error of scancel's is ignored: the job may have ended meanwhile).
void cancelJob(const std::string& jobId);

}  // namespace onelight::bake::slurm
