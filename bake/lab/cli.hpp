// onelight-lab's list values (its options are tables, world/command_options.hpp, in main.cpp):
// every error names the option and what was expected, and surfaces as world::Error (main prints
// it on one line and exits 1).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace onelight::lab {

// Comma-separated numbers, each within [lo, hi] (lo excluded when loOpen).
[[nodiscard]] std::vector<double> parseNumberList(std::string_view option, std::string_view text,
                                                  double lo, double hi, bool loOpen);

// Comma-separated words.
[[nodiscard]] std::vector<std::string> parseWordList(std::string_view text);

}  // namespace onelight::lab
