#include <algorithm>
#include <cmath>

#include "world/regions/primary_illuminance.hpp"

namespace onelight::world {
namespace {

/// Distances below this (metres) are clamped so a point on a light stays finite.
constexpr double kMinimumDistance = 1e-2;

double luminance(const glm::vec3& c) {
    return glm::dot(glm::dvec3(c), glm::dvec3(0.2126, 0.7152, 0.0722));
}

double cosine_term(const glm::vec3& normal, const glm::dvec3& to_light) {
    if (normal == glm::vec3(0.0f)) return 1.0;
    return std::max(0.0, glm::dot(glm::dvec3(normal), to_light));
}

double illuminance_of(const Light& light, const glm::dvec3& position, const glm::vec3& normal) {
    const double power = static_cast<double>(light.intensity) * luminance(light.color);
    if (light.type == LightType::directional)
        return power * cosine_term(normal, -glm::dvec3(light.direction));
    const glm::dvec3 offset = glm::dvec3(light.position) - position;
    const double distance = std::max(glm::length(offset), kMinimumDistance);
    const glm::dvec3 to_light = offset / distance;
    // KHR_lights_punctual recommended range window: saturate(1 - (d / range)^4)^2
    double window = 1.0;
    if (light.range > 0.0f) {
        const double ratio = distance / static_cast<double>(light.range);
        const double w = std::clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
        window = w * w;
    }
    double cone = 1.0;
    if (light.type == LightType::spot) {
        // KHR_lights_punctual spot falloff: smooth between the cosines of the cone angles
        const double cos_outer = std::cos(static_cast<double>(light.outer_cone));
        const double cos_inner = std::cos(static_cast<double>(light.inner_cone));
        const double cd = glm::dot(glm::dvec3(light.direction), -to_light);
        const double t =
            std::clamp((cd - cos_outer) / std::max(cos_inner - cos_outer, 1e-4), 0.0, 1.0);
        cone = t * t;
    }
    return power * window * cone * cosine_term(normal, to_light) / (distance * distance);
}

}  // namespace

uint32_t dominant_primary(std::span<const double> illuminance) {
    uint32_t best = kNoIndex;
    double best_value = 0.0;
    for (size_t i = 0; i < illuminance.size(); ++i) {
        if (illuminance[i] > best_value) {
            best_value = illuminance[i];
            best = static_cast<uint32_t>(i);
        }
    }
    return best;
}

PrimaryIlluminanceFn make_unshadowed_primary_illuminance(std::vector<Light> primaries) {
    return [primaries = std::move(primaries)](const glm::dvec3& position, const glm::vec3& normal,
                                              std::span<double> illuminance) {
        for (size_t i = 0; i < primaries.size() && i < illuminance.size(); ++i) {
            const double e = illuminance_of(primaries[i], position, normal);
            illuminance[i] = std::isfinite(e) ? e : 0.0;
        }
    };
}

}  // namespace onelight::world
