// The materials of a bake: the level's materials with their textures decoded and mip-mapped
// once (bake_textures.hpp), so that every ray hit can be shaded as the runtime shades a pixel.
#pragma once

#include <cstdint>
#include <vector>

#include "bake/materials/bake_textures.hpp"
#include "world/compiled_level.hpp"
#include "world/processed_textures.hpp"
#include "world/source_level.hpp"

namespace onelight::bake {

/// Which of SceneMaterials::textures a material reads for each glTF slot (kNoIndex: none).
struct MaterialTextureSet {
    uint32_t baseColor = world::kNoIndex;          // sRGB
    uint32_t metallicRoughness = world::kNoIndex;  // linear
    uint32_t normal = world::kNoIndex;             // linear
    uint32_t occlusion = world::kNoIndex;          // linear
    uint32_t emissive = world::kNoIndex;           // sRGB
    uint32_t cavity = world::kNoIndex;             // linear, R
    world::MaterialTextureSlots processed;         // the stage's slots (factorsFolded), when any
    [[nodiscard]] bool any() const {
        return (baseColor & metallicRoughness & normal & occlusion & emissive & cavity) !=
               world::kNoIndex;
    }
};

struct SceneMaterials {
    std::vector<world::Material> materials;
    std::vector<MaterialTextureSet> textureSets;  // per material
    std::vector<BakeTexture> textures;            // one per (glTF texture, colour space) used
    world::DiffuseModel diffuseModel = world::DiffuseModel::kLambert;  // the level's
};

/// The materials alone, shaded with their factors (no textures).
[[nodiscard]] SceneMaterials factorMaterials(
    std::vector<world::Material> materials,
    world::DiffuseModel diffuseModel = world::DiffuseModel::kLambert);

/// The level's materials with every texture they use decoded: images embedded in the glTF or
/// read from their files (uri as the importer resolved it). Throws world::Error naming an image
/// that cannot be read or decoded.
[[nodiscard]] SceneMaterials loadSceneMaterials(const world::SourceLevel& level);

/// The level's materials reading the texture stage's mip chains, `processed` (one texture set
/// per material, as the runtime binds them).
[[nodiscard]] SceneMaterials processedSceneMaterials(const world::SourceLevel& level,
                                                     const world::ProcessedTextures& processed);

/// Bytes the decoded textures hold.
[[nodiscard]] uint64_t textureBytes(const SceneMaterials& materials);

}  // namespace onelight::bake
