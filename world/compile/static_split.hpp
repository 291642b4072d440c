// The static/dynamic split: static mesh instances become one world-space triangle soup for the
// BSP, without degenerate (zero-area) triangles or exact duplicates; dynamic instances stay in
// their entity's space as dynamic meshes, identical ones (the items of a class) sharing one copy
// of their vertices and indices.
#pragma once

#include <cstdint>
#include <vector>

#include "world/source_level.hpp"
#include "world/static_geometry.hpp"

namespace onelight::world {

struct SplitLevel {
    StaticGeometry staticGeometry;
    std::vector<Vertex> dynamicVertices;
    std::vector<uint32_t> dynamicIndices;
    std::vector<DynamicMesh> dynamicMeshes;  // grouped by entity
    std::vector<Entity> entities;            // with their dynamic-mesh ranges filled
    uint32_t degenerateRemoved = 0;          // zero-area triangles dropped
    uint32_t duplicatesRemoved = 0;          // exact duplicates (same corners, same winding)
    uint32_t dynamicMeshesShared = 0;        // dynamic meshes drawn from an earlier one's copy
};

/// Throws Error when a world transform turns a position into NaN or Inf.
[[nodiscard]] SplitLevel splitStaticDynamic(const SourceLevel& level);

}  // namespace onelight::world
