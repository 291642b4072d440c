// A material evaluated where a ray landed, as the runtime's forward pass evaluates it at a pixel
// (shaders/material.glsl through shading.hpp, the same source): base colour factor times the
// sRGB-decoded texel, metallic-roughness to albedo, f0 and gloss, the normal map in the tangent
// frame the renderer builds, occlusion, and emission in cd/m^2. Texels are read at the level of
// detail of the ray's footprint (ray_cone.hpp).
#pragma once

#include <glm/glm.hpp>

#include "bake/materials/scene_materials.hpp"

namespace onelight::bake {

/// What the BRDF of a surface point needs: surfaceReflectance of shaders/lighting.glsl, the
/// level's diffuse model with its energy-conservation weight plus the runtime lobe.
struct Bsdf {
    glm::vec3 albedo{0.0f};         // diffuse reflectance, linear
    glm::vec3 specularColor{0.0f};  // f0
    float gloss = 0.0f;             // [0, 1]
    int materialClass = 2;          // MATERIAL_* (lighting.glsl); 2 = MATERIAL_FULL
    int diffuseModel = 0;           // DIFFUSE_* (lighting.glsl); 0 = DIFFUSE_LAMBERT
};

/// f(v, l) NoL of `bsdf` at unit normal n, view v and light l: surfaceReflectance of
/// shaders/lighting.glsl, as the forward pass evaluates it, with the split-sum term from the
/// runtime's table (env_brdf_table.hpp) and no cavity.
[[nodiscard]] glm::vec3 bsdfCos(const Bsdf& bsdf, const glm::vec3& n, const glm::vec3& v,
                                const glm::vec3& l);

/// The weight of `bsdf`'s diffuse layer seen at cosine NoV (diffuseEnergyWeight of
/// shaders/lighting.glsl with the runtime's split-sum table): 1 for a Lambert-only material.
[[nodiscard]] glm::vec3 diffuseEnergyWeight(const Bsdf& bsdf, float NoV);

/// The shading factors of a material with its textures ignored, under `diffuseModel`.
[[nodiscard]] Bsdf factorBsdf(const world::Material& material,
                              world::DiffuseModel diffuseModel = world::DiffuseModel::kLambert);

/// What a surface point looks like to the ray that found it.
struct SurfaceAttributes {
    glm::vec2 uv{0.0f};                         // TEXCOORD_0, interpolated
    glm::vec3 normal{0.0f, 0.0f, 1.0f};         // interpolated vertex normal, unit
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // interpolated, w = bitangent sign
    float uvDensityLog2 = 0.0f;                 // 0.5 log2(uv area / world area) of the triangle
};

struct MaterialSample {
    Bsdf bsdf;
    glm::vec3 shadingNormal{0.0f, 0.0f, 1.0f};  // unit, on the side the ray arrived from
    glm::vec3 emission{0.0f};                   // cd/m^2 leaving the side the ray arrived from
    float occlusion = 1.0f;                     // the material's ambient occlusion, [0, 1]
    float alpha = 1.0f;                         // coverage (base colour alpha)
};

/// Material `material` of `materials` at a point with `attributes`, seen by a ray whose
/// footprint there is `footprint` metres wide (0: the finest mip) arriving from `toViewer` (unit,
/// towards where the ray came from), from the side `geometricNormal` faces (the front face's
/// normal, flipped towards the ray on a back face) and `backFace` tells. A normal map's normal is
/// bent where its reflection of `toViewer` would leave below the surface
/// (normal_withValidReflection, shaders/material.glsl), as the forward pass bends it.
[[nodiscard]] MaterialSample sampleMaterial(const SceneMaterials& materials, uint32_t material,
                                            const SurfaceAttributes& attributes,
                                            const glm::vec3& geometricNormal, bool backFace,
                                            float footprint, const glm::vec3& toViewer);

/// The emission (cd/m^2) of `material` at a point, towards the side the ray arrived from (none
/// from the back face of a single-sided material), its texture read for a footprint `width`
/// metres wide across the surface (0: the finest mip).
[[nodiscard]] glm::vec3 sampleEmission(const SceneMaterials& materials, uint32_t material,
                                       const SurfaceAttributes& attributes, bool backFace,
                                       float width);

/// The emission factor times the emissive texture's mean (the last mip): to rank emitters.
[[nodiscard]] glm::vec3 meanEmission(const SceneMaterials& materials, uint32_t material);

/// The base colour alpha alone (alpha-tested coverage), at the finest mip.
[[nodiscard]] float sampleAlpha(const SceneMaterials& materials, uint32_t material, glm::vec2 uv);

}  // namespace onelight::bake
