// The static/dynamic split: static mesh instances become one world-space triangle soup for the
// BSP, without degenerate (zero-area) triangles or exact duplicates; dynamic instances stay in
// their entity's space as dynamic meshes.
#pragma once

#include <cstdint>
#include <vector>

#include "world/source_level.hpp"
#include "world/static_geometry.hpp"

namespace onelight::world {

struct SplitLevel {
    StaticGeometry static_geometry;
    std::vector<Vertex> dynamic_vertices;
    std::vector<uint32_t> dynamic_indices;
    std::vector<DynamicMesh> dynamic_meshes;  // grouped by entity
    std::vector<Entity> entities;             // with their dynamic-mesh ranges filled
    uint32_t degenerate_removed = 0;          // zero-area triangles dropped
    uint32_t duplicates_removed = 0;          // exact duplicates (same corners, same winding)
};

/// Throws Error when a world transform turns a position into NaN or Inf.
SplitLevel split_static_dynamic(const SourceLevel& level);

}  // namespace onelight::world
