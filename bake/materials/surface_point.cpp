#include "bake/materials/surface_point.hpp"

#include <algorithm>
#include <cmath>

#include "env_brdf_table.hpp"
#include "shading.hpp"

namespace onelight::bake {
namespace {

// The level of detail of `texture` for a footprint of `width` metres (already divided by the
// cosine) on a triangle of uv density `uvDensityLog2`: log2 of the texels the footprint covers
// (Akenine-Moller et al. 2019, Ray Tracing Gems ch. 20, eq. 20.4, with the triangle's texel
// density 0.5 log2(texels * uv area / world area)).
float lodOf(const BakeTexture& texture, float width, float uvDensityLog2) {
    if (!(width > 0.0f)) return 0.0f;
    return std::log2(width) + uvDensityLog2 +
           0.5f * std::log2(float(texture.width) * float(texture.height));
}

glm::vec4 texel(const SceneMaterials& materials, uint32_t index, const SurfaceAttributes& a,
                float width) {
    if (index == world::kNoIndex) return glm::vec4(1.0f);
    const BakeTexture& t = materials.textures[index];
    return sampleTexture(t, a.uv, lodOf(t, width, a.uvDensityLog2));
}

}  // namespace

glm::vec3 bsdfCos(const Bsdf& bsdf, const glm::vec3& n, const glm::vec3& v, const glm::vec3& l) {
    const glsl::BrdfDots d = glsl::brdfDots(n, v, l);
    const glm::vec2 env =
        bsdf.materialClass == MATERIAL_LAMBERT
            ? glm::vec2(0.0f)
            : glsl::sampleEnvBrdfTable(glsl::envBrdfTableCoord(d.NoV, bsdf.gloss));
    return glsl::surfaceReflectance(bsdf.materialClass, bsdf.diffuseModel, bsdf.albedo,
                                    bsdf.specularColor, bsdf.gloss, env, 1.0f, d);
}

glm::vec3 diffuseEnergyWeight(const Bsdf& bsdf, float NoV) {
    if (bsdf.materialClass == MATERIAL_LAMBERT) return glm::vec3(1.0f);
    const glm::vec2 env = glsl::sampleEnvBrdfTable(
        glsl::envBrdfTableCoord(std::clamp(NoV, glsl::MIN_NOV, 1.0f), bsdf.gloss));
    return glsl::diffuseEnergyWeight(bsdf.materialClass, bsdf.specularColor, env);
}

Bsdf factorBsdf(const world::Material& material, world::DiffuseModel diffuseModel) {
    // The compiled factors (materialPoint of the glTF factors), with the terms the material's
    // class keeps: a Lambert-only material no specular, a metal no diffuse (materialPoint).
    Bsdf b{material.albedo, material.specularColor, material.gloss, int(material.materialClass),
           int(diffuseModel)};
    if (material.materialClass == world::MaterialClass::kLambert) b.specularColor = glm::vec3(0.0f);
    if (material.materialClass == world::MaterialClass::kMetal) b.albedo = glm::vec3(0.0f);
    return b;
}

MaterialSample sampleMaterial(const SceneMaterials& materials, uint32_t material,
                              const SurfaceAttributes& a, const glm::vec3& geometricNormal,
                              bool backFace, float footprint, const glm::vec3& toViewer) {
    const float cosine = glm::dot(geometricNormal, toViewer);
    static const world::Material kDefault;
    const bool known = material < materials.materials.size();
    const world::Material& m = known ? materials.materials[material] : kDefault;
    MaterialSample s;
    s.shadingNormal = geometricNormal;
    if (!known || !materials.textureSets[material].any()) {
        s.bsdf = factorBsdf(m, materials.diffuseModel);
        s.emission = sampleEmission(materials, material, a, backFace, 0.0f);
        s.alpha = m.baseColor.w;
        // Smooth shading: the interpolated vertex normal, on the ray's side, as the shader.
        const float length2 = glm::dot(a.normal, a.normal);
        if (length2 > 1e-12f)
            s.shadingNormal = (backFace ? -a.normal : a.normal) / std::sqrt(length2);
        return s;
    }
    const MaterialTextureSet& set = materials.textureSets[material];
    const float width = footprint / std::max(std::fabs(cosine), 1e-3f);
    const glm::vec4 base = m.baseColor * texel(materials, set.baseColor, a, width);
    // Factors the texture stage folded into the textures read as 1 (as the runtime reads them).
    const world::TextureFactors factors = world::textureFactors(m, set.processed);
    const float metallic = factors.metallic, roughness = factors.roughness,
                normalScale = factors.normalScale;
    const glm::vec2 mr =
        glsl::metallicRoughness_fromTexel(int(m.materialClass), metallic, roughness,
                                          set.metallicRoughness == world::kNoIndex
                                              ? glm::vec4(1.0f)
                                              : texel(materials, set.metallicRoughness, a, width));
    const glsl::MaterialPoint point =
        glsl::materialPoint(int(m.materialClass), glm::vec3(base), mr.x, mr.y, m.specularColor.x);
    s.bsdf = {point.albedo, point.f0, point.gloss, int(m.materialClass),
              int(materials.diffuseModel)};
    s.alpha = base.w;
    if (set.occlusion != world::kNoIndex)
        s.occlusion =
            std::clamp(glsl::occlusion_fromTexel(texel(materials, set.occlusion, a, width).x,
                                                 m.occlusionStrength),
                       0.0f, 1.0f);
    s.emission = sampleEmission(materials, material, a, backFace, width);

    // The normal as forward_shading.glsl builds it: the interpolated normal (flipped on a back
    // face), the tangent made orthogonal to it, the map's texel in that frame.
    glm::vec3 n = geometricNormal;
    const float length2 = glm::dot(a.normal, a.normal);
    if (length2 > 1e-12f) n = (backFace ? -a.normal : a.normal) / std::sqrt(length2);
    if (set.normal != world::kNoIndex) {
        const glm::vec3 tangent(a.tangent);
        const glm::vec3 t = tangent - n * glm::dot(n, tangent);
        const float tl = glm::length(t);
        const glm::vec3 normalTexel(texel(materials, set.normal, a, width));
        if (tl > 1e-6f)
            n = glsl::normal_fromTangentSpace(normalTexel, normalScale, n, t / tl, a.tangent.w);
        // Bent where its reflection would leave below the surface, as forward_shading.glsl.
        const glm::vec3 surfaceNormal = length2 > 1e-12f
                                            ? (backFace ? -a.normal : a.normal) / std::sqrt(length2)
                                            : geometricNormal;
        n = glsl::normal_withValidReflection(n, surfaceNormal, toViewer);
        // The filter's spread of the normals folds into the gloss, as forward_shading.glsl does; a
        // point sample (the reference's camera rays, footprint 0) sees one normal, no mixture.
        if (m.materialClass != world::MaterialClass::kLambert && width > 0.0f)
            s.bsdf.gloss = glsl::gloss_withFilteredNormal(s.bsdf.gloss, normalTexel * 2.0f - 1.0f);
    }
    s.shadingNormal = n;
    return s;
}

glm::vec3 sampleEmission(const SceneMaterials& materials, uint32_t material,
                         const SurfaceAttributes& a, bool backFace, float width) {
    if (material >= materials.materials.size()) return glm::vec3(0.0f);
    const world::Material& m = materials.materials[material];
    if ((backFace && !m.doubleSided) || m.emissive == glm::vec3(0.0f)) return glm::vec3(0.0f);
    return m.emissive *
           glm::vec3(texel(materials, materials.textureSets[material].emissive, a, width));
}

glm::vec3 meanEmission(const SceneMaterials& materials, uint32_t material) {
    if (material >= materials.materials.size()) return glm::vec3(0.0f);
    const world::Material& m = materials.materials[material];
    const uint32_t index = materials.textureSets[material].emissive;
    if (index == world::kNoIndex) return m.emissive;
    const BakeTexture& t = materials.textures[index];
    return m.emissive * glm::vec3(t.texels[t.mipOffset.back()]);
}

float sampleAlpha(const SceneMaterials& materials, uint32_t material, glm::vec2 uv) {
    if (material >= materials.materials.size()) return 1.0f;
    const world::Material& m = materials.materials[material];
    const uint32_t base = materials.textureSets[material].baseColor;
    if (base == world::kNoIndex) return m.baseColor.w;
    return m.baseColor.w * sampleTexture(materials.textures[base], uv, 0.0f).w;
}

}  // namespace onelight::bake
