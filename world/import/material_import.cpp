#include "world/import/material_import.hpp"

#include <algorithm>
#include <cmath>

#include <tiny_gltf.h>

namespace onelight::world {
namespace {

float finite_or(double value, float fallback) {
    return std::isfinite(value) ? static_cast<float>(value) : fallback;
}

float clamp01(float value) {
    return std::clamp(value, 0.0f, 1.0f);
}

void derive_engine_parameters(Material& m) {
    const glm::vec3 base(m.base_color);
    m.albedo = base * (1.0f - m.metallic);
    m.specular_color = glm::mix(glm::vec3(0.04f), base, m.metallic);
    m.gloss = gloss_from_roughness(m.roughness);
    m.material_class = classify_material(m);
}

}  // namespace

float gloss_from_roughness(float roughness) {
    const double r = std::clamp(static_cast<double>(roughness), 1e-3, 1.0);
    const double r4 = (r * r) * (r * r);
    const double g = std::log2(std::max(2.0 / r4 - 1.0, 1.0)) / 18.0;
    return static_cast<float>(std::clamp(g, 0.0, 1.0));
}

MaterialClass classify_material(const Material& material) {
    const bool textured = material.metallic_roughness_texture != kNoIndex;
    if (!textured && material.metallic >= 1.0f) return MaterialClass::metal;
    if (material.metallic <= 0.0f) {
        if (!textured && material.roughness >= 1.0f) return MaterialClass::lambert;
        return MaterialClass::dielectric;
    }
    return MaterialClass::full;
}

Material default_material() {
    Material m;
    m.name = "default";
    derive_engine_parameters(m);
    return m;
}

Material convert_material(const tinygltf::Material& source,
                          const std::function<uint32_t(int)>& use_texture) {
    Material m;
    m.name = source.name;
    const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
    for (size_t i = 0; i < 4 && i < pbr.baseColorFactor.size(); ++i)
        m.base_color[static_cast<int>(i)] = clamp01(finite_or(pbr.baseColorFactor[i], 1.0f));
    m.metallic = clamp01(finite_or(pbr.metallicFactor, 1.0f));
    m.roughness = clamp01(finite_or(pbr.roughnessFactor, 1.0f));
    for (size_t i = 0; i < 3 && i < source.emissiveFactor.size(); ++i)
        m.emissive[static_cast<int>(i)] = std::max(0.0f, finite_or(source.emissiveFactor[i], 0.0f));
    m.alpha_cutoff = clamp01(finite_or(source.alphaCutoff, 0.5f));
    m.alpha_mode = source.alphaMode == "MASK"    ? AlphaMode::mask
                   : source.alphaMode == "BLEND" ? AlphaMode::blend
                                                 : AlphaMode::opaque;
    m.double_sided = source.doubleSided;
    m.base_color_texture = use_texture(pbr.baseColorTexture.index);
    m.metallic_roughness_texture = use_texture(pbr.metallicRoughnessTexture.index);
    m.normal_texture = use_texture(source.normalTexture.index);
    m.occlusion_texture = use_texture(source.occlusionTexture.index);
    m.emissive_texture = use_texture(source.emissiveTexture.index);
    m.normal_scale = finite_or(source.normalTexture.scale, 1.0f);
    m.occlusion_strength = clamp01(finite_or(source.occlusionTexture.strength, 1.0f));
    derive_engine_parameters(m);
    return m;
}

}  // namespace onelight::world
