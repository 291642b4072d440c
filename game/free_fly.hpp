// The free-fly camera of the window: WASD moves (Shift faster, Q/E down/up), the mouse looks.
#pragma once

#include <glm/glm.hpp>

#include "render/camera.hpp"

struct GLFWwindow;

namespace onelight::game {

struct FreeFly {
    glm::vec3 position{0.0f};
    float yawDegrees = 0.0f, pitchDegrees = 0.0f;
    float speed = 3.0f;  // metres per second
    double lastX = 0.0, lastY = 0.0;
    bool hasCursor = false;
};

/// Starts from a camera's position and look direction.
[[nodiscard]] FreeFly freeFlyFrom(const render::Camera& camera);

/// Applies the keys held and the mouse motion over `seconds`.
void updateFreeFly(FreeFly& fly, GLFWwindow* window, float seconds);

/// The camera it gives, keeping the lens of `lens`.
[[nodiscard]] render::Camera cameraOf(const FreeFly& fly, const render::Camera& lens);

}  // namespace onelight::game
