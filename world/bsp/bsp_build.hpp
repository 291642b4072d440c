// Builds the BSP over the static triangles. Splitting planes come from the polygons: each node
// tries the planes of a spread of its triangles (and, when those leave it unbalanced, as with a
// subdivided flat floor, the planes through their edges along their normals) and keeps the one
// with the lowest splitWeight * splits + |front - back|, which trades splits against depth.
// Triangles that straddle the plane are cut (attributes interpolated, cut points shared along an
// edge so no crack opens); a triangle in the plane goes to the side its normal faces. Leaves hold
// the triangles, so every triangle lies in exactly one leaf.
#pragma once

#include <cstdint>
#include <vector>

#include "world/compiled_level.hpp"
#include "world/static_geometry.hpp"

namespace onelight::world {

struct BspOptions {
    uint32_t maxLeafTriangles = 32;  // a node with this many or fewer becomes a leaf
    uint32_t maxDepth = 48;
    uint32_t candidatePlanes = 24;  // planes tried per node
    double splitWeight = 8.0;       // cost of one split against one triangle of imbalance
};

struct BspBuild {
    std::vector<BspPlane> planes;
    std::vector<BspNode> nodes;   // node 0 is the root when any exists
    std::vector<BspLeaf> leaves;  // firstTriangle/triangle_count into geometry.triangles
    uint32_t depth = 0;           // longest root-to-leaf path, in nodes
    uint32_t splits = 0;          // triangles cut by a plane
    double epsilon = 0.0;         // metres: |distance| below this counts as on the plane
};

/// Builds the tree and reorders geometry.triangles leaf by leaf.
[[nodiscard]] BspBuild buildBsp(StaticGeometry& geometry, const BspOptions& options);

}  // namespace onelight::world
