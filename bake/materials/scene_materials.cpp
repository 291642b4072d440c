#include "bake/materials/scene_materials.hpp"

#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "world/error.hpp"

namespace onelight::bake {

SceneMaterials factorMaterials(std::vector<world::Material> materials,
                               world::DiffuseModel diffuseModel) {
    SceneMaterials out;
    out.diffuseModel = diffuseModel;
    out.textureSets.resize(materials.size());
    out.materials = std::move(materials);
    return out;
}

SceneMaterials loadSceneMaterials(const world::SourceLevel& level) {
    SceneMaterials out = factorMaterials(level.materials, level.diffuseModel);
    std::map<uint32_t, world::DecodedImage> decoded;  // by image index
    // (texture, sRGB, averaged over its coverage) -> textures
    std::map<std::tuple<uint32_t, bool, bool>, uint32_t> made;
    // Each decoded image becomes float RGBA texels with their mips (16 * 4 / 3 bytes a texel),
    // once per colour space it is read in; charged before it is decoded.
    world::ImageMemoryBudget budget{16.0 * 4.0 / 3.0 + 4.0};
    auto image = [&](uint32_t index) -> const world::DecodedImage& {
        auto found = decoded.find(index);
        if (found != decoded.end()) return found->second;
        const world::Image& source = level.images.at(index);
        const std::string where =
            level.sourcePath + ": image " + std::to_string(index) + " '" + source.name + "'";
        world::DecodedImage pixels =
            source.encodedBytes.empty()
                ? world::readImageFile(source.uri, &budget)
                : world::decodeImage(source.encodedBytes.data(), source.encodedBytes.size(), where,
                                     &budget);
        return decoded.emplace(index, std::move(pixels)).first->second;
    };
    auto texture = [&](uint32_t index, bool srgb, bool overCoverage = false) -> uint32_t {
        if (index == world::kNoIndex || index >= level.textures.size()) return world::kNoIndex;
        const world::Texture& t = level.textures[index];
        if (t.image == world::kNoIndex || t.image >= level.images.size()) return world::kNoIndex;
        const auto key = std::make_tuple(index, srgb, overCoverage);
        auto found = made.find(key);
        if (found != made.end()) return found->second;
        out.textures.push_back(makeBakeTexture(image(t.image), srgb, overCoverage, t.sampler));
        const uint32_t slot = uint32_t(out.textures.size() - 1);
        made[key] = slot;
        return slot;
    };
    for (size_t m = 0; m < out.materials.size(); ++m) {
        const world::Material& material = out.materials[m];
        MaterialTextureSet& set = out.textureSets[m];
        set.baseColor = texture(material.baseColorTexture, true,
                                material.alphaMode != world::AlphaMode::kOpaque);
        set.metallicRoughness = texture(material.metallicRoughnessTexture, false);
        set.normal = texture(material.normalTexture, false);
        set.occlusion = texture(material.occlusionTexture, false);
        set.emissive = texture(material.emissiveTexture, true);
    }
    return out;
}

SceneMaterials processedSceneMaterials(const world::SourceLevel& level,
                                       const world::ProcessedTextures& processed) {
    SceneMaterials out = factorMaterials(level.materials, level.diffuseModel);
    out.textures.reserve(processed.textures.size());
    for (const world::ProcessedTexture& texture : processed.textures)
        out.textures.push_back(makeBakeTexture(texture));
    for (size_t m = 0; m < out.materials.size() && m < processed.materials.size(); ++m) {
        const world::MaterialTextureSlots& slots = processed.materials[m];
        const auto index = [&](uint32_t slot) {
            return slot < out.textures.size() && !out.textures[slot].texels.empty()
                       ? slot
                       : world::kNoIndex;
        };
        MaterialTextureSet& set = out.textureSets[m];
        set.baseColor = index(slots.baseColor);
        set.metallicRoughness = index(slots.metallicRoughness);
        set.normal = index(slots.normal);
        set.occlusion = index(slots.occlusion);
        set.emissive = index(slots.emissive);
        set.cavity = index(slots.cavity);
        set.processed = slots;
    }
    return out;
}

uint64_t textureBytes(const SceneMaterials& materials) {
    uint64_t bytes = 0;
    for (const BakeTexture& t : materials.textures) bytes += textureBytes(t);
    return bytes;
}

}  // namespace onelight::bake
