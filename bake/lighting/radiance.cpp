#include "bake/lighting/radiance.hpp"

#include <algorithm>
#include <cmath>

#include "bake/lighting/surface_sampling.hpp"
#include "shading.hpp"

namespace onelight::bake {
namespace {

glm::vec3 brdf_cos(const world::Material& material, const glm::vec3& n, const glm::vec3& v,
                   const glm::vec3& l) {
    const glsl::BrdfDots d = glsl::brdfDots(n, v, l);
    const glm::vec3 diffuse = material.albedo * (glsl::Fd_Lambert() * d.NoL);
    const glm::vec3 specular = glsl::specularLobe(kShadingNdf, kShadingVis, kShadingFresnel,
                                                  material.specular_color, material.gloss, d);
    return diffuse + specular;
}

bool finite_non_negative(const glm::vec3& c) {
    return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && c.x >= 0.0f &&
           c.y >= 0.0f && c.z >= 0.0f;
}

}  // namespace

glm::vec3 direct_radiance(const BakeScene& scene, const BakeLights& lights,
                          const world::Material& material, const glm::vec3& position,
                          const glm::vec3& normal, const glm::vec3& to_viewer, Rng& rng,
                          RayCounts& rays) {
    glm::vec3 radiance(0.0f);
    const glm::vec3 origin = position + normal * scene.ray_offset();
    for (const BakeLight& light : lights.lights) {
        const LightIncidence incidence = light_incidence(light, position);
        const glm::vec2 u(rng.next(), rng.next());
        if (incidence.irradiance == glm::vec3(0.0f)) continue;
        const LightDirection d =
            sample_light_direction(light, incidence, u, scene.scene_diameter());
        if (glm::dot(normal, d.direction) <= 0.0f) continue;
        if (d.shadow_distance > 0.0f &&
            scene.occluded(origin, d.direction, d.shadow_distance, rays.shadow))
            continue;
        radiance += brdf_cos(material, normal, to_viewer, d.direction) * incidence.irradiance;
    }
    return radiance;
}

glm::vec3 trace_radiance(const BakeScene& scene, const BakeLights& lights,
                         const TransportSettings& settings, glm::vec3 origin, glm::vec3 dir,
                         Rng& rng, RayCounts& rays, FirstHit* first_hit) {
    glm::vec3 radiance(0.0f);
    glm::vec3 throughput(1.0f);
    for (uint32_t depth = 0; depth < settings.max_depth; ++depth) {
        const SurfaceHit hit = scene.intersect(origin, dir, scene.scene_diameter(), rays.bounce);
        if (depth == 0 && first_hit) *first_hit = {hit.found, hit.back_face, hit.distance};
        if (!hit.found) {
            radiance += throughput * lights.sky_radiance;
            break;
        }
        const world::Material& material = scene.material_of(hit.triangle);
        if (hit.back_face && !material.double_sided) break;
        const glm::vec3 n = hit.back_face ? -hit.normal : hit.normal;
        const glm::vec3 v = -dir;
        radiance +=
            throughput * direct_radiance(scene, lights, material, hit.position, n, v, rng, rays);

        const SurfaceSample next = sample_surface(material, n, v, rng);
        if (next.weight == glm::vec3(0.0f)) break;
        throughput *= next.weight;
        if (depth + 1 >= settings.roulette_depth) {
            const float q = std::min(0.95f, std::max({throughput.x, throughput.y, throughput.z}));
            if (!(q > 0.0f) || rng.next() >= q) break;
            throughput /= q;
        }
        origin = hit.position + n * scene.ray_offset();
        dir = next.direction;
    }
    return finite_non_negative(radiance) ? radiance : glm::vec3(0.0f);
}

}  // namespace onelight::bake
