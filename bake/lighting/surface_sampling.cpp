#include "bake/lighting/surface_sampling.hpp"

#include <algorithm>
#include <cmath>

#include "bake/lighting/radiance.hpp"
#include "shading.hpp"

namespace onelight::bake {

float specularProbability(const Bsdf& material, float NoV) {
    // Only a Lambert-only material has no lobe: at f0 = 0 Schlick's Fresnel still reflects
    // (1 - LoH)^5, which cosine draws would leave to chance at high gloss.
    if (material.materialClass == MATERIAL_LAMBERT) return 0.0f;
    const float specular =
        luminance(glsl::F_Schlick(material.specularColor, std::clamp(NoV, 0.0f, 1.0f)));
    const float total = specular + std::max(luminance(material.albedo), 0.0f);
    return total > 0.0f ? specular / total : 0.0f;
}

namespace {

// The mixture density for a direction l above the surface (NoL = n.l > 0) whose dots with n and
// v are `d`, drawn with specular probability p: shared by surfacePdf and sampleSurface, which
// has p and the dots already.
float mixturePdf(float p, float gloss, const glsl::BrdfDots& d, float NoL) {
    float pdf = (1.0f - p) * NoL / glsl::PI;
    if (p > 0.0f) {
        const float NoH = std::sqrt(std::max(0.0f, 1.0f - d.NxH2));
        const float D = glsl::D_GGX(d.NxH2, glsl::ggxAlpha_fromGloss(gloss));
        pdf += p * D * NoH / (4.0f * std::max(d.LoH, 1e-8f));
    }
    return pdf;
}

}  // namespace

float surfacePdf(const Bsdf& material, const glm::vec3& n, const glm::vec3& v, const glm::vec3& l) {
    const float NoL = glm::dot(n, l);
    if (NoL <= 0.0f) return 0.0f;
    return mixturePdf(specularProbability(material, glm::dot(n, v)), material.gloss,
                      glsl::brdfDots(n, v, l), NoL);
}

SurfaceSample sampleSurface(const Bsdf& material, const glm::vec3& n, const glm::vec3& v,
                            Rng& rng) {
    const Frame frame = frameAround(n);
    const float p = specularProbability(material, glm::dot(n, v));
    SurfaceSample s;
    if (p > 0.0f && (p >= 1.0f || rng.next() < p)) {
        const float a = glsl::ggxAlpha_fromGloss(material.gloss);
        const float u1 = rng.next(), u2 = rng.next();
        const float cos2 = (1.0f - u1) / (1.0f + (a * a - 1.0f) * u1);
        const float sinH = std::sqrt(std::max(0.0f, 1.0f - cos2));
        const float phi = 2.0f * glsl::PI * u2;
        const glm::vec3 h = frame.toWorld(
            {sinH * std::cos(phi), sinH * std::sin(phi), std::sqrt(std::max(0.0f, cos2))});
        s.direction = glm::normalize(2.0f * glm::dot(v, h) * h - v);
    } else {
        s.direction =
            glm::normalize(frame.toWorld(sampleCosineHemisphere({rng.next(), rng.next()})));
        if (p == 0.0f && material.materialClass == MATERIAL_LAMBERT &&
            material.diffuseModel == DIFFUSE_LAMBERT) {
            // Lambert alone: f cos / pdf = (albedo NoL / pi) / (NoL / pi)
            s.weight = material.albedo;
            s.pdf = std::max(glm::dot(n, s.direction), 0.0f) / glsl::PI;
            return s;
        }
    }
    const float NoL = glm::dot(n, s.direction);
    if (NoL <= 1e-6f) return s;  // below the horizon: no contribution
    const glsl::BrdfDots d = glsl::brdfDots(n, v, s.direction);
    const float pdf = mixturePdf(p, material.gloss, d, NoL);
    if (!(pdf > 0.0f)) return s;
    const glm::vec3 fCos = bsdfCos(material, n, v, s.direction);
    s.weight = fCos / pdf;
    s.pdf = pdf;
    return s;
}

}  // namespace onelight::bake
