#include "bake/lighting/lights.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "bake/lighting/cell_visibility.hpp"
#include "world/error.hpp"
#include "world/light_model.hpp"

namespace onelight::bake {

BakeLights makeBakeLights(const BakeScene& scene, const std::vector<world::Light>& levelLights,
                          const LightSizes& sizes, glm::vec3 skyRadiance) {
    BakeLights out = makePunctualLights(levelLights, sizes, skyRadiance);
    std::vector<LightBound> bounds;
    for (uint32_t l = 0; l < out.lights.size(); ++l) {
        if (out.lights[l].light.type == world::LightType::kDirectional) {
            out.directionalLights.push_back(l);
            continue;
        }
        out.localLights.push_back(l);
        bounds.push_back(lightBoundOf(out.lights[l]));
    }
    out.lightCells = layoutLightCells(bounds.size(), scene.boundsMin(), scene.boundsMax());
    const CellSurfacePoints points = surfacePointsOfCells(scene, out.lightCells);
    fillLightCells(out.lightCells, bounds, [&](uint32_t source, uint32_t cell) {
        const BakeLight& light = out.lights[out.localLights[source]];
        return visibleFraction(points, cell, [&](const glm::vec3& p, const glm::vec3& n) {
            const LightIncidence incidence = lightIncidence(light, p);
            if (incidence.irradiance == glm::vec3(0.0f)) return false;
            const LightDirection d =
                sampleLightDirection(light, incidence, glm::vec2(0.5f), scene.sceneDiameter());
            uint64_t rays = 0;
            return glm::dot(n, d.direction) > 0.0f &&
                   (d.shadowDistance <= 0.0f ||
                    !scene.occluded(p, d.direction, d.shadowDistance, rays));
        });
    });
    out.emitters = collectEmitters(scene);
    return out;
}

BakeLights makeLevelLights(const BakeScene& scene, const world::SourceLevel& source,
                           const LightSizes& sizes, std::optional<glm::vec3> uniformSky) {
    BakeLights out =
        makeBakeLights(scene, source.lights, sizes, uniformSky.value_or(source.skyRadiance));
    if (uniformSky || source.skyImage == world::kNoIndex) return out;
    if (source.skyImage >= source.images.size() || source.images[source.skyImage].uri.empty())
        throw world::Error(source.sourcePath + ": sky image " + std::to_string(source.skyImage) +
                           " is not a file among its " + std::to_string(source.images.size()) +
                           " images; expected a Radiance .hdr file");
    out.skyImage =
        makeSkyImage(world::readHdrFile(source.images[source.skyImage].uri), source.skyRadiance);
    out.skyRadiance = glm::vec3(0.0f);
    return out;
}

BakeLights makePunctualLights(const std::vector<world::Light>& levelLights, const LightSizes& sizes,
                              glm::vec3 skyRadiance) {
    BakeLights out;
    out.skyRadiance = skyRadiance;
    for (size_t i = 0; i < levelLights.size(); ++i) {
        const world::Light& l = levelLights[i];
        if (l.role == world::LightRole::kEffect) continue;
        BakeLight b;
        b.light = l;
        b.levelIndex = static_cast<uint32_t>(i);
        b.radius =
            l.type == world::LightType::kDirectional ? sizes.sunAngularRadius : sizes.pointRadius;
        out.lights.push_back(b);
    }
    return out;
}

LightBound lightBoundOf(const BakeLight& light) {
    const world::Light& l = light.light;
    LightBound b;
    const glm::vec3 c = l.color * l.intensity;
    b.power = std::isfinite(luminance(c)) ? std::max(0.0f, luminance(c)) : 0.0f;
    if (l.type == world::LightType::kDirectional) {
        b.directional = true;
        return b;
    }
    // The sphere shadow rays aim at: the range window is measured from its centre.
    b.lo = l.position - glm::vec3(light.radius);
    b.hi = l.position + glm::vec3(light.radius);
    b.range = l.range > 0.0f ? l.range + light.radius : 0.0f;
    if (l.type == world::LightType::kSpot) {
        b.axis = l.direction;
        b.cosOuter = std::cos(l.outerCone);
    }
    return b;
}

LightIncidence lightIncidence(const BakeLight& light, const glm::vec3& position) {
    // The runtime's own evaluation (shaders/lighting.glsl), so bake and runtime agree exactly.
    const world::Light& l = light.light;
    const world::LightAtPoint sample = world::evaluateLight(l, position);
    LightIncidence out;
    out.direction = sample.toLight;
    out.distance = l.type == world::LightType::kDirectional ? std::numeric_limits<float>::infinity()
                                                            : sample.distance;
    const glm::vec3 e = sample.illuminance;
    const bool finite = std::isfinite(e.x) && std::isfinite(e.y) && std::isfinite(e.z);
    out.irradiance = finite ? glm::max(e, glm::vec3(0.0f)) : glm::vec3(0.0f);
    return out;
}

LightDirection sampleLightDirection(const BakeLight& light, const LightIncidence& incidence,
                                    glm::vec2 u, float sceneDiameter) {
    LightDirection out;
    float oneMinusCosMax;
    if (light.light.type == world::LightType::kDirectional) {
        const float s = std::sin(0.5f * light.radius);
        oneMinusCosMax = 2.0f * s * s;  // 1 - cos r = 2 sin^2(r / 2), no cancellation
        out.shadowDistance = sceneDiameter;
    } else {
        if (incidence.distance <= light.radius) {  // inside the light: its centre, unshadowed
            out.direction = incidence.direction;
            out.shadowDistance = 0.0f;
            return out;
        }
        const float sinMax = light.radius / incidence.distance;
        const float sin2 = sinMax * sinMax;
        oneMinusCosMax = sin2 / (1.0f + std::sqrt(std::max(0.0f, 1.0f - sin2)));
        out.shadowDistance = incidence.distance - light.radius;
    }
    const glm::vec3 local = sampleUniformCone(u, oneMinusCosMax);
    out.direction = glm::normalize(frameAround(incidence.direction).toWorld(local));
    return out;
}

float lightVisibility(const BakeScene& scene, const BakeLight& light,
                      const LightIncidence& incidence, const glm::vec3& origin, uint32_t samples,
                      Rng& rng, RayCounts& rays) {
    if (samples == 0) return 1.0f;
    const float s0 = rng.next(), s1 = rng.next();
    uint32_t visible = 0;
    for (uint32_t i = 0; i < samples; ++i) {
        const LightDirection d = sampleLightDirection(
            light, incidence, rotatedHammersley(i, samples, s0, s1), scene.sceneDiameter());
        if (d.shadowDistance <= 0.0f ||
            !scene.occluded(origin, d.direction, d.shadowDistance, rays.shadow))
            ++visible;
    }
    return static_cast<float>(visible) / static_cast<float>(samples);
}

}  // namespace onelight::bake
