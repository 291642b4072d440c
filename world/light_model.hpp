// A level light seen from a point, by the shared light model of shaders/lighting.glsl
// (evaluatePunctualLight): the one C++ door to it for world::Light, used by the baker, the game
// and the tests, so that every consumer evaluates a light the way the shader does.
#pragma once

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"

namespace onelight::world {

/// The runtime's default reach of per-pixel shadows from the camera (RendererOptions::
/// shadowRadius) and the band inside it over which they blend into the baked shadow mask: a
/// surface shows its baked mask only beyond kRuntimeShadowRadius - kRuntimeShadowBand metres.
inline constexpr float kRuntimeShadowRadius = 40.0f;  // metres
inline constexpr float kRuntimeShadowBand = 8.0f;     // metres

/// What a light delivers at a point, before any shadowing.
struct LightAtPoint {
    glm::vec3 toLight{0.0f, 0.0f, 1.0f};  // unit, from the point towards the light
    glm::vec3 illuminance{0.0f};          // lux at normal incidence, RGB
    float distance = 0.0f;                // metres to the light; 0 for a directional light
};

/// `light` at world point `point`: inverse-square falloff, the range window and the spot cone
/// for point and spot lights, the constant illuminance of a directional light (glTF units).
[[nodiscard]] LightAtPoint evaluateLight(const Light& light, glm::vec3 point);

/// The luminance (lux) of evaluateLight's illuminance: how bright the light is at the point.
[[nodiscard]] float unshadowedIlluminance(const Light& light, glm::vec3 point);

/// unshadowedIlluminance on a surface facing `normal`: times the cosine max(0, n.l) of the
/// normalised normal; a zero normal means "ignore orientation" (no cosine term). 0 where the
/// result is not finite.
[[nodiscard]] float unshadowedIlluminance(const Light& light, glm::vec3 point, glm::vec3 normal);

}  // namespace onelight::world
