// Lightmap charts. Meshes with TEXCOORD_1 keep it (one authored chart, one atlas page each);
// the others are cut into charts: connected triangles of one primary whose normals stay within
// a cone of the first triangle's, projected onto that triangle's plane.
#pragma once

#include <cstdint>
#include <vector>

#include "world/static_geometry.hpp"

namespace onelight::world {

struct ChartOptions {
    double texelsPerMetre = 16.0;  // requested density; a chart too big for an atlas gets less
    bool densityFromCommandLine = false;  // when false, a level's own density wins
    uint32_t atlasSize = 1024;            // texels per side of a generated atlas
    uint32_t padding = 2;                 // texels kept free on each side of a chart, >= 2
    double maxNormalAngleDegrees = 40.0;  // between a triangle and its chart's normal
    // Per generated chart, in chart order, a factor (0, 1] on its density (a pilot bake's
    // choice, bake/lightmap/chart_density.hpp); empty: 1 for every chart. The charts' shapes
    // do not depend on it, so the same level gives the same charts with fewer texels.
    std::vector<float> densityScale;
};

/// A generated chart before packing: its triangles and its planar projection.
struct ChartShape {
    std::vector<uint32_t> triangles;  // into StaticGeometry::triangles
    uint32_t instance = kNoIndex;
    bool authored = false;
    glm::dvec3 normal{0.0}, axisU{0.0}, axisV{0.0};
    glm::dvec2 minUv{0.0}, maxUv{0.0};  // metres along axisU / axisV
    double texelsPerMetre = 0.0;
    uint32_t width = 0, height = 0;  // texels, padding included
};

/// Groups the triangles into chart shapes and sets StaticTriangle::chart to the shape index.
[[nodiscard]] std::vector<ChartShape> buildChartShapes(StaticGeometry& geometry,
                                                       const ChartOptions& options);

}  // namespace onelight::world
