// onelight-bake merge -o LEVEL.olpak PART0.olpak PART1.olpak ...: joins the parts of a sharded
// bake (`--shard i/N`) into the package a whole bake writes, byte for byte.
#include <cstdio>
#include <string>

#include "bake/bake_level.hpp"
#include "bake/cli/cli_common.hpp"
#include "bake/cli/subcommands.hpp"
#include "world/package/baked_sections.hpp"
#include "world/package/package_reader.hpp"

namespace onelight::bake {

std::string merge_usage() {
    return format_usage(
        "onelight-bake merge -o LEVEL.olpak PART.olpak...",
        "joins the parts of a sharded bake (--shard i/N) into the whole package",
        {{"-o PATH", "the package to write", kRequired}, {"-h, --help", "this help", ""}});
}

int run_merge_command(const std::vector<std::string>& arguments) {
    if (asks_for_help(arguments)) {
        std::printf("%s", merge_usage().c_str());
        return 0;
    }
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
                     merge_usage().c_str());
        return 2;
    }
    world::CompiledLevel level;
    std::vector<uint8_t> first_core;
    std::vector<world::BakedLighting> parts;
    for (const std::string& path : inputs) {
        package::PackageReadResult read = package::read_package_file(path);
        if (!read.ok()) {
            std::fprintf(stderr, "onelight-bake: error: %s\n", read.error.c_str());
            return 1;
        }
        const std::vector<uint8_t> core = package::serialize_package(read.level);
        if (first_core.empty()) {
            first_core = core;
            level = read.level;
        } else if (core != first_core) {
            std::fprintf(stderr, "onelight-bake: error: %s: compiled level differs from %s's\n",
                         path.c_str(), inputs[0].c_str());
            return 1;
        }
        package::BakedReadResult baked =
            package::decode_baked_sections(read.baked_sections, read.level, path);
        if (!baked.ok() || !baked.present) {
            std::fprintf(stderr, "onelight-bake: error: %s\n",
                         baked.ok() ? (path + ": no baked lighting").c_str() : baked.error.c_str());
            return 1;
        }
        parts.push_back(std::move(baked.baked));
    }
    world::BakedLighting merged;
    const std::string error = merge_baked_lighting(level, std::move(parts), merged);
    if (!error.empty()) {
        std::fprintf(stderr, "onelight-bake: error: %s\n", error.c_str());
        return 1;
    }
    const std::vector<uint8_t> bytes = package_bytes(level, merged);
    const std::string write_error = package::write_file_atomically(output, bytes);
    if (!write_error.empty()) {
        std::fprintf(stderr, "onelight-bake: error: %s\n", write_error.c_str());
        return 1;
    }
    std::printf("merged %zu parts into %s (%zu bytes)\n", inputs.size(), output.c_str(),
                bytes.size());
    return 0;
}

}  // namespace onelight::bake
