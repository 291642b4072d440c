// The level's material textures as the texture stage made them (bake/textures/texture_stage,
// docs/materials.md): every mip of every texture, ready to upload as it is, and which texture
// each material reads in each slot. The runtime uploads these and the baker samples them;
// nothing else makes mips. Stored in the package's textures section (format.hpp, id 38).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "world/compiled_level.hpp"

namespace onelight::world {

/// How a processed texture's texels are stored (one Vulkan format each).
enum class TexelFormat : uint8_t {
    kRgba8Srgb = 0,   // VK_FORMAT_R8G8B8A8_SRGB: base colour, emissive
    kRgba8Unorm = 1,  // VK_FORMAT_R8G8B8A8_UNORM: normal, metallic-roughness, occlusion
    kR8Unorm = 2,     // VK_FORMAT_R8_UNORM: cavity
    kR16Float = 3,    // VK_FORMAT_R16_SFLOAT: a normal map's facet table
};

[[nodiscard]] inline uint32_t bytesPerTexel(TexelFormat format) {
    switch (format) {
        case TexelFormat::kR8Unorm:
            return 1u;
        case TexelFormat::kR16Float:
            return 2u;
        default:
            return 4u;
    }
}

/// Mips of a texture of `width` x `height`: down to 1x1, mip k is max(1, width >> k) by
/// max(1, height >> k).
[[nodiscard]] inline uint32_t fullMipCount(uint32_t width, uint32_t height) {
    uint32_t count = 1;
    for (uint32_t size = width > height ? width : height; size > 1; size /= 2) ++count;
    return count;
}

/// Bytes of every mip of a texture, largest first, tightly packed.
[[nodiscard]] inline uint64_t mipChainBytes(TexelFormat format, uint32_t width, uint32_t height,
                                            uint32_t mipCount) {
    uint64_t bytes = 0;
    for (uint32_t k = 0; k < mipCount; ++k) {
        const uint64_t w = (width >> k) > 0 ? (width >> k) : 1;
        const uint64_t h = (height >> k) > 0 ? (height >> k) : 1;
        bytes += w * h * bytesPerTexel(format);
    }
    return bytes;
}

struct ProcessedTexture {
    std::string name;  // what it was made from, for messages and reports ("stone normal")
    TexelFormat format = TexelFormat::kRgba8Unorm;
    uint32_t width = 0, height = 0;  // mip 0, 1..kMaxImageExtent
    uint32_t mipCount = 0;           // fullMipCount(width, height)
    Sampler sampler;                 // the glTF sampler it is read through
    std::vector<uint8_t> texels;     // every mip, largest first, rows top to bottom, packed
};

/// The processed texture each material slot reads (kNoIndex: none).
struct MaterialTextureSlots {
    uint32_t baseColor = kNoIndex;          // kRgba8Srgb
    uint32_t metallicRoughness = kNoIndex;  // kRgba8Unorm: G roughness, B metallic (glTF)
    uint32_t normal = kNoIndex;             // kRgba8Unorm: tangent-space, glTF convention
    uint32_t occlusion = kNoIndex;          // kRgba8Unorm: R
    uint32_t emissive = kNoIndex;           // kRgba8Srgb
    uint32_t cavity = kNoIndex;             // kR8Unorm, made from the normal map
    // kR16Float: the normal map's facet table, the distribution of the whole tile's facet normals
    // (bake/textures/facet_table.hpp), made with the normal and metallic-roughness pair of a
    // material with a specular lobe.
    uint32_t facets = kNoIndex;
    // The material's metallic and roughness factors and its normal scale are already in its
    // metallic-roughness and normal textures (the stage folds them in before filtering the
    // normals into the gloss): a reader multiplies by 1 instead of the material's factors.
    bool factorsFolded = false;
    // A of the metallic-roughness texture is the roughness of the normal-map texels' own lobes
    // under each mip texel (their RMS alpha), G the whole footprint's (the lobes and the spread
    // of the normals): a reader can tell the bumps' share of the lobe (shaders/material.glsl,
    // "A footprint's bumps"). Only on the pair the stage makes for a normal-mapped material.
    bool baseRoughnessInAlpha = false;
    // A of the normal texture is the kurtosis k of the slopes under each mip texel, stored as
    // (k - 1) / 2 (k from 1, slopes on a ring, to 3; 2 Gaussian): the shape of the bumps' facets
    // (shaders/material.glsl, "A footprint's bumps"). Only on the pair the stage makes.
    bool slopeKurtosisInNormalAlpha = false;
};

/// The factors a reader multiplies a material's texels by (shaders/material.glsl): 1 for those the
/// texture stage folded into the textures. A Lambert-only material never reads its
/// metallic-roughness texel (metallicRoughness_fromTexel), so it keeps those two factors.
struct TextureFactors {
    float metallic = 1.0f, roughness = 1.0f, normalScale = 1.0f;
};
[[nodiscard]] inline TextureFactors textureFactors(const Material& m,
                                                   const MaterialTextureSlots& slots) {
    if (!slots.factorsFolded) return {m.metallic, m.roughness, m.normalScale};
    if (m.materialClass == MaterialClass::kLambert) return {m.metallic, m.roughness, 1.0f};
    return {1.0f, 1.0f, 1.0f};
}

struct ProcessedTextures {
    GlossMipMethod method = GlossMipMethod::kClean;  // how the normal and gloss mips were made
    std::vector<ProcessedTexture> textures;
    std::vector<MaterialTextureSlots> materials;  // one per level material, in order
};

}  // namespace onelight::world
