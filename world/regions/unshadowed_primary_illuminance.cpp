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

double cosineTerm(const glm::vec3& normal, const glm::dvec3& toLight) {
    if (normal == glm::vec3(0.0f)) return 1.0;
    return std::max(0.0, glm::dot(glm::dvec3(normal), toLight));
}

double illuminanceOf(const Light& light, const glm::dvec3& position, const glm::vec3& normal) {
    const double power = static_cast<double>(light.intensity) * luminance(light.color);
    if (light.type == LightType::kDirectional)
        return power * cosineTerm(normal, -glm::dvec3(light.direction));
    const glm::dvec3 offset = glm::dvec3(light.position) - position;
    const double distance = std::max(glm::length(offset), kMinimumDistance);
    const glm::dvec3 toLight = offset / distance;
    // KHR_lights_punctual recommended range window: saturate(1 - (d / range)^4)^2
    double window = 1.0;
    if (light.range > 0.0f) {
        const double ratio = distance / static_cast<double>(light.range);
        const double w = std::clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
        window = w * w;
    }
    double cone = 1.0;
    if (light.type == LightType::kSpot) {
        // KHR_lights_punctual spot falloff: smooth between the cosines of the cone angles
        const double cosOuter = std::cos(static_cast<double>(light.outerCone));
        const double cosInner = std::cos(static_cast<double>(light.innerCone));
        const double cd = glm::dot(glm::dvec3(light.direction), -toLight);
        const double t =
            std::clamp((cd - cosOuter) / std::max(cosInner - cosOuter, 1e-4), 0.0, 1.0);
        cone = t * t;
    }
    return power * window * cone * cosineTerm(normal, toLight) / (distance * distance);
}

}  // namespace

uint32_t dominantPrimary(std::span<const double> illuminance) {
    uint32_t best = kNoIndex;
    double bestValue = 0.0;
    for (size_t i = 0; i < illuminance.size(); ++i) {
        if (illuminance[i] > bestValue) {
            bestValue = illuminance[i];
            best = static_cast<uint32_t>(i);
        }
    }
    return best;
}

PrimaryIlluminanceFn makeUnshadowedPrimaryIlluminance(std::vector<Light> primaries) {
    return [primaries = std::move(primaries)](const glm::dvec3& position, const glm::vec3& normal,
                                              std::span<double> illuminance) {
        for (size_t i = 0; i < primaries.size() && i < illuminance.size(); ++i) {
            const double e = illuminanceOf(primaries[i], position, normal);
            illuminance[i] = std::isfinite(e) ? e : 0.0;
        }
    };
}

}  // namespace onelight::world
