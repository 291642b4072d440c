// onelight-bake merge -o LEVEL.olpak PART0.olpak PART1.olpak ...: joins the parts of a sharded
// bake (`--shard i/N`) into the package a whole bake writes, byte for byte.
#include <cstdint>
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
namespace {

int mergeParts(const std::string& output, const std::vector<std::string>& inputs);

}  // namespace

const world::CommandTable& mergeCommandTable() {
    static const world::CommandTable table = [] {
        world::CommandTable t;
        t.program = "onelight-bake merge";
        t.synopsis = "onelight-bake merge -o LEVEL.olpak PART.olpak...";
        t.summary = "joins the parts of a sharded bake (--shard i/N) into the whole package";
        t.options = {
            world::textOption("-o", "PATH", "the package to write", world::kRequiredOption)};
        t.positionalName = "part";
        t.minPositionals = 1;
        t.maxPositionals = SIZE_MAX;
        return t;
    }();
    return table;
}

std::string mergeUsage() {
    return world::formatHelp(mergeCommandTable());
}

int runMergeCommand(const std::vector<std::string>& arguments) {
    return runCommandLine(mergeCommandTable(), arguments, [](const world::ParsedOptions& parsed) {
        return mergeParts(parsed.text("-o"), parsed.positionals);
    });
}

namespace {

int mergeParts(const std::string& output, const std::vector<std::string>& inputs) {
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

}  // namespace
}  // namespace onelight::bake
