#include "free_fly.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

namespace onelight::game {

FreeFly freeFlyFrom(const render::Camera& camera) {
    FreeFly fly;
    fly.position = camera.position;
    const glm::vec3 f = render::forwardOf(camera);
    fly.yawDegrees = glm::degrees(std::atan2(-f.x, -f.z));
    fly.pitchDegrees = glm::degrees(std::asin(std::clamp(f.y, -1.0f, 1.0f)));
    return fly;
}

void updateFreeFly(FreeFly& fly, GLFWwindow* window, float seconds) {
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    if (fly.hasCursor) {
        fly.yawDegrees -= float(x - fly.lastX) * 0.15f;
        fly.pitchDegrees =
            std::clamp(fly.pitchDegrees - float(y - fly.lastY) * 0.15f, -89.0f, 89.0f);
    }
    fly.lastX = x;
    fly.lastY = y;
    fly.hasCursor = true;

    const render::Camera c =
        render::cameraFromYawPitch(fly.position, fly.yawDegrees, fly.pitchDegrees);
    const glm::vec3 forward = render::forwardOf(c);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    glm::vec3 move(0.0f);
    if (glfwGetKey(window, GLFW_KEY_W) == GLFW_PRESS) move += forward;
    if (glfwGetKey(window, GLFW_KEY_S) == GLFW_PRESS) move -= forward;
    if (glfwGetKey(window, GLFW_KEY_D) == GLFW_PRESS) move += right;
    if (glfwGetKey(window, GLFW_KEY_A) == GLFW_PRESS) move -= right;
    if (glfwGetKey(window, GLFW_KEY_E) == GLFW_PRESS) move.y += 1.0f;
    if (glfwGetKey(window, GLFW_KEY_Q) == GLFW_PRESS) move.y -= 1.0f;
    const float boost = glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ? 4.0f : 1.0f;
    if (glm::dot(move, move) > 0.0f)
        fly.position += glm::normalize(move) * (fly.speed * boost * seconds);
}

render::Camera cameraOf(const FreeFly& fly, const render::Camera& lens) {
    render::Camera c = render::cameraFromYawPitch(fly.position, fly.yawDegrees, fly.pitchDegrees);
    c.yfov = lens.yfov;
    c.znear = lens.znear;
    c.zfar = lens.zfar;
    c.hasExposure = lens.hasExposure;
    c.ev100 = lens.ev100;
    return c;
}

}  // namespace onelight::game
