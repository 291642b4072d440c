#include "run_command.hpp"

#include "world/process/child_process.hpp"

namespace onelight::test {

CommandResult runCommand(const std::string& commandLine) {
    world::ChildOptions merged;
    merged.err = world::ChildStream::kIntoStdout;
    world::ChildResult r = world::runChild({"/bin/sh", "-c", commandLine}, merged);
    return {r.exitCode, std::move(r.out)};
}

}  // namespace onelight::test
