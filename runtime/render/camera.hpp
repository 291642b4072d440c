// Cameras, their matrices (Vulkan clip space: Y down, depth 0..1) and frustum culling.
#pragma once

#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "world/compiled_level.hpp"

namespace onelight::render {

/// A perspective camera. It looks down its local -Z with +Y up, as glTF cameras do.
struct Camera {
    glm::vec3 position{0.0f};                    // metres, world
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // world from camera
    float yfov = 1.0f;                           // radians
    float znear = 0.05f;                         // metres
    float zfar = 0.0f;                           // metres; 0 = fitted to the level bounds
    bool hasExposure = false;                    // ev100 is set; else the level's or automatic
    float ev100 = 0.0f;
};

/// A camera at `position` turned by yaw (degrees about +Y; 0 looks down -Z, 90 down -X) and
/// pitch (degrees, up positive).
[[nodiscard]] Camera cameraFromYawPitch(glm::vec3 position, float yawDegrees, float pitchDegrees);

/// The level's camera, as the package stores it (orthographic cameras become perspective).
[[nodiscard]] Camera cameraFromLevel(const world::Camera& camera);

/// Unit vector the camera looks along.
[[nodiscard]] glm::vec3 forwardOf(const Camera& camera);

[[nodiscard]] glm::mat4 viewMatrix(const Camera& camera);

/// Perspective projection with Y flipped for Vulkan and depth in [0, 1].
[[nodiscard]] glm::mat4 projectionMatrix(const Camera& camera, float aspect, float zfar);

/// Six inward planes (xyz normal, w offset) of a clip-from-world matrix.
struct Frustum {
    glm::vec4 planes[6];
};
[[nodiscard]] Frustum frustumOf(const glm::mat4& clipFromWorld);

/// False when the box lies entirely outside one plane.
[[nodiscard]] bool intersects(const Frustum& frustum, glm::vec3 boxMin, glm::vec3 boxMax);

}  // namespace onelight::render
