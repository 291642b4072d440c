// The light grid (package section 34) read at a point, on the CPU, as every consumer reads it:
// the renderer once per dynamic object and frame, the game for primaries and exposure, the
// baker for the probes' normalization.
#pragma once

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "world/baked_lighting.hpp"

namespace onelight::world {

/// The grid at a point: trilinear interpolation between the centres of the (up to) eight cells
/// around it, cells flagged inside solid skipped and the other weights renormalised to sum 1.
/// Outside the grid the point is clamped to the outermost cell centres. When every corner is
/// inside solid, plain trilinear weights over all eight are used instead (`allSolid`).
struct LightGridSample {
    std::array<glm::vec3, 6> ambientCube{};  // lux, faces +x -x +y -y +z -z
    std::array<uint32_t, 8> cells{};         // corner cells (x-fastest indices); weight 0 = unused
    std::array<float, 8> weights{};          // renormalised, sum 1
    bool allSolid = false;
};

/// Samples `grid` at world point p. The grid must have cells (dims >= 1 each).
[[nodiscard]] LightGridSample sampleLightGrid(const LightGrid& grid, glm::vec3 p);

/// Sum of weight * primaryVisibility over the corners whose dominant primary is `light`: the
/// baked score of that light at the sample, before its illuminance (0 when it dominates none).
[[nodiscard]] float dominantVisibility(const LightGrid& grid, const LightGridSample& sample,
                                       uint32_t light);

/// The baked visibility of `light` at the sample: primaryVisibility averaged (by weight) over
/// the corners where it is the dominant primary; 0 when it dominates none of them.
[[nodiscard]] float bakedVisibility(const LightGrid& grid, const LightGridSample& sample,
                                    uint32_t light);

}  // namespace onelight::world
