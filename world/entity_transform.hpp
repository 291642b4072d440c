// Where a level entity's mesh is in the world: the one object-to-world matrix of an entity, for
// the renderer (placement in the package) and the game (an entity that moved).
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "world/compiled_level.hpp"

namespace onelight::world {

/// World from object for entity `e` with its origin at `position` (metres, world): e's scale,
/// then its rotation (normalised), then a turn of `yaw` radians about +y (a spinning item's;
/// positive turns left seen from above), then the translation.
[[nodiscard]] inline glm::mat4 worldFromObject(const Entity& e, glm::vec3 position,
                                               float yaw = 0.0f) {
    glm::quat rotation = glm::normalize(e.rotation);
    if (yaw != 0.0f) rotation = glm::angleAxis(yaw, glm::vec3(0.0f, 1.0f, 0.0f)) * rotation;
    glm::mat4 m = glm::mat4_cast(rotation);
    m[0] *= e.scale.x;
    m[1] *= e.scale.y;
    m[2] *= e.scale.z;
    m[3] = glm::vec4(position, 1.0f);
    return m;
}

/// The same with a general `turn` after e's rotation (a mover's, world/movers.hpp).
[[nodiscard]] inline glm::mat4 worldFromObject(const Entity& e, glm::vec3 position,
                                               glm::quat turn) {
    glm::mat4 m = glm::mat4_cast(glm::normalize(turn * glm::normalize(e.rotation)));
    m[0] *= e.scale.x;
    m[1] *= e.scale.y;
    m[2] *= e.scale.z;
    m[3] = glm::vec4(position, 1.0f);
    return m;
}

}  // namespace onelight::world
