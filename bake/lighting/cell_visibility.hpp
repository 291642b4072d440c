// How much of each light the surfaces of a light cell see: a few points on the scene's
// triangles inside each cell, each testing the light with one shadow ray. The light cells
// (light_cells.hpp) weigh a light by it, so that a sun no interior surface sees, or a lamp
// behind a wall, is rarely drawn there.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/light_cells.hpp"

namespace onelight::bake {

/// Up to kPointsPerCell points on the scene's surfaces in each cell of `cells`, off the surface
/// along its front normal: area-uniform, chosen by a hash of (triangle, sample), so the same
/// scene gives the same points.
struct CellSurfacePoints {
    static constexpr uint32_t kPointsPerCell = 16;
    std::vector<uint32_t> first;  // cellCount + 1 offsets
    std::vector<glm::vec3> position, normal;
};
[[nodiscard]] CellSurfacePoints surfacePointsOfCells(const BakeScene& scene,
                                                     const LightCells& cells);

/// The fraction of cell `cell`'s points that see a light, `sees(position, normal)` testing one;
/// -1 when the cell has no surface point (then nothing is known).
template <typename Sees>
[[nodiscard]] float visibleFraction(const CellSurfacePoints& points, uint32_t cell, Sees&& sees) {
    const uint32_t begin = points.first[cell], end = points.first[cell + 1];
    if (begin == end) return -1.0f;
    uint32_t seen = 0;
    for (uint32_t i = begin; i < end; ++i) seen += sees(points.position[i], points.normal[i]);
    return static_cast<float>(seen) / static_cast<float>(end - begin);
}

}  // namespace onelight::bake
