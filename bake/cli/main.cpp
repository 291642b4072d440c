// onelight-bake SUBCOMMAND ...: dispatches to the subcommand; anything else is the bake's command
// line (bake_plan.hpp).
#include <cstdio>
#include <string>
#include <vector>

#include "bake/cli/bake_plan.hpp"
#include "bake/cli/subcommands.hpp"
#include "bake/report/interrupt.hpp"

namespace {

struct Subcommand {
    const char* name;
    int (*run)(const std::vector<std::string>&);
    std::string (*usage)();
};

constexpr Subcommand kSubcommands[] = {
    {"compile", &onelight::bake::runCompileCommand, &onelight::bake::compileUsage},
    {"reference", &onelight::bake::runReferenceCommand, &onelight::bake::referenceUsage},
    {"merge", &onelight::bake::runMergeCommand, &onelight::bake::mergeUsage},
    {"export", &onelight::bake::runExportCommand, &onelight::bake::exportUsage},
    {"slurm-task", &onelight::bake::runSlurmTaskCommand, &onelight::bake::slurmTaskUsage},
};

// Every command's help: the bake, then each subcommand.
std::string usage() {
    std::string text = onelight::bake::bakeUsage() + '\n' + onelight::bake::slurmUsage();
    for (const Subcommand& s : kSubcommands) {
        text += '\n';
        text += s.usage();
    }
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    onelight::bake::installInterruptHandler("onelight-bake");
    if (argc < 2) {
        std::fprintf(stderr,
                     "onelight-bake: error: no level or subcommand given (onelight-bake --help "
                     "lists them)\n");
        return 2;
    }
    const std::string name = argv[1];
    if (name == "-h" || name == "--help") {
        std::printf("%s", usage().c_str());
        return 0;
    }
    const std::vector<std::string> arguments(argv + 2, argv + argc);
    for (const Subcommand& s : kSubcommands)
        if (name == s.name) return s.run(arguments);
    return onelight::bake::runBakeCommand({argv + 1, argv + argc});
}
