#include "run_command.hpp"

#include <sys/wait.h>

#include <cstdio>

namespace onelight::test {

CommandResult runCommand(const std::string& commandLine) {
    std::string command = commandLine + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return {-1, "cannot run: " + commandLine};
    std::string out;
    char buffer[4096];
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
    int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

}  // namespace onelight::test
