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

}  // namespace onelight::world
