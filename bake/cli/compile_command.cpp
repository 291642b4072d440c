// onelight-bake compile LEVEL [-o LEVEL.olpak] [OPTIONS] (compileUsage lists them).
// Imports, compiles without lighting, writes the package atomically and prints a summary.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "bake/cli/cli_common.hpp"
#include "bake/cli/subcommands.hpp"
#include "bake/textures/texture_stage.hpp"
#include "world/compile/compile_level.hpp"
#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/file_write.hpp"
#include "world/import/level_import.hpp"
#include "world/package/package_writer.hpp"
#include "world/package/texture_section.hpp"

namespace onelight::bake {
namespace {

void printSummary(const std::string& output, const world::CompileStats& s, size_t bytes) {
    std::printf("compiled %s (%zu bytes)\n", output.c_str(), bytes);
    std::printf(
        "  triangles  %llu static (%llu imported, %llu degenerate and %llu duplicate removed), "
        "%llu dynamic\n",
        static_cast<unsigned long long>(s.triangles),
        static_cast<unsigned long long>(s.sourceTriangles),
        static_cast<unsigned long long>(s.degenerateRemoved),
        static_cast<unsigned long long>(s.duplicatesRemoved),
        static_cast<unsigned long long>(s.dynamicTriangles));
    std::printf("  surfaces   %llu\n", static_cast<unsigned long long>(s.surfaces));
    std::printf("  bsp        depth %u, %llu leaves, %llu nodes, %llu triangles cut\n", s.bspDepth,
                static_cast<unsigned long long>(s.bspLeaves),
                static_cast<unsigned long long>(s.bspNodes),
                static_cast<unsigned long long>(s.bspSplits));
    std::printf("  primaries  %u candidates, %u owning surfaces\n", s.primaryCandidates,
                s.primariesUsed);
    std::printf(
        "  splits     %u edges cut, %u triangles split at their centre, %u fragments merged, "
        "+%u triangles\n",
        s.regions.edgesCut, s.regions.facesCentreSplit, s.regions.fragmentsMerged,
        s.regions.trianglesAdded);
    std::printf("  charts     %llu (%llu from TEXCOORD_1), %llu atlases, %llu texels, fill %.3f\n",
                static_cast<unsigned long long>(s.charts),
                static_cast<unsigned long long>(s.authoredCharts),
                static_cast<unsigned long long>(s.atlases),
                static_cast<unsigned long long>(s.texels), s.fillRatio);
    std::printf(
        "  time       split %.3f s, regions %.3f s, charts %.3f s, bsp %.3f s, surfaces %.3f s\n",
        s.secondsSplit, s.secondsRegions, s.secondsCharts, s.secondsBsp, s.secondsSurfaces);
}

}  // namespace

std::string compileUsage() {
    const world::ChartOptions d;
    return formatUsage(
        "onelight-bake compile LEVEL [-o LEVEL.olpak] [OPTIONS]",
        "compiles LEVEL without lighting (BSP, primaries, charts) and prints a summary\n  " +
            kLevelMeaning,
        {{"-o PATH", "the package to write", "LEVEL with the extension .olpak"},
         {"--texels-per-metre N", "lightmap density, 0.01..1024",
          "the level's, or " + formatNumber(d.texelsPerMetre)},
         {"--atlas-size N", "texels per side of an atlas, 64..16384", std::to_string(d.atlasSize)},
         patchLevelOption(),
         {"-h, --help", "this help", ""}});
}

int runCompileCommand(const std::vector<std::string>& arguments) {
    if (printedHelp(arguments, compileUsage())) return 0;
    std::string input, output;
    world::CompileOptions options;
    world::Quake3Options quake3;
    for (size_t i = 0; i < arguments.size(); ++i) {
        const std::string& a = arguments[i];
        const bool hasValue = i + 1 < arguments.size();
        double value = 0.0;
        if (a == "-o" && hasValue) {
            output = arguments[++i];
        } else if (a == "--texels-per-metre" && hasValue) {
            if (!parseNumber(arguments[++i], 0.01, 1024.0, value)) {
                std::fprintf(stderr,
                             "onelight-bake compile: --texels-per-metre '%s'; expected a number in "
                             "[0.01, 1024]\n",
                             arguments[i].c_str());
                return 2;
            }
            options.charts.texelsPerMetre = value;
            options.charts.densityFromCommandLine = true;
        } else if (a == "--atlas-size" && hasValue) {
            if (!parseNumber(arguments[++i], 64.0, 16384.0, value)) {
                std::fprintf(stderr,
                             "onelight-bake compile: --atlas-size '%s'; expected an integer in "
                             "[64, 16384]\n",
                             arguments[i].c_str());
                return 2;
            }
            options.charts.atlasSize = static_cast<uint32_t>(value);
        } else if (a == "--patch-level" && hasValue) {
            if (!parsePatchLevel(arguments[++i], quake3)) {
                std::fprintf(stderr,
                             "onelight-bake compile: --patch-level '%s'; expected an integer in "
                             "[1, 64]\n",
                             arguments[i].c_str());
                return 2;
            }
        } else if (!a.empty() && a[0] != '-' && input.empty()) {
            input = a;
        } else {
            std::fprintf(stderr, "onelight-bake compile: unexpected argument '%s'\n%s", a.c_str(),
                         compileUsage().c_str());
            return 2;
        }
    }
    if (input.empty()) {
        std::fprintf(stderr, "onelight-bake compile: no level given\n%s", compileUsage().c_str());
        return 2;
    }
    if (output.empty()) output = world::defaultPackagePath(input);
    return runReportingErrors(input, [&] {
        const world::SourceLevel source = world::importLevel(input, quake3);
        world::refuseOutputOverInput(output, source.inputFiles);
        world::CompileResult result = world::compileLevel(source, options);
        package::placeImagesForPackage(result.level, output);
        // The texture stage's mips: a compiled package plays with placeholder lighting, and its
        // textures are what the bake would give it.
        const world::ProcessedTextures textures =
            bake::processLevelTextures(source, source.glossMips);
        const std::vector<package::RawSection> sections = {package::encodeTextureSection(textures)};
        const std::vector<uint8_t> bytes = package::serializePackage(result.level, sections);
        world::writeFileAtomically(output, bytes);
        printSummary(output, result.stats, bytes.size());
        for (const std::string& note : source.importNotes)
            std::fprintf(stderr, "onelight-bake: warning: %s\n", note.c_str());
        return 0;
    });
}

}  // namespace onelight::bake
