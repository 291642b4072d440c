// A view for a map without a player spawn, computed from its geometry: a player's eye height
// above the floor in the middle of the largest open area found, looking along the level's longest
// horizontal axis (towards the more open side). Candidates lie on a lattice over the level's
// bounds, each dropped to the floor below it; a candidate counts as inside the level when rays
// in the ten directions around it (the six axes and four horizontal diagonals) hit the front of
// the level's surfaces, the upward one excepted (open sky leaves no surface). A point inside a
// wall or outside the level sees the back of the faces around it (q3map2 removes the faces
// inside brushes), so it is never chosen. Brute-force ray casts: a second or two on a
// 100 000-triangle map, and only for maps without a spawn.
#pragma once

#include <optional>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "world/source_level.hpp"

namespace onelight::world::q3 {

struct ComputedView {
    glm::vec3 feet{0.0f};                        // on the floor, metres
    glm::vec3 eye{0.0f};                         // kComputedViewEyeHeight above the feet
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // a camera's -Z along `forward`
    glm::vec3 forward{0.0f, 0.0f, -1.0f};        // horizontal
};

/// A Quake 3 player's eyes above the floor: 50 units (feet at -24, eyes at +26).
inline constexpr float kComputedViewEyeHeight = 50.0f / 32.0f;

/// Nothing when no candidate is inside the level (no geometry, or no closed space).
[[nodiscard]] std::optional<ComputedView> computeViewInside(const SourceLevel& level);

/// Whether `point` is inside the level by the test above (for checks and tests).
[[nodiscard]] bool insideLevel(const SourceLevel& level, glm::vec3 point);

}  // namespace onelight::world::q3
