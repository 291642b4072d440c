// Running another program as a child process, the one way every part of onelight does it (the
// game runs onelight-bake, the Slurm bake runs sbatch/squeue/scontrol/scancel, the lab runs the
// baker and the runtime, the tests run all three): argv straight to the program (no shell; a
// name without '/' is looked up on PATH), standard input from /dev/null, each output stream
// captured, merged, passed through or discarded, an optional time limit, and every read, poll
// and wait retried when a signal interrupts it.
#pragma once

#include <string>
#include <vector>

namespace onelight::world {

/// Where one of the child's output streams goes.
enum class ChildStream {
    kCapture,     // into ChildResult::out (stdout) or ::err (stderr)
    kInherit,     // this process's own stream (a terminal shows it as it comes)
    kDiscard,     // /dev/null
    kIntoStdout,  // stderr only: wherever stdout goes, interleaved as written
};

struct ChildOptions {
    ChildStream out = ChildStream::kCapture;  // the child's stdout
    ChildStream err = ChildStream::kCapture;  // the child's stderr
    double timeLimitSeconds = 0.0;            // killed (SIGKILL) after this long; 0: no limit
    bool killProcessGroup = false;  // the child leads a process group of its own, and the time
                                    // limit kills the whole group (a shell and what it started)
};

struct ChildResult {
    int exitCode = -1;  // its exit status when it exited; 127 when it could not be started
    int signal = 0;     // the signal that ended it (SIGKILL at the time limit); 0 when it exited
    bool timedOut = false;  // killed at the time limit
    bool started = true;    // false: the program could not be run (missing, not executable); the
                            // reason, "PROGRAM: cannot run it (...)", went where its stderr goes
    std::string out;        // its stdout when captured (with stderr when that is kIntoStdout)
    std::string err;        // its stderr when captured
};

/// Runs `argv` (argv[0] the program) and waits for it, or for the time limit. Throws
/// world::Error naming the program when it cannot even try (no program, a pipe or the process
/// could not be created); a program that cannot be run is a result (started false, exit 127).
[[nodiscard]] ChildResult runChild(const std::vector<std::string>& argv,
                                   const ChildOptions& options = {});

/// How the run ended, for a message: "exit 3", "killed by signal 9 (Killed)", "killed at its
/// time limit", "could not be started".
[[nodiscard]] std::string describeEnd(const ChildResult& result);

/// Whether `name` is an executable file in one of PATH's folders.
[[nodiscard]] bool onPath(const std::string& name);

/// This process's own executable (/proc/self/exe). Throws world::Error when it cannot be read.
[[nodiscard]] std::string ownExecutable();

/// The path of `name` in the folder of this process's own executable, where the build and an
/// install put onelight, onelight-bake and onelight-lab side by side. Whether it exists is the
/// caller's to check (with a message that says what to build).
[[nodiscard]] std::string executableBeside(const std::string& name);

}  // namespace onelight::world
