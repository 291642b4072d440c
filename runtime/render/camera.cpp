#include "render/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace onelight::render {

Camera cameraFromYawPitch(glm::vec3 position, float yawDegrees, float pitchDegrees) {
    Camera c;
    c.position = position;
    c.rotation = glm::angleAxis(glm::radians(yawDegrees), glm::vec3(0.0f, 1.0f, 0.0f)) *
                 glm::angleAxis(glm::radians(pitchDegrees), glm::vec3(1.0f, 0.0f, 0.0f));
    return c;
}

Camera cameraFromLevel(const world::Camera& camera) {
    Camera c;
    c.position = camera.position;
    c.rotation = glm::normalize(camera.rotation);
    c.yfov = camera.orthographic ? 1.0f : camera.yfov;
    c.znear = camera.znear > 0.0f ? camera.znear : 0.05f;
    c.zfar = camera.zfar;
    c.hasExposure = camera.hasExposure;
    c.ev100 = camera.exposureEv100;
    return c;
}

glm::vec3 forwardOf(const Camera& camera) {
    return camera.rotation * glm::vec3(0.0f, 0.0f, -1.0f);
}

glm::mat4 viewMatrix(const Camera& camera) {
    glm::mat4 worldFromCamera = glm::mat4_cast(camera.rotation);
    worldFromCamera[3] = glm::vec4(camera.position, 1.0f);
    return glm::inverse(worldFromCamera);
}

glm::mat4 projectionMatrix(const Camera& camera, float aspect, float zfar) {
    glm::mat4 p = glm::perspectiveRH_ZO(camera.yfov, aspect, camera.znear, zfar);
    p[1][1] = -p[1][1];
    return p;
}

Frustum frustumOf(const glm::mat4& m) {
    // Gribb and Hartmann 2001: rows of the matrix; Vulkan depth 0..1 makes near = row 2.
    const glm::mat4 t = glm::transpose(m);
    Frustum f;
    f.planes[0] = t[3] + t[0];
    f.planes[1] = t[3] - t[0];
    f.planes[2] = t[3] + t[1];
    f.planes[3] = t[3] - t[1];
    f.planes[4] = t[2];
    f.planes[5] = t[3] - t[2];
    return f;
}

bool intersects(const Frustum& frustum, glm::vec3 boxMin, glm::vec3 boxMax) {
    for (const glm::vec4& plane : frustum.planes) {
        const glm::vec3 far(plane.x >= 0.0f ? boxMax.x : boxMin.x,
                            plane.y >= 0.0f ? boxMax.y : boxMin.y,
                            plane.z >= 0.0f ? boxMax.z : boxMin.z);
        if (glm::dot(glm::vec3(plane), far) + plane.w < 0.0f) return false;
    }
    return true;
}

}  // namespace onelight::render
