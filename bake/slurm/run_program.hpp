// Running the scheduler's client programs (sbatch, squeue, scontrol, scancel) with a bound on
// the wait: a controller that does not answer becomes an error, never a hang.
#pragma once

#include <string>
#include <vector>

namespace onelight::bake::slurm {

struct ProgramResult {
    int exitCode = -1;  // -1 when it did not exit normally
    std::string out;    // its standard output
    std::string err;    // its standard error
};

/// Whether `name` is an executable file in one of PATH's folders.
[[nodiscard]] bool onPath(const std::string& name);

/// Runs `argv` (argv[0] looked up on PATH) with no standard input and waits at most
/// `timeoutSeconds` for it to exit. Throws world::Error when it cannot start or does not exit in
/// time (it is then killed).
[[nodiscard]] ProgramResult runProgram(const std::vector<std::string>& argv, double timeoutSeconds);

}  // namespace onelight::bake::slurm
