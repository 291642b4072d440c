// onelight-bake LEVEL -o LEVEL.olpak [OPTIONS] (bakeUsage lists them with their defaults).
// Compiles and bakes in one go: progress bars with ETA on stderr, a summary on stdout. --sky
// overrides the level's uniform sky (extras.onelight.sky).
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
namespace {

int badArgument(const std::string& what) {
    std::fprintf(stderr, "onelight-bake: %s\n%s", what.c_str(), bakeUsage().c_str());
    return 2;
}

}  // namespace

std::string bakeUsage() {
    const BakeOptions d;
    const world::ChartOptions& charts = d.compile.charts;
    return formatUsage(
        "onelight-bake LEVEL [-o LEVEL.olpak] [OPTIONS]",
        "compiles LEVEL and bakes its lighting: progress on stderr, a summary on stdout\n  " +
            kLevelMeaning,
        {{"-o PATH", "the package to write", "LEVEL with the extension .olpak"},
         {"--quality Q", "draft, default or high", qualityName(d.quality)},
         {"--threads N", "worker threads, 1..1024", "every core"},
         {"--report PATH", "a JSON report of every stage", "none"},
         {"--shard i/N", "bake part i of N (join them with merge)", "the whole level"},
         {"--sky CD_PER_M2", "a uniform sky's radiance", "the level's extras.onelight.sky, or 0"},
         {"--grid-cell M", "the light grid's cell size in metres", formatNumber(d.gridCellSize)},
         {"--texels-per-metre N", "lightmap density, 0.01..1024",
          "the level's, or " + formatNumber(charts.texelsPerMetre)},
         patchLevelOption(),
         {"--probe-spacing M", "metres between automatic probes, 0.25..1000",
          "the level's extras.onelight.probe_spacing, or " + formatNumber(d.probeSpacing)},
         {"--probe-face-size N", "texels per probe cube face, a power of two 4..512",
          "draft 32, default 64, high 128"},
         {"--error-budget E",
          "leave out what the level's views are predicted not to need for a "
          "mean 8x8-block error of at most E, a fraction in (0, 1] or a percentage (5%)",
          "everything baked"},
         {"--all-lights", "every light with its own shadow rays at every point (slow)",
          "lights drawn by importance"},
         {"--paths-only", "whole paths for the indirect light, no cached bounces (slow)",
          "cached bounce passes"},
         {"--no-denoise", "the lightmaps' indirect light as estimated, unfiltered", "denoised"},
         {"--uniform-density", "every chart at the requested density",
          "fewer texels on charts whose light a pilot pass finds smooth"},
         {"--quiet", "no progress bars", "bars on a terminal"},
         {"--slurm N", "bake on a Slurm cluster as N shards (its options: --slurm 1 --help)",
          "this machine"},
         {"-h, --help", "this help", ""}});
}

bool parseBakeCommandLine(const std::vector<std::string>& arguments, BakeCommandLine& line) {
    auto bad = [](const std::string& what) {
        (void)badArgument(what);
        return false;
    };
    BakeOptions& options = line.options;
    options.adaptiveDensity = true;
    for (size_t i = 0; i < arguments.size(); ++i) {
        const std::string& a = arguments[i];
        const bool hasValue = i + 1 < arguments.size();
        double v = 0.0;
        if (a == "-o" && hasValue) {
            line.output = arguments[++i];
        } else if (a == "--quality" && hasValue) {
            if (!parseQuality(arguments[++i], options.quality))
                return bad("--quality '" + arguments[i] + "'; expected draft, default or high");
        } else if (a == "--threads" && hasValue) {
            if (!parseNumber(arguments[++i], 1, 1024, v))
                return bad("--threads '" + arguments[i] + "'; expected 1..1024");
            line.threads = static_cast<int>(v);
        } else if (a == "--report" && hasValue) {
            line.reportPath = arguments[++i];
        } else if (a == "--shard" && hasValue) {
            const std::string s = arguments[++i];
            const size_t slash = s.find('/');
            double index = 0, count = 0;
            if (slash == std::string::npos || !parseNumber(s.substr(0, slash), 0, 65535, index) ||
                !parseNumber(s.substr(slash + 1), 1, 65536, count) || index >= count)
                return bad("--shard '" + s + "'; expected i/N with 0 <= i < N");
            options.shardIndex = static_cast<uint32_t>(index);
            options.shardCount = static_cast<uint32_t>(count);
        } else if (a == "--sky" && hasValue) {
            if (!parseNumber(arguments[++i], 0, 1e9, v))
                return bad("--sky '" + arguments[i] + "'; expected cd/m^2 >= 0");
            options.skyRadiance = glm::vec3(static_cast<float>(v));
        } else if (a == "--grid-cell" && hasValue) {
            if (!parseNumber(arguments[++i], 0.05, 1000, v))
                return bad("--grid-cell '" + arguments[i] + "'; expected metres");
            options.gridCellSize = static_cast<float>(v);
        } else if (a == "--texels-per-metre" && hasValue) {
            if (!parseNumber(arguments[++i], 0.01, 1024, v))
                return bad("--texels-per-metre '" + arguments[i] +
                           "'; expected a number in [0.01, 1024]");
            options.compile.charts.texelsPerMetre = v;
            options.compile.charts.densityFromCommandLine = true;
        } else if (a == "--patch-level" && hasValue) {
            if (!parsePatchLevel(arguments[++i], line.quake3))
                return bad("--patch-level '" + arguments[i] + "'; expected an integer in [1, 64]");
        } else if (a == "--probe-spacing" && hasValue) {
            if (!parseNumber(arguments[++i], 0.25, 1000, v))
                return bad("--probe-spacing '" + arguments[i] +
                           "'; expected metres in [0.25, 1000]");
            options.probeSpacing = static_cast<float>(v);
            options.probeSpacingOverridesLevel = true;
        } else if (a == "--probe-face-size" && hasValue) {
            if (!parseNumber(arguments[++i], 4, 512, v) || v != std::floor(v) ||
                (uint32_t(v) & (uint32_t(v) - 1)) != 0)
                return bad("--probe-face-size '" + arguments[i] +
                           "'; expected a power of two in [4, 512]");
            options.probeFaceSize = static_cast<uint32_t>(v);
        } else if (a == "--error-budget" && hasValue) {
            std::string text = arguments[++i];
            const bool percentage = !text.empty() && text.back() == '%';
            if (percentage) text.pop_back();
            if (!parseNumber(text, 0, percentage ? 100 : 1, v) || !(v > 0.0))
                return bad("--error-budget '" + arguments[i] +
                           "'; expected a fraction in (0, 1] or a percentage in (0%, 100%]");
            options.errorBudget = static_cast<float>(percentage ? v / 100.0 : v);
        } else if (a == "--quiet") {
            options.showProgress = false;
        } else if (a == "--all-lights") {
            options.allLights = true;
        } else if (a == "--paths-only") {
            options.pathsOnly = true;
        } else if (a == "--no-denoise") {
            options.noDenoise = true;
        } else if (a == "--uniform-density") {
            options.adaptiveDensity = false;
        } else if (!a.empty() && a[0] != '-' && line.input.empty()) {
            line.input = a;
        } else {
            return bad("unexpected argument '" + a + "'");
        }
    }
    if (line.input.empty()) return bad("no level given");
    if (options.errorBudget > 0.0f && options.shardCount > 1)
        return bad(
            "--error-budget with --shard: a budget's choices need the whole level; bake "
            "it whole");
    if (line.output.empty()) line.output = world::defaultPackagePath(line.input);
    return true;
}

BakeReport bakeAndWritePackage(const world::SourceLevel& source, const BakeCommandLine& line) {
    world::refuseOutputOverInput(line.output, source.inputFiles);
    noteStage("compiling the level");
    BakeResult result = bakeLevel(source, line.options);
    noteStage("writing the package");
    package::placeImagesForPackage(result.level, line.output);
    writeBakedPackage(line, result.level, result.baked, result.textures, result.report);
    return result.report;
}

void writeBakedPackage(const BakeCommandLine& line, const world::CompiledLevel& level,
                       const world::BakedLighting& baked, const world::ProcessedTextures& textures,
                       BakeReport& report) {
    const BakeOptions& options = line.options;
    const std::vector<uint8_t> bytes = packageBytes(level, baked, textures);
    report.packageBytes = bytes.size();
    if (!line.reportPath.empty()) writeReport(line.reportPath, report);
    // The package last, and whole: an interrupt from here on is ignored (interrupt.hpp).
    ignoreInterrupts();
    world::writeFileAtomically(line.output, bytes);
    std::printf("baked %s (%zu bytes, quality %s%s)\n", line.output.c_str(), bytes.size(),
                qualityName(options.quality),
                options.shardCount > 1 ? (", shard " + std::to_string(options.shardIndex) + "/" +
                                          std::to_string(options.shardCount))
                                             .c_str()
                                       : "");
    std::printf("%s", reportSummary(report).c_str());
    for (const std::string& warning : report.warnings)
        std::fprintf(stderr, "onelight-bake: warning: %s: %s\n", line.input.c_str(),
                     warning.c_str());
}

int runBakeCommand(const std::vector<std::string>& arguments) {
    for (const std::string& a : arguments)
        if (a == "--slurm") return runSlurmBakeCommand(arguments);
    if (printedHelp(arguments, bakeUsage())) return 0;
    BakeCommandLine line;
    if (!parseBakeCommandLine(arguments, line)) return 2;
    std::unique_ptr<tbb::global_control> limit;
    if (line.threads > 0)
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      static_cast<size_t>(line.threads));
    return runReportingErrors(line.input, [&] {
        noteStage("importing the level");
        const world::SourceLevel source = world::importLevel(line.input, line.quake3);
        (void)bakeAndWritePackage(source, line);
        return 0;
    });
}

}  // namespace onelight::bake
