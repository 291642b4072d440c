// Waiting for the jobs of a Slurm bake: the shard array's tasks until every one has ended
// (squeue once a poll; a task counts as baked only when its stamp verifies), then the merge job
// (scontrol). Every wait is bounded: each client call by kSchedulerTimeoutSeconds, a task the
// controller has forgotten by kForgottenPolls, a merge that never ends by the caller's limit.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bake/slurm/scheduler.hpp"
#include "bake/slurm/work_folder.hpp"

namespace onelight::bake::slurm {

/// Seconds between two polls of the scheduler.
constexpr double kPollSeconds = 1.0;
/// Polls in a row that a task may be missing from squeue, or have completed without a stamp
/// that verifies yet, before it counts as failed.
constexpr uint32_t kForgottenPolls = 10;

/// A shard whose task ended without a verified package.
struct ShardFailure {
    uint32_t shard = 0;
    std::string jobId;   // ARRAY_INDEX
    std::string state;   // FAILED, TIMEOUT, ..., or what else went wrong
    JobDetails details;  // from scontrol: node, exit code, log (empty fields when forgotten)
};

/// Waits until every task of array job `arrayId` (one per shard of `shards`) has ended. Calls
/// `baked(shard)` once per shard as its stamp verifies and `failed(failure)` once per shard as
/// its task fails; returns the failures.
[[nodiscard]] std::vector<ShardFailure> watchShardArray(
    const WorkFolder& work, const Manifest& manifest, const std::string& arrayId,
    const std::vector<uint32_t>& shards, const std::function<void(uint32_t)>& baked,
    const std::function<void(const ShardFailure&)>& failed);

/// Waits until job `jobId` has ended, at most `limitSeconds`; its last details (state empty
/// when the controller has forgotten it, "PENDING"/"RUNNING" when the limit passed).
[[nodiscard]] JobDetails waitForJob(const std::string& jobId, double limitSeconds);

/// "shard 2 failed on node n1 (FAILED, exit 1:0); its log: PATH".
[[nodiscard]] std::string describeFailure(const ShardFailure& failure);

}  // namespace onelight::bake::slurm
