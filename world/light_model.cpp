#include "world/light_model.hpp"

#include <cmath>

#include "shading.hpp"

namespace onelight::world {

LightAtPoint evaluateLight(const Light& light, glm::vec3 point) {
    // light.direction is unit (the importer normalises it), as the shader's GpuLight.
    const glsl::LightSample s = glsl::evaluatePunctualLight(
        int(light.type), light.color, light.intensity, light.range, light.position, light.direction,
        std::cos(light.innerCone), std::cos(light.outerCone), point);
    return {s.l, s.illuminance, s.distance};
}

float unshadowedIlluminance(const Light& light, glm::vec3 point) {
    return glsl::luminance(evaluateLight(light, point).illuminance);
}

float unshadowedIlluminance(const Light& light, glm::vec3 point, glm::vec3 normal) {
    const LightAtPoint at = evaluateLight(light, point);
    const float cosine = normal == glm::vec3(0.0f)
                             ? 1.0f
                             : glsl::max(0.0f, glm::dot(glm::normalize(normal), at.toLight));
    const float e = glsl::luminance(at.illuminance) * cosine;
    return std::isfinite(e) && e > 0.0f ? e : 0.0f;
}

}  // namespace onelight::world
