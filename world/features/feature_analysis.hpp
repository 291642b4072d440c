// Feature analysis: which material classes, light types, effect lights, probes and light-grid
// extent the level needs, so the baker and the runtime build only those.
#pragma once

#include "world/compiled_level.hpp"

namespace onelight::world {

/// Reads everything but `level.features` and returns what to put there. The grid covers the
/// authored bounds when given (`authored_grid`), else the static bounds grown by `grid_margin`
/// metres on each side.
Features analyse_features(const CompiledLevel& level, bool has_authored_grid,
                          const glm::vec3& authored_grid_min, const glm::vec3& authored_grid_max,
                          float grid_margin = 1.0f);

}  // namespace onelight::world
