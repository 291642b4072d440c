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

/// What carries an instance's vertices into world space: the cofactor matrix of the linear part
/// carries normals (det * inverse transpose, signed so that a mirror keeps the side; defined
/// even when the transform is singular), and a mirror flips the bitangent's sign and the winding.
struct InstanceTransform {
    glm::dmat4 worldFromLocal{1.0};
    glm::dmat3 normalMatrix{1.0};
    bool mirrored = false;  // determinant < 0: swap two corners of each triangle
};
[[nodiscard]] InstanceTransform instanceTransformOf(const glm::dmat4& worldFromLocal);

/// `v` in world space: the position in double precision, unit normal and tangent (+z and +x
/// where the transform collapses them).
[[nodiscard]] CompileVertex worldVertexOf(const Vertex& v, const InstanceTransform& transform);

/// Throws Error when a world transform turns a position into NaN or Inf.
[[nodiscard]] SplitLevel splitStaticDynamic(const SourceLevel& level);

}  // namespace onelight::world
