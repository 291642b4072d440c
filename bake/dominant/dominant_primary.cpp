#include "bake/dominant/dominant_primary.hpp"

#include <bit>
#include <cmath>
#include <vector>

namespace onelight::bake {
namespace {
constexpr uint32_t kDominantPass = 3;
}  // namespace

world::PrimaryIlluminanceFn makeShadowedPrimaryIlluminance(const BakeScene& scene,
                                                           const BakeLights& lights,
                                                           uint32_t shadowSamples,
                                                           AtomicRayCount* rays) {
    std::vector<const BakeLight*> primaries;
    for (const BakeLight& l : lights.lights)
        if (l.light.role == world::LightRole::kPrimary) primaries.push_back(&l);
    return [&scene, primaries, shadowSamples, rays](
               const glm::dvec3& position, const glm::vec3& normal, std::span<double> illuminance) {
        const glm::vec3 p(position);
        Rng rng{seedFrom(std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.y),
                         std::bit_cast<uint32_t>(p.z), kDominantPass)};
        const bool oriented = normal != glm::vec3(0.0f);
        const glm::vec3 origin = oriented ? p + glm::normalize(normal) * scene.rayOffset() : p;
        RayCounts local;
        for (size_t i = 0; i < primaries.size() && i < illuminance.size(); ++i) {
            const LightIncidence incidence = lightIncidence(*primaries[i], p);
            const float cosine =
                oriented ? std::max(0.0f, glm::dot(glm::normalize(normal), incidence.direction))
                         : 1.0f;
            const float e = luminance(incidence.irradiance) * cosine;
            if (!(e > 0.0f) || !std::isfinite(e)) {
                illuminance[i] = 0.0;
                continue;
            }
            const float v =
                lightVisibility(scene, *primaries[i], incidence, origin, shadowSamples, rng, local);
            illuminance[i] = double(e) * double(v);
        }
        if (rays) rays->shadow += local.shadow;
    };
}

}  // namespace onelight::bake
