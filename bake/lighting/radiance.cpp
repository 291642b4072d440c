#include "bake/lighting/radiance.hpp"

#include <algorithm>
#include <cmath>

#include "bake/lighting/surface_sampling.hpp"
#include "shading.hpp"

namespace onelight::bake {
namespace {

bool finiteNonNegative(const glm::vec3& c) {
    return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && c.x >= 0.0f &&
           c.y >= 0.0f && c.z >= 0.0f;
}

// Candidates per resampled light choice, and the target's floor (a fraction of the light's
// diffuse term, so that a light whose centre is just below the horizon while part of it is not
// keeps a density).
constexpr uint32_t kRisCandidates = 4;
constexpr float kRisTargetFloor = 0.02f;

// The probability that sampleEmission draws an emitter point rather than a sky direction.
float emitterChoice(const BakeLights& lights) {
    if (lights.emitters.empty()) return 0.0f;
    return lights.skyImage.empty() ? 1.0f : 0.5f;
}

/// The radiance light `light` sends off `point` towards `toViewer`, tested by one shadow ray.
glm::vec3 oneLight(const BakeScene& scene, const BakeLight& light, const ShadingPoint& point,
                   const glm::vec3& origin, const glm::vec3& toViewer, glm::vec2 u,
                   RayCounts& rays) {
    const LightIncidence incidence = lightIncidence(light, point.position);
    if (incidence.irradiance == glm::vec3(0.0f)) return glm::vec3(0.0f);
    const LightDirection d = sampleLightDirection(light, incidence, u, scene.sceneDiameter());
    if (glm::dot(point.geometricNormal, d.direction) <= 0.0f ||
        glm::dot(point.shadingNormal, d.direction) <= 0.0f)
        return glm::vec3(0.0f);
    if (d.shadowDistance > 0.0f &&
        scene.occluded(origin, d.direction, d.shadowDistance, rays.shadow))
        return glm::vec3(0.0f);
    return bsdfCos(point.bsdf, point.shadingNormal, toViewer, d.direction) * incidence.irradiance;
}

}  // namespace

glm::vec3 directRadiance(const BakeScene& scene, const BakeLights& lights,
                         const TransportSettings& settings, const ShadingPoint& point,
                         const glm::vec3& toViewer, Rng& rng, RayCounts& rays) {
    const glm::vec3 origin = point.position + point.geometricNormal * scene.rayOffset();
    if (!settings.sampleLights || lights.lightCells.empty()) {
        glm::vec3 radiance(0.0f);
        for (const BakeLight& light : lights.lights) {
            const glm::vec2 u(rng.next(), rng.next());
            radiance += oneLight(scene, light, point, origin, toViewer, u, rays);
        }
        return radiance;
    }
    glm::vec3 radiance(0.0f);
    for (const uint32_t l : lights.directionalLights) {
        const glm::vec2 u(rng.next(), rng.next());
        radiance += oneLight(scene, lights.lights[l], point, origin, toViewer, u, rays);
    }
    // Resampled importance sampling among the local lights (see radiance.hpp).
    // The target's BRDF part: the diffuse lobe's cosine, and a constant for the specular one.
    const float albedo = luminance(point.bsdf.albedo) / glsl::PI;
    const float specular = luminance(point.bsdf.specularColor) / glsl::PI;
    const LightCellView cell = lightsAt(lights.lightCells, point.position);
    uint32_t chosen = 0;
    float chosenTarget = 0.0f, weightSum = 0.0f;
    for (uint32_t k = 0; k < kRisCandidates; ++k) {
        const LightPick pick = pickLight(cell, rng.next());
        if (!(pick.probability > 0.0f)) return radiance;  // no local light reaches the point
        const BakeLight& light = lights.lights[lights.localLights[pick.source]];
        const LightIncidence incidence = lightIncidence(light, point.position);
        const float e = luminance(incidence.irradiance);
        if (!(e > 0.0f)) continue;
        const float cosine = glm::dot(point.shadingNormal, incidence.direction);
        const float target = e * (albedo * std::max(cosine, kRisTargetFloor) +
                                  specular * (cosine > 0.0f ? 1.0f : kRisTargetFloor));
        const float w = target / pick.probability;
        if (!(w > 0.0f) || !std::isfinite(w)) continue;
        weightSum += w;
        if (rng.next() * weightSum < w) {  // reservoir: candidate k kept with w_k / sum w
            chosen = pick.source;
            chosenTarget = target;
        }
    }
    const glm::vec2 disc(rng.next(), rng.next());
    if (!(weightSum > 0.0f)) return radiance;
    const glm::vec3 f = oneLight(scene, lights.lights[lights.localLights[chosen]], point, origin,
                                 toViewer, disc, rays);
    return radiance + f * (weightSum / (float(kRisCandidates) * chosenTarget));
}

bool samplesEmission(const BakeLights& lights) {
    return !lights.emitters.empty() || !lights.skyImage.empty();
}

EmissionEstimate sampleEmission(const BakeScene& scene, const BakeLights& lights,
                                const glm::vec3& origin, const glm::vec3& normal, Rng& rng,
                                RayCounts& rays) {
    EmissionEstimate out;
    const glm::vec3 u(rng.next(), rng.next(), rng.next());
    const float choice = emitterChoice(lights);
    float shadowDistance = 0.0f;
    glm::vec3 radiance(0.0f);
    if (u.x < choice) {
        const EmitterSample e =
            sampleEmitter(scene, lights.emitters, origin, glm::vec3(u.x / choice, u.y, u.z));
        out.direction = e.direction;
        out.pdf = e.pdf * choice;
        shadowDistance = e.shadowDistance;
        radiance = e.radiance;
    } else if (!lights.skyImage.empty()) {
        const SkySample s = sampleSky(lights.skyImage, glm::vec2(u.y, u.z));
        out.direction = s.direction;
        out.pdf = s.pdf * (1.0f - choice);
        shadowDistance = scene.sceneDiameter();
        radiance = s.radiance;
    }
    if (!(out.pdf > 0.0f) ||
        (normal != glm::vec3(0.0f) && glm::dot(normal, out.direction) <= 0.0f) ||
        (shadowDistance > 0.0f &&
         scene.occluded(origin, out.direction, shadowDistance, rays.shadow))) {
        out.pdf = 0.0f;
        return out;
    }
    out.radianceOverPdf = radiance / out.pdf;
    return out;
}

float emitterHitPdf(const BakeLights& lights, const glm::vec3& origin, uint32_t triangle,
                    float distance, float cosLight) {
    const float choice = emitterChoice(lights);
    return choice > 0.0f
               ? choice * emitterPdf(lights.emitters, origin, triangle, distance, cosLight)
               : 0.0f;
}

float skyEscapePdf(const BakeLights& lights, const glm::vec3& direction) {
    return lights.skyImage.empty()
               ? 0.0f
               : (1.0f - emitterChoice(lights)) * skyPdf(lights.skyImage, direction);
}

glm::vec3 traceRadiance(const BakeScene& scene, const BakeLights& lights,
                        const TransportSettings& settings, glm::vec3 origin, glm::vec3 dir,
                        RayCone cone, Rng& rng, RayCounts& rays, FirstHit* firstHit,
                        float originPdf, const BakeScene* seenOnly) {
    glm::vec3 radiance(0.0f);
    glm::vec3 throughput(1.0f);
    float directionPdf = originPdf;  // density `dir` was drawn with, 0: no emission sampling
    for (uint32_t depth = 0; depth < settings.maxDepth; ++depth) {
        SurfaceHit hit = scene.intersect(origin, dir, scene.sceneDiameter(), rays.bounce);
        const BakeScene* shading = &scene;  // whose triangle `hit` is
        if (depth == 0 && seenOnly) {
            const SurfaceHit seen = seenOnly->intersect(
                origin, dir, hit.found ? hit.distance : scene.sceneDiameter(), rays.bounce);
            if (seen.found && (!hit.found || seen.distance < hit.distance)) {
                hit = seen;
                shading = seenOnly;
            }
        }
        if (depth == 0 && firstHit) *firstHit = {hit.found, hit.backFace, hit.distance};
        if (!hit.found) {
            const float weight = directionPdf > 0.0f && !lights.skyImage.empty()
                                     ? powerHeuristic(directionPdf, skyEscapePdf(lights, dir))
                                     : 1.0f;
            radiance += throughput * skyAlong(lights, dir) * weight;
            break;
        }
        const world::Material& material = shading->materialOf(hit.triangle);
        if (hit.backFace && !material.doubleSided) break;
        ShadingPoint point;
        point.position = hit.position;
        point.geometricNormal = hit.backFace ? -hit.normal : hit.normal;
        const glm::vec3 v = -dir;
        const MaterialSample m =
            sampleMaterial(shading->materials(), shading->materialIndexOf(hit.triangle),
                           shading->attributesAt(hit), point.geometricNormal, hit.backFace,
                           cone.widthAt(hit.distance), v);
        point.shadingNormal = m.shadingNormal;
        point.bsdf = m.bsdf;
        if (m.emission != glm::vec3(0.0f)) {
            // A seen-only triangle is no emitter the lights sample: its emission counts whole.
            const float weight =
                directionPdf > 0.0f && shading == &scene
                    ? powerHeuristic(directionPdf,
                                     emitterHitPdf(lights, origin, hit.triangle, hit.distance,
                                                   std::fabs(glm::dot(dir, hit.normal))))
                    : 1.0f;
            radiance += throughput * m.emission * weight;
        }
        if (settings.cache) {
            const uint32_t k = findCachePoint(*settings.cache, hit.position, point.geometricNormal);
            if (k != kNoCachePoint &&
                hit.distance >= settings.cacheNearField * settings.cache->reach[k]) {
                // The diffuse part from the cache, weighted for the energy its specular lobe
                // takes at this view as a traced bounce is (bsdfCos); the specular part traced
                // on, with the probability sampleSurface would draw it (radiance.hpp).
                const glm::vec3 e =
                    settings.cache->direct[k] + settings.cache->indirect[k] * m.occlusion;
                const float NoV = glm::dot(point.shadingNormal, v);
                radiance += throughput * point.bsdf.albedo * diffuseEnergyWeight(point.bsdf, NoV) *
                            (e / glsl::PI);
                const float p = specularProbability(point.bsdf, NoV);
                if (!(p > 0.0f) || rng.next() >= p) break;
                throughput /= p;
                point.bsdf.albedo = glm::vec3(0.0f);
            }
        }
        radiance += throughput * directRadiance(scene, lights, settings, point, v, rng, rays);
        const glm::vec3 offOrigin = hit.position + point.geometricNormal * scene.rayOffset();
        if (samplesEmission(lights)) {
            const EmissionEstimate e =
                sampleEmission(scene, lights, offOrigin, point.geometricNormal, rng, rays);
            if (e.pdf > 0.0f && glm::dot(point.shadingNormal, e.direction) > 0.0f) {
                const float weight = powerHeuristic(
                    e.pdf, surfacePdf(point.bsdf, point.shadingNormal, v, e.direction));
                radiance += throughput * m.occlusion * e.radianceOverPdf * weight *
                            bsdfCos(point.bsdf, point.shadingNormal, v, e.direction);
            }
        }
        const SurfaceSample next = sampleSurface(point.bsdf, point.shadingNormal, v, rng);
        if (next.weight == glm::vec3(0.0f) ||
            glm::dot(point.geometricNormal, next.direction) <= 0.0f)
            break;
        throughput *= next.weight * m.occlusion;
        if (depth + 1 >= settings.rouletteDepth) {
            const float q = std::min(0.95f, std::max({throughput.x, throughput.y, throughput.z}));
            if (!(q > 0.0f) || rng.next() >= q) break;
            throughput /= q;
        }
        cone = bounceCone(cone, hit.distance, next.pdf);
        origin = offOrigin;
        dir = next.direction;
        directionPdf = next.pdf;
    }
    return finiteNonNegative(radiance) ? radiance : glm::vec3(0.0f);
}

}  // namespace onelight::bake
