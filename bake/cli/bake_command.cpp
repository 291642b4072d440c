// onelight-bake LEVEL.gltf -o LEVEL.olpak [OPTIONS] (bake_usage lists them with their defaults).
// Compiles and bakes in one go: progress bars with ETA on stderr, a summary on stdout. --sky
// overrides the level's uniform sky (extras.onelight.sky).
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>

#include <tbb/global_control.h>

#include "bake/bake_level.hpp"
#include "bake/cli/cli_common.hpp"
#include "bake/cli/subcommands.hpp"
#include "world/error.hpp"
#include "world/import/gltf_import.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::bake {
namespace {

int bad_argument(const std::string& what) {
    std::fprintf(stderr, "onelight-bake: %s\n%s", what.c_str(), bake_usage().c_str());
    return 2;
}

}  // namespace

std::string bake_usage() {
    const BakeOptions d;
    const world::ChartOptions& charts = d.compile.charts;
    return format_usage(
        "onelight-bake LEVEL.gltf [-o LEVEL.olpak] [OPTIONS]",
        "compiles LEVEL and bakes its lighting: progress on stderr, a summary on stdout",
        {{"-o PATH", "the package to write", "LEVEL with the extension .olpak"},
         {"--quality Q", "draft, default or high", quality_name(d.quality)},
         {"--threads N", "worker threads, 1..1024", "every core"},
         {"--report PATH", "a JSON report of every stage", "none"},
         {"--shard i/N", "bake part i of N (join them with merge)", "the whole level"},
         {"--sky CD_PER_M2", "a uniform sky's radiance", "the level's extras.onelight.sky, or 0"},
         {"--grid-cell M", "the light grid's cell size in metres", format_number(d.grid_cell_size)},
         {"--texels-per-metre N", "lightmap density, 0.01..1024",
          "the level's, or " + format_number(charts.texels_per_metre)},
         {"--quiet", "no progress bars", "bars on a terminal"},
         {"-h, --help", "this help", ""}});
}

int run_bake_command(const std::vector<std::string>& arguments) {
    if (asks_for_help(arguments)) {
        std::printf("%s", bake_usage().c_str());
        return 0;
    }
    std::string input, output, report_path;
    BakeOptions options;
    int threads = 0;
    for (size_t i = 0; i < arguments.size(); ++i) {
        const std::string& a = arguments[i];
        const bool has_value = i + 1 < arguments.size();
        double v = 0.0;
        if (a == "-o" && has_value) {
            output = arguments[++i];
        } else if (a == "--quality" && has_value) {
            if (!parse_quality(arguments[++i], options.quality))
                return bad_argument("--quality '" + arguments[i] +
                                    "'; expected draft, default or high");
        } else if (a == "--threads" && has_value) {
            if (!parse_number(arguments[++i], 1, 1024, v))
                return bad_argument("--threads '" + arguments[i] + "'; expected 1..1024");
            threads = static_cast<int>(v);
        } else if (a == "--report" && has_value) {
            report_path = arguments[++i];
        } else if (a == "--shard" && has_value) {
            const std::string s = arguments[++i];
            const size_t slash = s.find('/');
            double index = 0, count = 0;
            if (slash == std::string::npos || !parse_number(s.substr(0, slash), 0, 65535, index) ||
                !parse_number(s.substr(slash + 1), 1, 65536, count) || index >= count)
                return bad_argument("--shard '" + s + "'; expected i/N with 0 <= i < N");
            options.shard_index = static_cast<uint32_t>(index);
            options.shard_count = static_cast<uint32_t>(count);
        } else if (a == "--sky" && has_value) {
            if (!parse_number(arguments[++i], 0, 1e9, v))
                return bad_argument("--sky '" + arguments[i] + "'; expected cd/m^2 >= 0");
            options.sky_radiance = glm::vec3(static_cast<float>(v));
        } else if (a == "--grid-cell" && has_value) {
            if (!parse_number(arguments[++i], 0.05, 1000, v))
                return bad_argument("--grid-cell '" + arguments[i] + "'; expected metres");
            options.grid_cell_size = static_cast<float>(v);
        } else if (a == "--texels-per-metre" && has_value) {
            if (!parse_number(arguments[++i], 0.01, 1024, v))
                return bad_argument("--texels-per-metre '" + arguments[i] +
                                    "'; expected a number in [0.01, 1024]");
            options.compile.charts.texels_per_metre = v;
            options.compile.charts.density_from_command_line = true;
        } else if (a == "--quiet") {
            options.show_progress = false;
        } else if (!a.empty() && a[0] != '-' && input.empty()) {
            input = a;
        } else {
            return bad_argument("unexpected argument '" + a + "'");
        }
    }
    if (input.empty()) return bad_argument("no level given");
    if (output.empty()) output = std::filesystem::path(input).replace_extension(".olpak").string();
    std::unique_ptr<tbb::global_control> limit;
    if (threads > 0)
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      static_cast<size_t>(threads));
    return run_reporting_errors(input, [&] {
        const world::SourceLevel source = world::import_gltf(input);
        BakeResult result = bake_level(source, options);
        const std::vector<uint8_t> bytes = package_bytes(result.level, result.baked);
        package::write_file_atomically(output, bytes);
        if (!report_path.empty()) {
            result.report.package_bytes = bytes.size();
            write_report(report_path, result.report);
        }
        std::printf("baked %s (%zu bytes, quality %s%s)\n", output.c_str(), bytes.size(),
                    quality_name(options.quality),
                    options.shard_count > 1 ? (", shard " + std::to_string(options.shard_index) +
                                               "/" + std::to_string(options.shard_count))
                                                  .c_str()
                                            : "");
        std::printf("%s", report_summary(result.report).c_str());
        for (const std::string& warning : result.report.warnings)
            std::fprintf(stderr, "onelight-bake: warning: %s: %s\n", input.c_str(),
                         warning.c_str());
        return 0;
    });
}

}  // namespace onelight::bake
