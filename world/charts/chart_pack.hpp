// Packs chart rectangles into atlases (shelf packing, tallest first: deterministic, no
// overlaps, padding kept inside each rectangle) and writes every vertex's lightmap coordinates.
#pragma once

#include <cstdint>
#include <vector>

#include "world/charts/chart_build.hpp"

namespace onelight::world {

struct ChartLayout {
    std::vector<Chart> charts;  // one per shape, same order
    std::vector<Atlas> atlases;
    uint64_t texelCount = 0;  // sum of atlas areas
    double fillRatio = 0.0;   // triangle area in texels / texelCount
};

/// Places the shapes, then rewrites geometry so each vertex belongs to one chart and carries
/// uv1 normalised over its atlas.
[[nodiscard]] ChartLayout packCharts(StaticGeometry& geometry,
                                     const std::vector<ChartShape>& shapes,
                                     const ChartOptions& options);

/// buildChartShapes followed by packCharts.
[[nodiscard]] ChartLayout buildLightmapCharts(StaticGeometry& geometry,
                                              const ChartOptions& options);

}  // namespace onelight::world
