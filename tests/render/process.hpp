// Running the onelight executable from a test: exit code and captured stderr.
#pragma once

#include <string>
#include <vector>

namespace onelight::test {

struct ProcessResult {
    int exitCode = -1;  // -1 when killed by a signal or not run
    bool signalled = false;
    std::string stderrText;
};

/// Runs `program args...` (no shell), stdout discarded, stderr captured.
ProcessResult runProcess(const std::string& program, const std::vector<std::string>& args);

}  // namespace onelight::test
