#include "bake/slurm/job_watch.hpp"

#include <chrono>
#include <map>
#include <thread>

namespace onelight::bake::slurm {
namespace {

void sleepOnePoll() {
    std::this_thread::sleep_for(std::chrono::duration<double>(kPollSeconds));
}

}  // namespace

std::vector<ShardFailure> watchShardArray(const WorkFolder& work, const Manifest& manifest,
                                          const std::string& arrayId,
                                          const std::vector<uint32_t>& shards,
                                          const std::function<void(uint32_t)>& baked,
                                          const std::function<void(const ShardFailure&)>& failed) {
    std::map<uint32_t, uint32_t> waiting;  // shard -> polls in a row it was missing
    for (const uint32_t s : shards) waiting[s] = 0;
    std::vector<ShardFailure> failures;
    auto fail = [&](uint32_t shard, const std::string& state) {
        ShardFailure f{shard, arrayId + "_" + std::to_string(shard), state, {}};
        f.details = queryJob(f.jobId);
        failures.push_back(f);
        failed(f);
        waiting.erase(shard);
    };
    while (!waiting.empty()) {
        std::map<uint32_t, TaskState> listed;
        for (const TaskState& t : queryArrayTasks(arrayId)) listed[t.shard] = t;
        for (auto it = waiting.begin(); it != waiting.end();) {
            const uint32_t shard = it->first;
            uint32_t& patience = it->second;
            const auto task = listed.find(shard);
            const std::string state = task == listed.end() ? "" : task->second.state;
            ++it;  // `fail` and the erase below remove the shard's entry, never the next one
            // A task that ended well, or one the controller has forgotten, is baked when its
            // stamp verifies; a shared filesystem may show the stamp a little after the task
            // ends, so both wait kForgottenPolls polls before they count as failed.
            if (state == "COMPLETED" || state.empty()) {
                if (verifiedShard(work, manifest, shard)) {
                    baked(shard);
                    waiting.erase(shard);
                } else if (++patience >= kForgottenPolls) {
                    fail(shard, state.empty()
                                    ? "lost: the controller no longer lists its task"
                                    : "COMPLETED, but its package does not verify (checksum, "
                                      "level or settings)");
                }
            } else if (failedState(state)) {
                fail(shard, state);
            } else {
                patience = 0;
            }
        }
        if (!waiting.empty()) sleepOnePoll();
    }
    return failures;
}

JobDetails waitForJob(const std::string& jobId, double limitSeconds) {
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(limitSeconds);
    for (;;) {
        const JobDetails d = queryJob(jobId);
        if (d.state.empty() || finalState(d.state) || std::chrono::steady_clock::now() > deadline)
            return d;
        sleepOnePoll();
    }
}

std::string describeFailure(const ShardFailure& f) {
    std::string text = "shard " + std::to_string(f.shard) + " (job " + f.jobId + ") failed";
    text += f.details.node.empty() ? "" : " on node " + f.details.node;
    text +=
        " (" + f.state + (f.details.exitCode.empty() ? "" : ", exit " + f.details.exitCode) + ")";
    text += f.details.log.empty() ? "" : "; its log: " + f.details.log;
    return text;
}

}  // namespace onelight::bake::slurm
