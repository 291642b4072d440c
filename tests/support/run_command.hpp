// Running a command line from a test: its exit code and its output (stdout and stderr).
#pragma once

#include <string>

namespace onelight::test {

struct CommandResult {
    int exitCode = -1;   // -1 when it did not exit normally
    std::string output;  // stdout and stderr, interleaved as written
};

// Runs `commandLine` through /bin/sh with stderr joined to stdout and stdin empty
// (world/process/child_process.hpp).
CommandResult runCommand(const std::string& commandLine);

}  // namespace onelight::test
