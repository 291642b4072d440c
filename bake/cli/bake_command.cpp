// onelight-bake LEVEL -o LEVEL.olpak [OPTIONS] (bake_plan.hpp: its table, help and plan).
// Compiles and bakes in one go: progress bars with ETA on stderr, a summary on stdout. --sky
// overrides the level's uniform sky (extras.onelight.sky).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>

#include <tbb/global_control.h>

#include "bake/bake_level.hpp"
#include "bake/cli/bake_command_line.hpp"
#include "bake/cli/cli_common.hpp"
#include "bake/cli/subcommands.hpp"
#include "bake/report/interrupt.hpp"
#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/file_write.hpp"
#include "world/import/level_import.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::bake {

BakeReport bakeAndWritePackage(const world::SourceLevel& source, const BakePlan& plan) {
    world::refuseOutputOverInput(plan.output, source.inputFiles);
    noteStage("compiling the level");
    BakeResult result = bakeLevel(source, plan.options);
    noteStage("writing the package");
    package::placeImagesForPackage(result.level, plan.output);
    writeBakedPackage(plan, result.level, result.baked, result.textures, result.report);
    return result.report;
}

void writeBakedPackage(const BakePlan& plan, const world::CompiledLevel& level,
                       const world::BakedLighting& baked, const world::ProcessedTextures& textures,
                       BakeReport& report) {
    const BakeOptions& options = plan.options;
    const std::vector<uint8_t> bytes = packageBytes(level, baked, textures);
    report.packageBytes = bytes.size();
    if (!plan.reportPath.empty()) writeReport(plan.reportPath, report);
    // The package last, and whole: an interrupt from here on is ignored (interrupt.hpp).
    ignoreInterrupts();
    world::writeFileAtomically(plan.output, bytes);
    std::printf("baked %s (%zu bytes, quality %s%s)\n", plan.output.c_str(), bytes.size(),
                qualityName(options.quality),
                options.shardCount > 1 ? (", shard " + std::to_string(options.shardIndex) + "/" +
                                          std::to_string(options.shardCount))
                                             .c_str()
                                       : "");
    std::printf("%s", reportSummary(report).c_str());
    for (const std::string& line : report.lightSources)
        std::printf("%s: %s\n", plan.input.c_str(), line.c_str());
    for (const std::string& warning : report.warnings)
        std::fprintf(stderr, "onelight-bake: warning: %s: %s\n", plan.input.c_str(),
                     warning.c_str());
}

int runBakeCommand(const std::vector<std::string>& arguments) {
    const bool slurm = std::find(arguments.begin(), arguments.end(), "--slurm") != arguments.end();
    return runCommandLine(
        bakeCommandTable(), arguments,
        [](const world::ParsedOptions& parsed) {
            BakePlan plan = resolveBakePlan(parsed);
            // --threads: with --slurm the compile's on this machine (the shards take
            // --cpus-per-task).
            std::unique_ptr<tbb::global_control> limit;
            if (plan.threads > 0)
                limit = std::make_unique<tbb::global_control>(
                    tbb::global_control::max_allowed_parallelism,
                    static_cast<size_t>(plan.threads));
            if (plan.slurm)
                return runReportingErrors(plan.input, [&] { return runSlurmBake(plan); });
            return runReportingErrors(plan.input, [&] {
                noteStage("importing the level");
                const world::SourceLevel source = world::importLevel(plan.input, plan.quake3);
                (void)bakeAndWritePackage(source, plan);
                return 0;
            });
        },
        slurm ? slurmUsage() : bakeUsage());
}

}  // namespace onelight::bake
