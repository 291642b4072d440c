#include "bake/cli/cli_common.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>

#include "world/error.hpp"

namespace onelight::bake {

std::string formatUsage(const std::string& synopsis, const std::string& summary,
                        const std::vector<CliOption>& options) {
    size_t width = 0;
    for (const CliOption& o : options) width = std::max(width, o.flag.size());
    std::string text = "usage: " + synopsis + "\n  " + summary + "\n";
    for (const CliOption& o : options)
        text += "  " + o.flag + std::string(width + 2 - o.flag.size(), ' ') + o.meaning +
                (o.defaultValue.empty()        ? ""
                 : o.defaultValue == kRequired ? " (required)"
                                               : " (default: " + o.defaultValue + ")") +
                "\n";
    return text;
}

CliOption patchLevelOption() {
    return {"--patch-level N", "segments per Quake 3 patch piece and direction, 1..64",
            std::to_string(world::Quake3Options{}.patchLevel)};
}

bool parsePatchLevel(const std::string& text, world::Quake3Options& options) {
    double value = 0.0;
    if (!parseNumber(text, 1.0, 64.0, value) || value != std::floor(value)) return false;
    options.patchLevel = static_cast<uint32_t>(value);
    return true;
}

std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%g", value);
    return text;
}

bool printedHelp(const std::vector<std::string>& arguments, const std::string& usage) {
    for (const std::string& a : arguments)
        if (a == "-h" || a == "--help") {
            std::printf("%s", usage.c_str());
            return true;
        }
    return false;
}

bool parseNumber(const std::string& text, double low, double high, double& out) {
    try {
        size_t used = 0;
        out = std::stod(text, &used);
        return used == text.size() && out >= low && out <= high;
    } catch (const std::exception&) {
        return false;
    }
}

int runReportingErrors(const std::string& input, const std::function<int()>& command) {
    try {
        return command();
    } catch (const world::Error& e) {
        std::fprintf(stderr, "onelight-bake: error: %s\n", e.what());
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "onelight-bake: error: %s: out of memory\n", input.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "onelight-bake: error: %s: %s\n", input.c_str(), e.what());
    }
    return 1;
}

}  // namespace onelight::bake
