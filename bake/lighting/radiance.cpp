#include "bake/lighting/radiance.hpp"

#include <algorithm>
#include <cmath>

#include "bake/lighting/surface_sampling.hpp"
#include "shading.hpp"

namespace onelight::bake {
namespace {

glm::vec3 brdfCos(const Bsdf& bsdf, const glm::vec3& n, const glm::vec3& v, const glm::vec3& l) {
    const glsl::BrdfDots d = glsl::brdfDots(n, v, l);
    const glm::vec3 diffuse = bsdf.albedo * (glsl::Fd_Lambert() * d.NoL);
    const glm::vec3 specular = glsl::specularLobe(kShadingNdf, kShadingVis, kShadingFresnel,
                                                  bsdf.specularColor, bsdf.gloss, d);
    return diffuse + specular;
}

bool finiteNonNegative(const glm::vec3& c) {
    return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && c.x >= 0.0f &&
           c.y >= 0.0f && c.z >= 0.0f;
}

}  // namespace

glm::vec3 directRadiance(const BakeScene& scene, const BakeLights& lights,
                         const ShadingPoint& point, const glm::vec3& toViewer, Rng& rng,
                         RayCounts& rays) {
    glm::vec3 radiance(0.0f);
    const glm::vec3 origin = point.position + point.geometricNormal * scene.rayOffset();
    for (const BakeLight& light : lights.lights) {
        const LightIncidence incidence = lightIncidence(light, point.position);
        const glm::vec2 u(rng.next(), rng.next());
        if (incidence.irradiance == glm::vec3(0.0f)) continue;
        const LightDirection d = sampleLightDirection(light, incidence, u, scene.sceneDiameter());
        if (glm::dot(point.geometricNormal, d.direction) <= 0.0f ||
            glm::dot(point.shadingNormal, d.direction) <= 0.0f)
            continue;
        if (d.shadowDistance > 0.0f &&
            scene.occluded(origin, d.direction, d.shadowDistance, rays.shadow))
            continue;
        radiance +=
            brdfCos(point.bsdf, point.shadingNormal, toViewer, d.direction) * incidence.irradiance;
    }
    return radiance;
}

EmitterEstimate sampleEmitterRadiance(const BakeScene& scene, const Emitters& emitters,
                                      const glm::vec3& origin, const glm::vec3& normal, Rng& rng,
                                      RayCounts& rays) {
    EmitterEstimate out;
    const glm::vec3 u(rng.next(), rng.next(), rng.next());
    if (emitters.empty()) return out;
    const EmitterSample e = sampleEmitter(scene, emitters, origin, u);
    out.direction = e.direction;
    if (!(e.pdf > 0.0f) || (normal != glm::vec3(0.0f) && glm::dot(normal, e.direction) <= 0.0f))
        return out;
    if (e.shadowDistance > 0.0f &&
        scene.occluded(origin, e.direction, e.shadowDistance, rays.shadow))
        return out;
    out.pdf = e.pdf;
    out.radianceOverPdf = e.radiance / e.pdf;
    return out;
}

glm::vec3 traceRadiance(const BakeScene& scene, const BakeLights& lights,
                        const TransportSettings& settings, glm::vec3 origin, glm::vec3 dir,
                        RayCone cone, Rng& rng, RayCounts& rays, FirstHit* firstHit,
                        float originPdf) {
    glm::vec3 radiance(0.0f);
    glm::vec3 throughput(1.0f);
    float directionPdf = originPdf;  // density `dir` was drawn with, 0: no emitter sampling
    for (uint32_t depth = 0; depth < settings.maxDepth; ++depth) {
        const SurfaceHit hit = scene.intersect(origin, dir, scene.sceneDiameter(), rays.bounce);
        if (depth == 0 && firstHit) *firstHit = {hit.found, hit.backFace, hit.distance};
        if (!hit.found) {
            radiance += throughput * lights.skyRadiance;
            break;
        }
        const world::Material& material = scene.materialOf(hit.triangle);
        if (hit.backFace && !material.doubleSided) break;
        ShadingPoint point;
        point.position = hit.position;
        point.geometricNormal = hit.backFace ? -hit.normal : hit.normal;
        const glm::vec3 v = -dir;
        const MaterialSample m =
            sampleMaterial(scene.materials(), scene.materialIndexOf(hit.triangle),
                           scene.attributesAt(hit), point.geometricNormal, hit.backFace,
                           cone.widthAt(hit.distance), glm::dot(point.geometricNormal, v));
        point.shadingNormal = m.shadingNormal;
        point.bsdf = m.bsdf;
        if (m.emission != glm::vec3(0.0f)) {
            const float emitter = emitterPdf(lights.emitters, hit.triangle, hit.distance,
                                             std::fabs(glm::dot(dir, hit.normal)));
            const float weight = directionPdf > 0.0f ? powerHeuristic(directionPdf, emitter) : 1.0f;
            radiance += throughput * m.emission * weight;
        }
        radiance += throughput * directRadiance(scene, lights, point, v, rng, rays);
        const glm::vec3 offOrigin = hit.position + point.geometricNormal * scene.rayOffset();
        if (!lights.emitters.empty()) {
            const EmitterEstimate e = sampleEmitterRadiance(scene, lights.emitters, offOrigin,
                                                            point.geometricNormal, rng, rays);
            if (e.pdf > 0.0f && glm::dot(point.shadingNormal, e.direction) > 0.0f) {
                const float weight = powerHeuristic(
                    e.pdf, surfacePdf(point.bsdf, point.shadingNormal, v, e.direction));
                radiance += throughput * m.occlusion * e.radianceOverPdf * weight *
                            brdfCos(point.bsdf, point.shadingNormal, v, e.direction);
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
