// onelight-bake compile LEVEL.gltf [-o LEVEL.olpak] [OPTIONS] (compile_usage lists them).
// Imports, compiles without lighting, writes the package atomically and prints a summary.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "bake/cli/cli_common.hpp"
#include "bake/cli/subcommands.hpp"
#include "world/compile/compile_level.hpp"
#include "world/error.hpp"
#include "world/import/gltf_import.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::bake {
namespace {

/// Image file references become relative to the package's folder.
void rebase_image_paths(world::CompiledLevel& level, const std::filesystem::path& package) {
    const std::filesystem::path folder = std::filesystem::absolute(package).parent_path();
    for (world::Image& image : level.images) {
        if (image.uri.empty()) continue;
        std::error_code ec;
        const std::filesystem::path relative =
            std::filesystem::relative(std::filesystem::absolute(image.uri), folder, ec);
        if (!ec && !relative.empty()) image.uri = relative.generic_string();
    }
}

void print_summary(const std::string& output, const world::CompileStats& s, size_t bytes) {
    std::printf("compiled %s (%zu bytes)\n", output.c_str(), bytes);
    std::printf(
        "  triangles  %llu static (%llu imported, %llu degenerate and %llu duplicate removed), "
        "%llu dynamic\n",
        static_cast<unsigned long long>(s.triangles),
        static_cast<unsigned long long>(s.source_triangles),
        static_cast<unsigned long long>(s.degenerate_removed),
        static_cast<unsigned long long>(s.duplicates_removed),
        static_cast<unsigned long long>(s.dynamic_triangles));
    std::printf("  surfaces   %llu\n", static_cast<unsigned long long>(s.surfaces));
    std::printf("  bsp        depth %u, %llu leaves, %llu nodes, %llu triangles cut\n", s.bsp_depth,
                static_cast<unsigned long long>(s.bsp_leaves),
                static_cast<unsigned long long>(s.bsp_nodes),
                static_cast<unsigned long long>(s.bsp_splits));
    std::printf("  primaries  %u candidates, %u owning surfaces\n", s.primary_candidates,
                s.primaries_used);
    std::printf(
        "  splits     %u edges cut, %u triangles split at their centre, %u fragments merged, "
        "+%u triangles\n",
        s.regions.edges_cut, s.regions.faces_centre_split, s.regions.fragments_merged,
        s.regions.triangles_added);
    std::printf("  charts     %llu (%llu from TEXCOORD_1), %llu atlases, %llu texels, fill %.3f\n",
                static_cast<unsigned long long>(s.charts),
                static_cast<unsigned long long>(s.authored_charts),
                static_cast<unsigned long long>(s.atlases),
                static_cast<unsigned long long>(s.texels), s.fill_ratio);
    std::printf(
        "  time       split %.3f s, regions %.3f s, charts %.3f s, bsp %.3f s, surfaces %.3f s\n",
        s.seconds_split, s.seconds_regions, s.seconds_charts, s.seconds_bsp, s.seconds_surfaces);
}

}  // namespace

std::string compile_usage() {
    const world::ChartOptions d;
    return format_usage(
        "onelight-bake compile LEVEL.gltf [-o LEVEL.olpak] [OPTIONS]",
        "compiles LEVEL without lighting (BSP, primaries, charts) and prints a summary",
        {{"-o PATH", "the package to write", "LEVEL with the extension .olpak"},
         {"--texels-per-metre N", "lightmap density, 0.01..1024",
          "the level's, or " + format_number(d.texels_per_metre)},
         {"--atlas-size N", "texels per side of an atlas, 64..16384", std::to_string(d.atlas_size)},
         {"-h, --help", "this help", ""}});
}

int run_compile_command(const std::vector<std::string>& arguments) {
    if (asks_for_help(arguments)) {
        std::printf("%s", compile_usage().c_str());
        return 0;
    }
    std::string input, output;
    world::CompileOptions options;
    for (size_t i = 0; i < arguments.size(); ++i) {
        const std::string& a = arguments[i];
        const bool has_value = i + 1 < arguments.size();
        double value = 0.0;
        if (a == "-o" && has_value) {
            output = arguments[++i];
        } else if (a == "--texels-per-metre" && has_value) {
            if (!parse_number(arguments[++i], 0.01, 1024.0, value)) {
                std::fprintf(stderr,
                             "onelight-bake compile: --texels-per-metre '%s'; expected a number in "
                             "[0.01, 1024]\n",
                             arguments[i].c_str());
                return 2;
            }
            options.charts.texels_per_metre = value;
            options.charts.density_from_command_line = true;
        } else if (a == "--atlas-size" && has_value) {
            if (!parse_number(arguments[++i], 64.0, 16384.0, value)) {
                std::fprintf(stderr,
                             "onelight-bake compile: --atlas-size '%s'; expected an integer in "
                             "[64, 16384]\n",
                             arguments[i].c_str());
                return 2;
            }
            options.charts.atlas_size = static_cast<uint32_t>(value);
        } else if (!a.empty() && a[0] != '-' && input.empty()) {
            input = a;
        } else {
            std::fprintf(stderr, "onelight-bake compile: unexpected argument '%s'\n%s", a.c_str(),
                         compile_usage().c_str());
            return 2;
        }
    }
    if (input.empty()) {
        std::fprintf(stderr, "onelight-bake compile: no level given\n%s", compile_usage().c_str());
        return 2;
    }
    if (output.empty()) output = std::filesystem::path(input).replace_extension(".olpak").string();
    return run_reporting_errors(input, [&] {
        const world::SourceLevel source = world::import_gltf(input);
        world::CompileResult result = world::compile_level(source, options);
        rebase_image_paths(result.level, output);
        const std::vector<uint8_t> bytes = package::serialize_package(result.level);
        package::write_file_atomically(output, bytes);
        print_summary(output, result.stats, bytes.size());
        return 0;
    });
}

}  // namespace onelight::bake
