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

}  // namespace onelight::world
