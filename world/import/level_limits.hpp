// The extremes an imported level may reach, checked once after import (glTF and Quake 3 alike)
// so that nothing downstream (the BSP, charts, Embree, the GPU's floats) meets a value it cannot
// represent. docs/limits.md lists them with what happens past each.
#pragma once

#include <cstdint>

#include "world/source_level.hpp"

namespace onelight::world {

/// Largest |x|, |y| or |z| of any world position: vertices after their node's transform,
/// lights, cameras, entities, boxes. 1000 km: a float there still resolves 6 cm (a level 100 km
/// from the origin compiles and bakes, tests/world/compile_test.cpp), and Embree and the BSP stay
/// far from overflow (Embree rejects rays past 1.8e19).
inline constexpr double kMaxCoordinateMetres = 1e6;

/// Most triangles (static and dynamic, after import) and most lights a level may have.
inline constexpr uint64_t kMaxLevelTriangles = uint64_t(1) << 26;  // 67M
inline constexpr uint64_t kMaxLevelLights = 65536;
/// Most vertices the import may build (a Quake 3 map's surfaces each copy their vertex range,
/// which many may share; its patches make (level + 1)^2 a piece).
inline constexpr uint64_t kMaxLevelVertices = uint64_t(1) << 26;

/// Throws world::Error naming `level.sourcePath`, the element and the limit when the level
/// passes one of the limits above.
void checkLevelLimits(const SourceLevel& level);

}  // namespace onelight::world
