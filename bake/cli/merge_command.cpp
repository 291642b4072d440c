// onelight-bake merge -o LEVEL.olpak PART0.olpak PART1.olpak ...: joins the parts of a sharded
// bake (`--shard i/N`) into the package a whole bake writes, byte for byte.
#include <cstdio>
#include <string>

#include "bake/bake_level.hpp"
#include "bake/cli/cli_common.hpp"
#include "bake/cli/subcommands.hpp"
#include "world/error.hpp"
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
    return run_reporting_errors(inputs[0], [&] {
        world::CompiledLevel level;
        std::vector<uint8_t> first_core;
        std::vector<world::BakedLighting> parts;
        for (const std::string& path : inputs) {
            package::PackageContents read = package::read_package_file(path);
            const std::vector<uint8_t> core = package::serialize_package(read.level);
            if (first_core.empty()) {
                first_core = core;
                level = read.level;
            } else if (core != first_core) {
                throw world::Error(path + ": compiled level differs from " + inputs[0] + "'s");
            }
            package::BakedContents baked =
                package::decode_baked_sections(read.baked_sections, read.level, path);
            if (!baked.present) throw world::Error(path + ": no baked lighting");
            parts.push_back(std::move(baked.baked));
        }
        const world::BakedLighting merged = merge_baked_lighting(level, std::move(parts));
        const std::vector<uint8_t> bytes = package_bytes(level, merged);
        package::write_file_atomically(output, bytes);
        std::printf("merged %zu parts into %s (%zu bytes)\n", inputs.size(), output.c_str(),
                    bytes.size());
        return 0;
    });
}

}  // namespace onelight::bake
