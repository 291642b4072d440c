// Feature analysis: which material classes, light types, effect lights, probes and light-grid
// extent the level needs, so the baker and the runtime build only those.
#pragma once

#include "world/compiled_level.hpp"

namespace onelight::world {

/// Reads everything but `level.features` and returns what to put there. The grid covers the
/// authored bounds when given (`authored_grid`), else the static bounds grown by `gridMargin`
/// metres on each side.
[[nodiscard]] Features analyseFeatures(const CompiledLevel& level, bool hasAuthoredGrid,
                                       const glm::vec3& authoredGridMin,
                                       const glm::vec3& authoredGridMax, float gridMargin = 1.0f);

/// Where the level's dynamic objects can go: the world box of every dynamic entity's meshes at
/// its place and, for a mover, at the poses that bound its path (world::moverReach: a straight
/// move's box is the union of its ends' boxes; a turn's is sampled every eighth of a turn). False
/// when the level has no dynamic entity with a vertex.
[[nodiscard]] bool dynamicObjectReach(const CompiledLevel& level, glm::vec3& boxMin,
                                      glm::vec3& boxMax);

}  // namespace onelight::world
