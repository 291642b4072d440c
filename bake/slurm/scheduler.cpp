#include "bake/slurm/scheduler.hpp"

#include <sstream>

#include "world/error.hpp"
#include "world/file_read.hpp"

namespace onelight::bake::slurm {
namespace {

std::string firstLine(const std::string& text) {
    const std::string line = text.substr(0, text.find('\n'));
    return world::clipForMessage(line.empty() ? "(no message)" : line, 200);
}

}  // namespace

void requireSlurmClients() {
    for (const char* tool : {"sbatch", "squeue", "scontrol", "scancel"})
        if (!world::onPath(tool))
            throw world::Error(std::string(tool) +
                               ": not found on PATH; --slurm needs Slurm's client commands "
                               "(sbatch, squeue, scontrol, scancel: Debian's slurm-client)");
}

world::ChildResult runSchedulerCommand(const std::vector<std::string>& argv,
                                       double timeoutSeconds) {
    world::ChildOptions options;
    options.timeLimitSeconds = timeoutSeconds;
    world::ChildResult r = world::runChild(argv, options);
    if (!r.started)
        throw world::Error(firstLine(r.err) +
                           "; expected Slurm's client commands on PATH (package slurm-client)");
    if (r.timedOut)
        throw world::Error(argv[0] + ": no answer within " +
                           std::to_string(static_cast<int>(timeoutSeconds)) +
                           " s; is the Slurm controller up (scontrol ping)?");
    return r;
}

std::string submitJob(const std::vector<std::string>& arguments, const std::string& script) {
    std::vector<std::string> argv = {"sbatch", "--parsable"};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    argv.push_back(script);
    const world::ChildResult r = runSchedulerCommand(argv);
    // --parsable prints "JOBID" or "JOBID;CLUSTER".
    const std::string id = r.out.substr(0, r.out.find_first_of(";\n"));
    if (r.exitCode != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
        throw world::Error("sbatch " + script + ": refused (exit " + std::to_string(r.exitCode) +
                           "): " + firstLine(r.err.empty() ? r.out : r.err));
    return id;
}

std::vector<TaskState> parseTaskStates(const std::string& text) {
    std::vector<TaskState> tasks;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        const size_t a = line.find('|'), b = line.find('|', a + 1);
        if (a == std::string::npos || b == std::string::npos) continue;
        const std::string index = line.substr(0, a);
        if (index.empty() || index.find_first_not_of("0123456789") != std::string::npos) continue;
        TaskState t;
        try {
            t.shard = static_cast<uint32_t>(std::stoul(index));
        } catch (const std::exception&) {
            continue;
        }
        t.state = line.substr(a + 1, b - a - 1);
        t.node = line.substr(b + 1);
        while (!t.node.empty() && (t.node.back() == ' ' || t.node.back() == '\r'))
            t.node.pop_back();
        if (t.node == "(null)") t.node.clear();
        tasks.push_back(t);
    }
    return tasks;
}

std::vector<TaskState> queryArrayTasks(const std::string& jobId) {
    const world::ChildResult r =
        runSchedulerCommand({"squeue", "-h", "-r", "--states=all", "-j", jobId, "-o", "%K|%T|%N"});
    // A job the controller has forgotten: squeue says "Invalid job id" and exits non-zero.
    if (r.exitCode != 0) return {};
    return parseTaskStates(r.out);
}

JobDetails parseJobDetails(const std::string& text) {
    JobDetails d;
    std::istringstream words(text.substr(0, text.find('\n')));
    std::string word;
    while (words >> word) {
        const size_t eq = word.find('=');
        if (eq == std::string::npos) continue;
        const std::string key = word.substr(0, eq), value = word.substr(eq + 1);
        if (key == "JobState")
            d.state = value;
        else if (key == "Reason")
            d.reason = value;
        else if (key == "ExitCode")
            d.exitCode = value;
        else if (key == "NodeList")
            d.node = value == "(null)" ? "" : value;
        else if (key == "StdOut")
            d.log = value;
    }
    return d;
}

JobDetails queryJob(const std::string& jobId) {
    const world::ChildResult r = runSchedulerCommand({"scontrol", "show", "job", "-o", jobId});
    if (r.exitCode != 0) return {};
    return parseJobDetails(r.out);
}

bool failedState(const std::string& state) {
    for (const char* failed : {"FAILED", "CANCELLED", "TIMEOUT", "NODE_FAIL", "OUT_OF_MEMORY",
                               "BOOT_FAIL", "DEADLINE", "PREEMPTED", "REVOKED", "SPECIAL_EXIT"})
        if (state.rfind(failed, 0) == 0) return true;  // "CANCELLED by 0" counts
    return false;
}

bool finalState(const std::string& state) {
    return state == "COMPLETED" || failedState(state);
}

void cancelJob(const std::string& jobId) {
    (void)runSchedulerCommand({"scancel", jobId});
}

}  // namespace onelight::bake::slurm
