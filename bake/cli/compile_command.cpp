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
#include "world/level_names.hpp"
#include "world/package/package_writer.hpp"
#include "world/package/texture_section.hpp"

namespace onelight::bake {
namespace {

int compileFromCommandLine(const world::ParsedOptions& parsed);

void printSummary(const std::string& output, const world::CompileStats& s, size_t bytes) {
    std::printf("compiled %s (%zu bytes)\n", output.c_str(), bytes);
    std::printf(
        "  triangles  %llu static (%llu imported, %llu degenerate and %llu duplicate removed), "
        "%llu dynamic (%llu of them drawn from a shared copy)\n",
        static_cast<unsigned long long>(s.triangles),
        static_cast<unsigned long long>(s.sourceTriangles),
        static_cast<unsigned long long>(s.degenerateRemoved),
        static_cast<unsigned long long>(s.duplicatesRemoved),
        static_cast<unsigned long long>(s.dynamicTriangles),
        static_cast<unsigned long long>(s.dynamicTrianglesShared));
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

const world::CommandTable& compileCommandTable() {
    static const world::CommandTable table = [] {
        const world::ChartOptions d;
        world::CommandTable t;
        t.program = "onelight-bake compile";
        t.synopsis = "onelight-bake compile LEVEL [-o LEVEL.olpak] [OPTIONS]";
        t.summary =
            "compiles LEVEL without lighting (BSP, primaries, charts) and prints a summary\n  " +
            kLevelMeaning;
        t.options = {
            world::textOption("-o", "PATH", "the package to write",
                              "LEVEL with the extension .olpak"),
            world::realOption("--texels-per-metre", "N", 0.01, 1024.0, "lightmap density",
                              "the level's, or " + world::shortestNumber(d.texelsPerMetre)),
            world::integerOption("--atlas-size", "N", 64, 16384, "texels per side of an atlas",
                                 std::to_string(d.atlasSize)),
            patchLevelOption()};
        t.positionalName = "level";
        t.minPositionals = t.maxPositionals = 1;
        return t;
    }();
    return table;
}

std::string compileUsage() {
    return world::formatHelp(compileCommandTable());
}

int runCompileCommand(const std::vector<std::string>& arguments) {
    return runCommandLine(compileCommandTable(), arguments, [](const world::ParsedOptions& parsed) {
        return compileFromCommandLine(parsed);
    });
}

namespace {

int compileFromCommandLine(const world::ParsedOptions& parsed) {
    const std::string input = parsed.positionals.at(0);
    const std::string output =
        parsed.has("-o") ? parsed.text("-o") : world::defaultPackagePath(input);
    world::CompileOptions options;
    world::Quake3Options quake3;
    if (parsed.has("--texels-per-metre")) {
        options.charts.texelsPerMetre = parsed.real("--texels-per-metre");
        options.charts.densityFromCommandLine = true;
    }
    if (parsed.has("--atlas-size"))
        options.charts.atlasSize = static_cast<uint32_t>(parsed.integer("--atlas-size"));
    if (parsed.has("--patch-level"))
        quake3.patchLevel = static_cast<uint32_t>(parsed.integer("--patch-level"));
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
        for (const std::string& line : source.lightSources)
            std::printf("%s: %s\n", input.c_str(), line.c_str());
        for (const std::string& note : source.importNotes)
            std::fprintf(stderr, "onelight-bake: warning: %s\n", note.c_str());
        return 0;
    });
}

}  // namespace
}  // namespace onelight::bake
