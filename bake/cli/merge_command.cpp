// onelight-bake merge -o LEVEL.olpak PART0.olpak PART1.olpak ...: joins the parts of a sharded
// bake (`--shard i/N`) into the package a whole bake writes, byte for byte.
#include <cstdio>
#include <string>

#include "bake/bake_level.hpp"
#include "bake/cli/cli_common.hpp"
#include "bake/cli/subcommands.hpp"
#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/file_write.hpp"
#include "world/package/baked_sections.hpp"
#include "world/package/package_reader.hpp"
#include "world/package/texture_section.hpp"

namespace onelight::bake {

std::string mergeUsage() {
    return formatUsage(
        "onelight-bake merge -o LEVEL.olpak PART.olpak...",
        "joins the parts of a sharded bake (--shard i/N) into the whole package",
        {{"-o PATH", "the package to write", kRequired}, {"-h, --help", "this help", ""}});
}

int runMergeCommand(const std::vector<std::string>& arguments) {
    if (printedHelp(arguments, mergeUsage())) return 0;
    std::string output;
    std::vector<std::string> inputs;
    for (size_t i = 0; i < arguments.size(); ++i) {
        if (arguments[i] == "-o" && i + 1 < arguments.size())
            output = arguments[++i];
        else if (!arguments[i].empty() && arguments[i][0] != '-')
            inputs.push_back(arguments[i]);
        else {
            std::fprintf(stderr, "onelight-bake merge: unexpected argument '%s'\n",
                         arguments[i].c_str());
            return 2;
        }
    }
    if (output.empty() || inputs.empty()) {
        std::fprintf(stderr, "onelight-bake merge: -o and at least one part are required\n%s",
                     mergeUsage().c_str());
        return 2;
    }
    return runReportingErrors(inputs[0], [&] {
        world::refuseOutputOverInput(output, inputs);
        world::CompiledLevel level;
        std::vector<uint8_t> firstCore;
        std::vector<world::BakedLighting> parts;
        world::ProcessedTextures textures;
        std::vector<uint8_t> firstTextures;
        for (const std::string& path : inputs) {
            package::PackageContents read = package::readPackageFile(path);
            const std::vector<uint8_t> core = package::serializePackage(read.level);
            if (firstCore.empty()) {
                firstCore = core;
                level = read.level;
            } else if (core != firstCore) {
                throw world::Error(path + ": compiled level differs from " + inputs[0] + "'s");
            }
            package::BakedContents baked =
                package::decodeBakedSections(read.bakedSections, read.level, path);
            if (!baked.present) throw world::Error(path + ": no baked lighting");
            parts.push_back(std::move(baked.baked));
            // Every shard runs the whole (deterministic) texture stage: the parts agree.
            package::TextureContents made =
                package::decodeTextureSection(read.bakedSections, read.level, path);
            if (!made.present) throw world::Error(path + ": no textures section (38)");
            const std::vector<uint8_t> bytes = package::encodeTextureSection(made.textures).bytes;
            if (firstTextures.empty()) {
                firstTextures = bytes;
                textures = std::move(made.textures);
            } else if (bytes != firstTextures) {
                throw world::Error(path + ": textures differ from " + inputs[0] + "'s");
            }
        }
        const world::BakedLighting merged = mergeBakedLighting(level, std::move(parts), inputs);
        const std::vector<uint8_t> bytes = packageBytes(level, merged, textures);
        world::writeFileAtomically(output, bytes);
        std::printf("merged %zu parts into %s (%zu bytes)\n", inputs.size(), output.c_str(),
                    bytes.size());
        return 0;
    });
}

}  // namespace onelight::bake
