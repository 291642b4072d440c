// Minimal PNG charts for lab reports: scatter and line series on linear or log axes, with
// labelled points, a legend and tick labels (stb_easy_font text; the PNG written by
// world::writePngFile, world/images/image_files.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace onelight::lab {

struct PlotSeries {
    std::string label;
    std::array<uint8_t, 3> color;
    std::vector<std::pair<double, double>> points;  // (x, y)
    bool line = false;                              // joined by a line; otherwise dots
    bool labelPoints = false;                       // write the series label beside each dot
    bool inLegend = true;                           // false: no legend entry
};

struct Plot {
    std::string title, xLabel, yLabel;
    bool logX = false, logY = false;
    std::vector<PlotSeries> series;
};

// Writes the plot as a 960x600 PNG, atomically; throws world::Error naming the path on failure.
// Non-positive values on a log axis and non-finite values are skipped.
void writePlotPng(const std::string& path, const Plot& plot);

// A distinct colour for series i.
[[nodiscard]] std::array<uint8_t, 3> seriesColor(int i);

}  // namespace onelight::lab
