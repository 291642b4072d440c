#include "bake/cli/cli_common.hpp"

#include <cstdio>
#include <exception>
#include <new>

#include "world/error.hpp"

namespace onelight::bake {

bool parse_number(const std::string& text, double low, double high, double& out) {
    try {
        size_t used = 0;
        out = std::stod(text, &used);
        return used == text.size() && out >= low && out <= high;
    } catch (const std::exception&) {
        return false;
    }
}

int run_reporting_errors(const std::string& input, const std::function<int()>& command) {
    try {
        return command();
    } catch (const world::CompileError& e) {
        std::fprintf(stderr, "onelight-bake: error: %s\n", e.what());
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "onelight-bake: error: %s: out of memory\n", input.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "onelight-bake: error: %s: %s\n", input.c_str(), e.what());
    }
    return 1;
}

}  // namespace onelight::bake
