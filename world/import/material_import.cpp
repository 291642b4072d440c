#include "world/import/material_import.hpp"

#include <algorithm>
#include <cmath>

#include <tiny_gltf.h>

namespace onelight::world {
namespace {

float finiteOr(double value, float fallback) {
    return std::isfinite(value) ? static_cast<float>(value) : fallback;
}

float clamp01(float value) {
    return std::clamp(value, 0.0f, 1.0f);
}

void deriveEngineParameters(Material& m) {
    const glm::vec3 base(m.baseColor);
    m.albedo = base * (1.0f - m.metallic);
    m.specularColor = glm::mix(glm::vec3(0.04f), base, m.metallic);
    m.gloss = glossFromRoughness(m.roughness);
    m.materialClass = classifyMaterial(m);
}

}  // namespace

float glossFromRoughness(float roughness) {
    const double r = std::clamp(static_cast<double>(roughness), 1e-3, 1.0);
    const double r4 = (r * r) * (r * r);
    const double g = std::log2(std::max(2.0 / r4 - 1.0, 1.0)) / 18.0;
    return static_cast<float>(std::clamp(g, 0.0, 1.0));
}

MaterialClass classifyMaterial(const Material& material) {
    const bool textured = material.metallicRoughnessTexture != kNoIndex;
    if (!textured && material.metallic >= 1.0f) return MaterialClass::kMetal;
    if (material.metallic <= 0.0f) {
        if (!textured && material.roughness >= 1.0f) return MaterialClass::kLambert;
        return MaterialClass::kDielectric;
    }
    return MaterialClass::kFull;
}

Material defaultMaterial() {
    Material m;
    m.name = "default";
    deriveEngineParameters(m);
    return m;
}

Material convertMaterial(const tinygltf::Material& source,
                         const std::function<uint32_t(int)>& useTexture) {
    Material m;
    m.name = source.name;
    const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
    for (size_t i = 0; i < 4 && i < pbr.baseColorFactor.size(); ++i)
        m.baseColor[static_cast<int>(i)] = clamp01(finiteOr(pbr.baseColorFactor[i], 1.0f));
    m.metallic = clamp01(finiteOr(pbr.metallicFactor, 1.0f));
    m.roughness = clamp01(finiteOr(pbr.roughnessFactor, 1.0f));
    for (size_t i = 0; i < 3 && i < source.emissiveFactor.size(); ++i)
        m.emissive[static_cast<int>(i)] = std::max(0.0f, finiteOr(source.emissiveFactor[i], 0.0f));
    // KHR_materials_emissive_strength scales the factor; the product is in cd/m^2 (README).
    if (const auto it = source.extensions.find("KHR_materials_emissive_strength");
        it != source.extensions.end() && it->second.Has("emissiveStrength")) {
        const tinygltf::Value& strength = it->second.Get("emissiveStrength");
        if (strength.IsNumber())
            m.emissive *= std::max(0.0f, finiteOr(strength.GetNumberAsDouble(), 1.0f));
    }
    m.alphaCutoff = clamp01(finiteOr(source.alphaCutoff, 0.5f));
    m.alphaMode = source.alphaMode == "MASK"    ? AlphaMode::kMask
                  : source.alphaMode == "BLEND" ? AlphaMode::kBlend
                                                : AlphaMode::kOpaque;
    m.doubleSided = source.doubleSided;
    m.baseColorTexture = useTexture(pbr.baseColorTexture.index);
    m.metallicRoughnessTexture = useTexture(pbr.metallicRoughnessTexture.index);
    m.normalTexture = useTexture(source.normalTexture.index);
    m.occlusionTexture = useTexture(source.occlusionTexture.index);
    m.emissiveTexture = useTexture(source.emissiveTexture.index);
    m.normalScale = finiteOr(source.normalTexture.scale, 1.0f);
    m.occlusionStrength = clamp01(finiteOr(source.occlusionTexture.strength, 1.0f));
    // extras.onelight.casts_shadows false: drawn, but light passes it (a Quake 3 translucent
    // surface written back by onelight-bake export; compiled_level.hpp, Material::castsShadows).
    if (source.extras.IsObject() && source.extras.Has("onelight")) {
        const tinygltf::Value& o = source.extras.Get("onelight");
        if (o.IsObject() && o.Has("casts_shadows") && o.Get("casts_shadows").IsBool())
            m.castsShadows = o.Get("casts_shadows").Get<bool>();
    }
    deriveEngineParameters(m);
    return m;
}

}  // namespace onelight::world
