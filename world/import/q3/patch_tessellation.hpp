// Quake 3 patches: a grid of biquadratic Bezier pieces (3 x 3 controls each, sharing their
// border rows and columns) tessellated into triangles at a fixed level, watertight where
// patches meet.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace onelight::world::q3 {

/// A control point or a tessellated vertex: what a patch interpolates.
struct PatchPoint {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec2 uv{0.0f};
    glm::vec2 lightmapUv{0.0f};   // q3map2's lightmap coordinates
    glm::vec3 vertexLight{0.0f};  // q3map2's vertex light, 0..255
};

struct PatchMesh {
    std::vector<PatchPoint> vertices;
    std::vector<uint32_t> triangles;  // in the grid's order; the importer orients them
};

/// Tessellates a width x height control grid (odd sizes >= 3, row-major) with `level` segments
/// per piece and direction (level >= 1).
/*
   Each piece's point at (i, j) of (L + 1)^2 evaluates, row by row, the quadratic Bezier
       B(P0, P1, P2; k) = ((L - k)^2 P0 + k^2 P2 + 2 k (L - k) P1) / L^2,  with B(..; 0) = P0 and
       B(..; L) = P2 exactly,
   the two end terms summed first. Reversing the curve (P0 <-> P2, k <-> L - k) swaps those two
   terms, and float addition is commutative, so a border evaluates to the same bits from either
   side and in either direction: two patches that share a border's three controls share its
   vertices bit for bit, and no crack opens (at the same level).
*/
[[nodiscard]] PatchMesh tessellatePatch(const std::vector<PatchPoint>& controls, uint32_t width,
                                        uint32_t height, uint32_t level);

}  // namespace onelight::world::q3
