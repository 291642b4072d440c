#include "cli.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "world/error.hpp"

namespace onelight::lab {

std::vector<std::string> parseWordList(std::string_view text) {
    std::vector<std::string> words;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find(',', start);
        if (end == std::string_view::npos) end = text.size();
        words.emplace_back(text.substr(start, end - start));
        start = end + 1;
    }
    return words;
}

namespace {

// `value` as the shortest text that reads it back ("%g": 0, 0.25, 10000).
std::string shortest(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

}  // namespace

std::vector<double> parseNumberList(std::string_view option, std::string_view text, double lo,
                                    double hi, bool loOpen) {
    std::vector<double> values;
    for (const std::string& word : parseWordList(text)) {
        double x = 0.0;
        auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), x);
        bool inRange = std::isfinite(x) && (loOpen ? x > lo : x >= lo) && x <= hi;
        if (word.empty() || ec != std::errc() || end != word.data() + word.size() || !inRange) {
            throw world::Error(std::string(option) + ": '" + word + "' is not a number in " +
                               (loOpen ? "(" : "[") + shortest(lo) + ", " + shortest(hi) + "]");
        }
        values.push_back(x);
    }
    return values;
}

}  // namespace onelight::lab
