// onelight-bake export LEVEL -o OUT.gltf: the level as imported, written back as glTF for an
// outside renderer (world/gltf/level_export.hpp says what is kept and what is not).
#include <cstdio>
#include <filesystem>
#include <string>

#include "bake/cli/cli_common.hpp"
#include "bake/cli/subcommands.hpp"
#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/gltf/level_export.hpp"
#include "world/import/level_import.hpp"

namespace onelight::bake {
namespace {

const world::CommandTable& exportCommandTable() {
    static const world::CommandTable table = [] {
        world::CommandTable t;
        t.program = "onelight-bake export";
        t.synopsis = "onelight-bake export LEVEL -o OUT.gltf [OPTIONS]";
        t.summary =
            "writes LEVEL as imported back as glTF (OUT.gltf, OUT.bin, OUT_images/): its static "
            "triangles, materials, textures, lights, cameras and sky, for an outside renderer "
            "(scripts/cycles-render.py)\n  " +
            kLevelMeaning;
        t.options = {world::textOption("-o", "PATH", "the .gltf to write", world::kRequiredOption),
                     patchLevelOption()};
        t.positionalName = "level";
        t.minPositionals = t.maxPositionals = 1;
        return t;
    }();
    return table;
}

int exportFromCommandLine(const world::ParsedOptions& parsed) {
    const std::string input = parsed.positionals.at(0);
    const std::filesystem::path output = parsed.text("-o");
    if (output.extension() != ".gltf")
        throw world::Error("-o '" + output.string() + "': expected a path ending in .gltf");
    world::Quake3Options quake3;
    if (parsed.has("--patch-level"))
        quake3.patchLevel = static_cast<uint32_t>(parsed.integer("--patch-level"));
    return runReportingErrors(input, [&] {
        const world::SourceLevel source = world::importLevel(input, quake3);
        world::refuseOutputOverInput(output.string(), source.inputFiles);
        const std::filesystem::path folder =
            output.has_parent_path() ? output.parent_path() : std::filesystem::path(".");
        const world::LevelExportStats s =
            world::exportLevelGltf(source, std::filesystem::path(source.sourcePath).parent_path(),
                                   folder, output.stem().string());
        std::printf(
            "exported %s: %zu static meshes, %zu triangles, %zu materials, %zu images, %zu "
            "lights, %zu cameras\n",
            output.c_str(), s.instances, s.triangles, s.materials, s.images, s.lights, s.cameras);
        if (s.dynamicLeftOut)
            std::printf("  %zu dynamic meshes left out (items, movers)\n", s.dynamicLeftOut);
        if (s.imagesMissing)
            std::fprintf(stderr,
                         "onelight-bake: warning: %s: %zu image(s) could not be read or decoded; "
                         "their textures are left out\n",
                         input.c_str(), s.imagesMissing);
        return 0;
    });
}

}  // namespace

std::string exportUsage() {
    return world::formatHelp(exportCommandTable());
}

int runExportCommand(const std::vector<std::string>& arguments) {
    return runCommandLine(exportCommandTable(), arguments, [](const world::ParsedOptions& parsed) {
        return exportFromCommandLine(parsed);
    });
}

}  // namespace onelight::bake
