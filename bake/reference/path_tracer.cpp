#include "bake/reference/path_tracer.hpp"

#include <cmath>
#include <numbers>

#include <tbb/enumerable_thread_specific.h>
#include <glm/gtc/quaternion.hpp>

#include "bake/lighting/sampling.hpp"
#include "bake/parallel_for.hpp"

namespace onelight::bake {
namespace {
constexpr uint32_t kReferencePass = 4;
constexpr uint32_t kReferenceIrradiancePass = 5;
}  // namespace

CameraRay cameraRay(const world::Camera& camera, float aspect, float sx, float sy) {
    const glm::mat3 rotation = glm::mat3_cast(camera.rotation);
    CameraRay ray;
    ray.origin = camera.position;
    if (camera.orthographic) {
        ray.origin += rotation * glm::vec3(sx * camera.xmag, sy * camera.ymag, 0.0f);
        ray.dir = rotation * glm::vec3(0.0f, 0.0f, -1.0f);
    } else {
        const float tanHalf = std::tan(0.5f * camera.yfov);
        ray.dir = glm::normalize(rotation * glm::vec3(sx * tanHalf * aspect, sy * tanHalf, -1.0f));
    }
    return ray;
}

ReferenceImage renderReference(const BakeScene& scene, const BakeLights& lights,
                               const world::Camera& camera, uint32_t width, uint32_t height,
                               uint32_t spp, const TransportSettings& transport, Progress* progress,
                               RayCounts& rays, uint32_t seed, const BakeScene* seenOnly) {
    ReferenceImage image;
    image.width = width;
    image.height = height;
    image.rgb.assign(size_t(width) * height * 3, 0.0f);
    const float aspect = float(width) / float(height);
    // Camera rays read textures at full resolution (a footprint of 0: mip 0): the paths, jittered
    // over the pixel, average the full-resolution shading over it, which is the ground truth the
    // runtime's mips approximate (docs/materials.md). Later bounces keep their cones.
    const RayCone pixelCone{0.0f, 0.0f};
    tbb::enumerable_thread_specific<RayCounts> counts;
    bake::parallelFor(tbb::blocked_range<uint32_t>(0, height), [&](const auto& rows) {
        RayCounts& local = counts.local();
        for (uint32_t y = rows.begin(); y != rows.end(); ++y) {
            for (uint32_t x = 0; x < width; ++x) {
                Rng rng{seedFrom(x, y, seed, kReferencePass)};
                glm::dvec3 sum(0.0);
                for (uint32_t s = 0; s < spp; ++s) {
                    const float sx = (float(x) + rng.next()) / float(width) * 2.0f - 1.0f;
                    const float sy = 1.0f - (float(y) + rng.next()) / float(height) * 2.0f;
                    const CameraRay ray = cameraRay(camera, aspect, sx, sy);
                    sum +=
                        glm::dvec3(traceRadiance(scene, lights, transport, ray.origin, ray.dir,
                                                 pixelCone, rng, local, nullptr, 0.0f, seenOnly));
                }
                const glm::vec3 l = glm::vec3(sum / double(std::max(1u, spp)));
                float* out = &image.rgb[(size_t(y) * width + x) * 3];
                out[0] = l.x;
                out[1] = l.y;
                out[2] = l.z;
            }
        }
        if (progress) progress->advance(rows.size());
    });
    for (const RayCounts& r : counts) rays += r;
    return image;
}

glm::vec3 referenceIrradiance(const BakeScene& scene, const BakeLights& lights,
                              const glm::vec3& position, const glm::vec3& normal, uint32_t samples,
                              uint32_t seed, const TransportSettings& transport, RayCounts& rays) {
    Rng rng{seedFrom(seed, 0, 0, kReferenceIrradiancePass)};
    const glm::vec3 origin = position + normal * scene.rayOffset();
    glm::dvec3 e(0.0);
    for (const BakeLight& light : lights.lights) {
        const LightIncidence incidence = lightIncidence(light, origin);
        const float cosine = glm::dot(normal, incidence.direction);
        if (cosine <= 0.0f || incidence.irradiance == glm::vec3(0.0f)) continue;
        const float v = lightVisibility(scene, light, incidence, origin, samples, rng, rays);
        e += glm::dvec3(incidence.irradiance) * double(cosine * v);
    }
    const Frame frame = frameAround(normal);
    glm::dvec3 indirect(0.0);
    const bool emission = samplesEmission(lights);
    const float kUniformPdf = 1.0f / (2.0f * glsl::PI);  // the hemisphere directions' density
    for (uint32_t i = 0; i < samples; ++i) {
        // uniform hemisphere: the upper half of a uniform sphere direction
        glm::vec3 local = sampleUniformSphere({rng.next() * 0.5f, rng.next()});
        const glm::vec3 w = glm::normalize(frame.toWorld(local));
        indirect += glm::dvec3(traceRadiance(scene, lights, transport, origin, w,
                                             RayCone{0.0f, sampleSpread(2.0f * glsl::PI, samples)},
                                             rng, rays, nullptr, emission ? kUniformPdf : 0.0f)) *
                    double(local.z);
        if (!emission) continue;
        // One emission sample per direction, in the same 2 pi / N scale (radiance.hpp).
        const EmissionEstimate emitter = sampleEmission(scene, lights, origin, normal, rng, rays);
        if (emitter.pdf > 0.0f)
            indirect += glm::dvec3(emitter.radianceOverPdf) *
                        double(glm::dot(normal, emitter.direction) *
                               powerHeuristic(emitter.pdf, kUniformPdf) * kUniformPdf);
    }
    e += indirect * (2.0 * std::numbers::pi / double(std::max(1u, samples)));
    return glm::vec3(e);
}

}  // namespace onelight::bake
