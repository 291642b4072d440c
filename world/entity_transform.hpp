// Where a level entity's mesh is in the world: the one object-to-world matrix of an entity, for
// the renderer (placement in the package) and the game (an entity that moved).
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "world/compiled_level.hpp"

namespace onelight::world {

/// World from object for entity `e` with its origin at `position` (metres, world): e's scale,
/// then its rotation (normalised), then the translation.
[[nodiscard]] inline glm::mat4 worldFromObject(const Entity& e, glm::vec3 position) {
    glm::mat4 m = glm::mat4_cast(glm::normalize(e.rotation));
    m[0] *= e.scale.x;
    m[1] *= e.scale.y;
    m[2] *= e.scale.z;
    m[3] = glm::vec4(position, 1.0f);
    return m;
}

}  // namespace onelight::world
