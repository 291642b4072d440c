// The light grid: a 3D grid over the level (or its authored bounds) for dynamic objects. Each
// cell holds the secondary irradiance as an ambient cube, the dominant primary at its centre
// and that primary's visibility; cells whose centre is inside solid geometry are flagged.
#pragma once

#include <cstdint>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/lights.hpp"
#include "bake/lighting/radiance.hpp"
#include "bake/report/progress.hpp"
#include "world/baked_lighting.hpp"

namespace onelight::bake {

struct GridSettings {
    float cellSize = 1.0f;          // metres, requested
    uint32_t maxCellsPerAxis = 64;  // cells grow past cellSize to stay under this
    uint32_t samples = 256;         // sphere directions per cell
    uint32_t shadowSamples = 16;    // per light per cell
    float insideFraction = 0.5f;    // back-face hits above this fraction: inside solid (a
                                    // block's face coplanar with a wall may be met as either)
    bool punctualDirect = true;     // false: the cells leave out every punctual light's direct
                                    // light (the probes' statistic, probeIrradianceCubes)
    TransportSettings transport;
};

/// Origin, cell size and dimensions (cells empty) over the authored grid bounds when the
/// level has them, else over the static geometry's bounds and wherever its dynamic objects go
/// (world::dynamicObjectReach: a mover may rise above an open floor).
[[nodiscard]] world::LightGrid layoutLightGrid(const world::CompiledLevel& level,
                                               const GridSettings& settings);
/// The same over the box [boxMin, boxMax].
[[nodiscard]] world::LightGrid layoutLightGridOver(glm::vec3 boxMin, glm::vec3 boxMax,
                                                   const GridSettings& settings);

struct GridStats {
    RayCounts rays;
    uint64_t cellsBaked = 0;
    uint64_t cellsInside = 0;
};

/// Bakes cells [cellBegin, cellEnd) of `grid` (cells already sized). Each cell's random
/// sequence is seeded from its index.
/*
   Ambient cube face a (unit axis):  E_a = int_{S^2} L(w) max(0, a . w) dw
   with w uniform on the sphere (pdf 1 / (4 pi)) on a rotated Hammersley set:
     E_a ~ (4 pi / N) sum_i L(w_i) max(0, a . w_i)
   plus the non-dominant lights' direct part, analytic with stratified visibility:
     E_a += sum_{l != dominant} E_l V_l max(0, a . w_l)
                 +----------------------------------------------------------------+
                 | E_a ~ (4 pi / N) sum_i L(w_i) (a.w_i)+ + sum_l E_l V_l (a.w_l)+ |
                 +----------------------------------------------------------------+
   Dominant primary: argmax over primaries of Y(E_l) V_l (no cosine: an object's orientation
   is unknown), lowest index on ties.
*/
[[nodiscard]] GridStats bakeLightGrid(const BakeScene& scene, const BakeLights& lights,
                                      const GridSettings& settings, uint64_t cellBegin,
                                      uint64_t cellEnd, world::LightGrid& grid, Progress* progress);

/// Irradiance (lux) on a surface of normal n from an ambient cube: n.x^2 C[+-x] + ...
[[nodiscard]] glm::vec3 ambientCubeIrradiance(const world::LightGridCell& cell, const glm::vec3& n);

}  // namespace onelight::bake
