// The static triangles of a level while it compiles: world-space vertices in double precision
// (so splitting keeps area and huge coordinates keep their digits) and per-triangle tags that
// each stage fills in (primary by regions, chart by charts, leaf order by the BSP).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"

namespace onelight::world {

struct CompileVertex {
    glm::dvec3 position{0.0};  // metres, world space
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};
    glm::vec2 uv0{0.0f};
    glm::vec2 uv1{0.0f};  // authored TEXCOORD_1, or chart coordinates once charts are built
};

struct StaticTriangle {
    std::array<uint32_t, 3> v{};  // into StaticGeometry::vertices, counter-clockwise
    uint32_t material = kNoIndex;
    uint32_t instance = kNoIndex;  // the mesh instance it came from
    uint32_t primary = kNoIndex;   // primary index (into the level's primary list), regions stage
    uint32_t chart = kNoIndex;     // charts stage
};

struct StaticGeometry {
    std::vector<CompileVertex> vertices;
    std::vector<StaticTriangle> triangles;
    std::vector<uint8_t> instanceHasUv1;     // per source instance
    std::vector<std::string> instanceNames;  // per source instance, "node/mesh"
    std::vector<uint8_t> instanceIsProp;     // per source instance: one primary, at its origin
    std::vector<glm::dvec3> instanceLightingOrigin;  // per source instance (props'), world
};

/// Attribute-wise interpolation a + t (b - a), normal and tangent renormalised.
[[nodiscard]] CompileVertex interpolate(const CompileVertex& a, const CompileVertex& b, double t);

/// Twice the area vector of the triangle (cross product of its edges), metres squared.
[[nodiscard]] glm::dvec3 areaVector(const StaticGeometry& geometry, const StaticTriangle& triangle);

/// Area of the triangle, metres squared.
[[nodiscard]] double triangleArea(const StaticGeometry& geometry, const StaticTriangle& triangle);

/// Sum of every triangle's area, metres squared (Kahan-summed).
[[nodiscard]] double totalArea(const StaticGeometry& geometry);

}  // namespace onelight::world
