#include "bake/cli/cli_common.hpp"

#include <cstdio>
#include <exception>
#include <new>

#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/import/q3/q3_import.hpp"

namespace onelight::bake {

world::CommandOption patchLevelOption() {
    return world::integerOption("--patch-level", "N", 1, 64,
                                "segments per Quake 3 patch piece and direction",
                                std::to_string(world::Quake3Options{}.patchLevel));
}

int runCommandLine(const world::CommandTable& table, const std::vector<std::string>& arguments,
                   const std::function<int(const world::ParsedOptions&)>& run,
                   const std::string& help) {
    try {
        const world::ParsedOptions parsed = world::parseOptions(table, arguments);
        if (parsed.help) {
            std::printf("%s", help.empty() ? world::formatHelp(table).c_str() : help.c_str());
            return 0;
        }
        return run(parsed);
    } catch (const world::Error& e) {
        std::fprintf(stderr, "onelight-bake: error: %s\n", world::oneLineMessage(e.what()).c_str());
        return 2;
    }
}

int runReportingErrors(const std::string& input, const std::function<int()>& command) {
    try {
        return command();
    } catch (const world::Error& e) {
        std::fprintf(stderr, "onelight-bake: error: %s\n", world::oneLineMessage(e.what()).c_str());
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "onelight-bake: error: %s: out of memory\n",
                     world::oneLineMessage(input).c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "onelight-bake: error: %s\n",
                     world::oneLineMessage(input + ": " + e.what()).c_str());
    }
    return 1;
}

}  // namespace onelight::bake
