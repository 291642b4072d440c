#include "bake/budget/probe_drop.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/enumerable_thread_specific.h>
#include <glm/gtc/quaternion.hpp>

#include "bake/lighting/sampling.hpp"
#include "bake/parallel_for.hpp"
#include "bake/reference/path_tracer.hpp"
#include "env_brdf_table.hpp"
#include "shading.hpp"

namespace onelight::bake {
namespace {

constexpr uint32_t kProbeDropPass = 7;  // seed stream of this pass (seedFrom's last argument)
constexpr float kEyeHeight = 1.6f;      // metres above a spawn's feet
constexpr double kBlockFloor = 0.05;    // of the view's mean luminance (block_error.hpp)

struct BlockSums {
    double change = 0.0;    // sum of Y(dL)
    double radiance = 0.0;  // sum of Y(L_pixel)
    uint32_t samples = 0;
};

// The radiance average over `count` directions from `origin`, each drawn by `draw(i)`, which
// returns the direction and its weight (0: skipped).
template <class Draw>
glm::vec3 meanRadiance(const BakeScene& scene, const BakeLights& lights,
                       const TransportSettings& transport, const glm::vec3& origin, uint32_t count,
                       Draw draw, Rng& rng, RayCounts& rays) {
    glm::vec3 sum(0.0f);
    float weight = 0.0f;
    for (uint32_t i = 0; i < count; ++i) {
        const auto [dir, w] = draw(i);
        if (!(w > 0.0f)) continue;
        sum += w * traceRadiance(scene, lights, transport, origin, dir, RayCone{}, rng, rays);
        weight += w;
    }
    return weight > 0.0f ? sum / weight : glm::vec3(0.0f);
}

// Y(dL) at the first hit of the ray (origin, dir), or 0 when there is no specular lobe there.
float secondarySpecularChange(const BakeScene& scene, const BakeLights& lights,
                              const TransportSettings& transport, const SurfaceHit& hit,
                              const glm::vec3& dir, const ProbeDropSettings& settings, Rng& rng,
                              RayCounts& rays, bool& glossy) {
    const glm::vec3 geometricNormal = hit.backFace ? -hit.normal : hit.normal;
    const glm::vec3 v = -dir;
    const MaterialSample m =
        sampleMaterial(scene.materials(), scene.materialIndexOf(hit.triangle),
                       scene.attributesAt(hit), geometricNormal, hit.backFace, 0.0f, v);
    glossy = m.bsdf.materialClass != MATERIAL_LAMBERT;
    if (!glossy) return 0.0f;
    const glm::vec3 n = m.shadingNormal;
    const float NoV = std::max(glm::dot(n, v), 1e-4f);
    const glm::vec3 r = glm::normalize(2.0f * glm::dot(n, v) * n - v);
    const glm::vec3 origin = hit.position + geometricNormal * scene.rayOffset();
    // The lobe about r: GGX half vectors (Walter et al. 2007, eq. 35), weighted by NoL.
    const float alpha = glsl::ggxAlpha_fromGloss(m.bsdf.gloss), a2 = alpha * alpha;
    const Frame lobe = frameAround(r);
    const glm::vec3 lobeRadiance = meanRadiance(
        scene, lights, transport, origin, settings.lobeRays,
        [&](uint32_t) {
            const float u1 = rng.next(), u2 = rng.next();
            const float cos2 = (1.0f - u1) / (1.0f + (a2 - 1.0f) * u1);
            const float sinH = std::sqrt(std::max(0.0f, 1.0f - cos2));
            const float phi = 2.0f * glsl::PI * u2;
            const glm::vec3 h = lobe.toWorld(
                glm::vec3(sinH * std::cos(phi), sinH * std::sin(phi), std::sqrt(cos2)));
            const glm::vec3 l = 2.0f * glm::dot(r, h) * h - r;
            return std::pair{l, std::max(0.0f, glm::dot(r, l))};
        },
        rng, rays);
    const Frame around = frameAround(n);
    const glm::vec3 cosineMean = meanRadiance(
        scene, lights, transport, origin, settings.hemisphereRays,
        [&](uint32_t) {
            const glm::vec3 w = around.toWorld(sampleCosineHemisphere({rng.next(), rng.next()}));
            return std::pair{w, glm::dot(w, geometricNormal) > 0.0f ? 1.0f : 0.0f};
        },
        rng, rays);
    const glm::vec3 irradiance = glsl::PI * cosineMean;
    // The probe's statistic at x's normal, the capture's side and the pixel's alike (x sees what
    // the probe does): the probe reads lobeRadiance / E(n) (probeAtNormal) times E(n).
    const glm::vec3 probe = glsl::probeNormalize(lobeRadiance, irradiance);
    const glm::vec2 env = glsl::sampleEnvBrdfTable(glsl::envBrdfTableCoord(NoV, m.bsdf.gloss));
    const auto secondary = [&](const glm::vec3& normalisedProbe) {
        return glsl::secondaryRadiance(m.bsdf.materialClass, m.bsdf.albedo, m.bsdf.specularColor,
                                       env, irradiance, m.occlusion, 1.0f, normalisedProbe,
                                       irradiance);
    };
    return glsl::luminance(secondary(probe) - secondary(glm::vec3(glsl::INV_PI)));
}

double viewError(const BakeScene& scene, const BakeLights& lights,
                 const TransportSettings& transport, const world::Camera& camera,
                 uint32_t viewIndex, const ProbeDropSettings& settings, ProbeDropPrediction& out) {
    const float aspect = camera.aspectRatio > 0.0f ? camera.aspectRatio : 16.0f / 9.0f;
    const uint32_t across = std::max(1u, settings.blocksAcross);
    const uint32_t down = std::max(1u, uint32_t(std::lround(float(across) / aspect)));
    const uint32_t side = std::max(1u, settings.samplesPerSide);
    std::vector<BlockSums> blocks(size_t(across) * down);
    tbb::enumerable_thread_specific<RayCounts> counts;
    tbb::enumerable_thread_specific<std::pair<uint64_t, uint64_t>> hits;
    parallelFor(tbb::blocked_range<size_t>(0, blocks.size()), [&](const auto& range) {
        RayCounts& local = counts.local();
        auto& [found, glossyFound] = hits.local();
        for (size_t b = range.begin(); b != range.end(); ++b) {
            const uint32_t bx = uint32_t(b % across), by = uint32_t(b / across);
            BlockSums& sums = blocks[b];
            for (uint32_t s = 0; s < side * side; ++s) {
                Rng rng{seedFrom(uint32_t(b), s, viewIndex, kProbeDropPass)};
                const float fx = (float(bx * side + s % side) + rng.next()) / float(across * side);
                const float fy = (float(by * side + s / side) + rng.next()) / float(down * side);
                const float sx = 2.0f * fx - 1.0f, sy = 1.0f - 2.0f * fy;
                const CameraRay ray = cameraRay(camera, aspect, sx, sy);
                const glm::vec3 origin = ray.origin, dir = ray.dir;
                glm::vec3 pixel(0.0f);
                for (uint32_t p = 0; p < settings.pixelPaths; ++p)
                    pixel +=
                        traceRadiance(scene, lights, transport, origin, dir, RayCone{}, rng, local);
                sums.radiance +=
                    double(glsl::luminance(pixel) / float(std::max(1u, settings.pixelPaths)));
                ++sums.samples;
                const SurfaceHit hit =
                    scene.intersect(origin, dir, scene.sceneDiameter(), local.bounce);
                if (!hit.found) continue;
                ++found;
                bool glossy = false;
                sums.change += double(secondarySpecularChange(scene, lights, transport, hit, dir,
                                                              settings, rng, local, glossy));
                glossyFound += glossy;
            }
        }
    });
    for (const RayCounts& r : counts) out.rays += r;
    for (const auto& [found, glossy] : hits) {
        out.samples += found;
        out.glossySamples += glossy;
    }
    double total = 0.0;
    uint64_t samples = 0;
    for (const BlockSums& s : blocks) {
        total += s.radiance;
        samples += s.samples;
    }
    const double meanRadiance = samples ? total / double(samples) : 0.0;
    double sum = 0.0;
    for (const BlockSums& s : blocks) {
        const double floor = kBlockFloor * meanRadiance * s.samples;
        const double denominator = std::max(s.radiance, floor);
        sum += denominator > 0.0 ? std::fabs(s.change) / denominator : 0.0;
    }
    return blocks.empty() ? 0.0 : sum / double(blocks.size());
}

}  // namespace

ProbeDropPrediction predictProbeDropError(const BakeScene& scene, const BakeLights& lights,
                                          const TransportSettings& transport,
                                          const std::vector<world::Camera>& views,
                                          const ProbeDropSettings& settings) {
    ProbeDropPrediction out;
    for (uint32_t i = 0; i < views.size(); ++i) {
        const double e = viewError(scene, lights, transport, views[i], i, settings, out);
        out.views.push_back(std::isfinite(e) ? e : 0.0);
        out.error = std::max(out.error, out.views.back());
    }
    return out;
}

std::vector<world::Camera> budgetViews(const world::CompiledLevel& level) {
    if (!level.cameras.empty()) return level.cameras;
    std::vector<world::Camera> views;
    for (const world::Entity& e : level.entities) {
        if (!(e.flags & world::kEntitySpawn)) continue;
        for (int k = 0; k < 4; ++k) {
            world::Camera c;
            c.name = e.name + " heading " + std::to_string(90 * k);
            c.yfov = 1.0f;
            c.position = e.position + glm::vec3(0.0f, kEyeHeight, 0.0f);
            c.rotation =
                glm::angleAxis(glm::radians(90.0f * float(k)), glm::vec3(0.0f, 1.0f, 0.0f));
            views.push_back(c);
        }
    }
    return views;
}

}  // namespace onelight::bake
