// onelight-bake SUBCOMMAND ...: dispatches to the subcommand.
#include <cstdio>
#include <string>
#include <vector>

#include "bake/cli/subcommands.hpp"

namespace {

struct Subcommand {
    const char* name;
    const char* summary;
    int (*run)(const std::vector<std::string>&);
};

constexpr Subcommand kSubcommands[] = {
    {"compile", "compile LEVEL.gltf -o LEVEL.olpak: world compile without lighting",
     &onelight::bake::run_compile_command},
    {"reference", "reference LEVEL.gltf --camera NAME [--size WxH] --spp N -o OUT.exr",
     &onelight::bake::run_reference_command},
    {"merge", "merge -o LEVEL.olpak PART.olpak...: join the parts of a sharded bake",
     &onelight::bake::run_merge_command},
};

void print_usage() {
    std::fprintf(stderr,
                 "usage: onelight-bake LEVEL.gltf -o LEVEL.olpak [--quality "
                 "draft|default|high] [--threads N] [--report R.json] [--shard i/N]\n"
                 "       onelight-bake SUBCOMMAND [ARGS]\n");
    for (const Subcommand& s : kSubcommands) std::fprintf(stderr, "  %s\n", s.summary);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        print_usage();
        return 2;
    }
    const std::string name = argv[1];
    if (name == "-h" || name == "--help") {
        print_usage();
        return 0;
    }
    const std::vector<std::string> arguments(argv + 2, argv + argc);
    for (const Subcommand& s : kSubcommands)
        if (name == s.name) return s.run(arguments);
    if (name[0] != '-') return onelight::bake::run_bake_command({argv + 1, argv + argc});
    std::fprintf(stderr, "onelight-bake: unknown subcommand '%s'\n", name.c_str());
    print_usage();
    return 2;
}
