// Runs the engine's other programs as child processes (the lab links no renderer and no baker):
// argv straight to execv, no shell, output appended to a log file.
#pragma once

#include <string>
#include <vector>

namespace onelight::lab {

struct ChildRun {
    int exitCode = -1;     // -1 when it did not exit normally
    double seconds = 0.0;  // wall time from start to exit
};

// Runs `argv` (argv[0] a path), its stdout and stderr appended to `logPath`; waits for it.
// Throws std::runtime_error when it cannot be started.
[[nodiscard]] ChildRun runChild(const std::vector<std::string>& argv, const std::string& logPath);

// The path of `name` in the folder of this process's own executable (/proc/self/exe), where
// the build and an install put onelight, onelight-bake and onelight-lab side by side.
[[nodiscard]] std::string siblingExecutable(const std::string& name);

// The last `lines` lines of a text file, for an error message ("" when it cannot be read).
[[nodiscard]] std::string tailOfFile(const std::string& path, int lines);

}  // namespace onelight::lab
