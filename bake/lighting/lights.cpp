#include "bake/lighting/lights.hpp"

#include <cmath>
#include <limits>

#include "world/light_model.hpp"

namespace onelight::bake {

BakeLights make_bake_lights(const std::vector<world::Light>& level_lights, const LightSizes& sizes,
                            glm::vec3 sky_radiance) {
    BakeLights out;
    out.sky_radiance = sky_radiance;
    for (size_t i = 0; i < level_lights.size(); ++i) {
        const world::Light& l = level_lights[i];
        if (l.role == world::LightRole::effect) continue;
        BakeLight b;
        b.light = l;
        b.level_index = static_cast<uint32_t>(i);
        b.radius =
            l.type == world::LightType::directional ? sizes.sun_angular_radius : sizes.point_radius;
        out.lights.push_back(b);
    }
    return out;
}

LightIncidence light_incidence(const BakeLight& light, const glm::vec3& position) {
    // The runtime's own evaluation (shaders/lighting.glsl), so bake and runtime agree exactly.
    const world::Light& l = light.light;
    const world::LightAtPoint sample = world::evaluateLight(l, position);
    LightIncidence out;
    out.direction = sample.toLight;
    out.distance = l.type == world::LightType::directional ? std::numeric_limits<float>::infinity()
                                                           : sample.distance;
    const glm::vec3 e = sample.illuminance;
    const bool finite = std::isfinite(e.x) && std::isfinite(e.y) && std::isfinite(e.z);
    out.irradiance = finite ? glm::max(e, glm::vec3(0.0f)) : glm::vec3(0.0f);
    return out;
}

LightDirection sample_light_direction(const BakeLight& light, const LightIncidence& incidence,
                                      glm::vec2 u, float scene_diameter) {
    LightDirection out;
    float one_minus_cos_max;
    if (light.light.type == world::LightType::directional) {
        const float s = std::sin(0.5f * light.radius);
        one_minus_cos_max = 2.0f * s * s;  // 1 - cos r = 2 sin^2(r / 2), no cancellation
        out.shadow_distance = scene_diameter;
    } else {
        if (incidence.distance <= light.radius) {  // inside the light: its centre, unshadowed
            out.direction = incidence.direction;
            out.shadow_distance = 0.0f;
            return out;
        }
        const float sin_max = light.radius / incidence.distance;
        const float sin2 = sin_max * sin_max;
        one_minus_cos_max = sin2 / (1.0f + std::sqrt(std::max(0.0f, 1.0f - sin2)));
        out.shadow_distance = incidence.distance - light.radius;
    }
    const glm::vec3 local = sample_uniform_cone(u, one_minus_cos_max);
    out.direction = glm::normalize(frame_around(incidence.direction).to_world(local));
    return out;
}

float light_visibility(const BakeScene& scene, const BakeLight& light,
                       const LightIncidence& incidence, const glm::vec3& origin, uint32_t samples,
                       Rng& rng, RayCounts& rays) {
    if (samples == 0) return 1.0f;
    const float s0 = rng.next(), s1 = rng.next();
    uint32_t visible = 0;
    for (uint32_t i = 0; i < samples; ++i) {
        const LightDirection d = sample_light_direction(
            light, incidence, rotated_hammersley(i, samples, s0, s1), scene.scene_diameter());
        if (d.shadow_distance <= 0.0f ||
            !scene.occluded(origin, d.direction, d.shadow_distance, rays.shadow))
            ++visible;
    }
    return static_cast<float>(visible) / static_cast<float>(samples);
}

}  // namespace onelight::bake
