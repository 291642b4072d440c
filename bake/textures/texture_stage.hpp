// The texture stage of onelight-bake: a level's glTF material textures in, their processed mip
// chains out (world/processed_textures.hpp), which the runtime uploads as they are and the baker
// samples. Every mip of every material texture is made here (docs/materials.md).
//
// Plain textures (base colour and emissive as kRgba8Srgb; occlusion, and the metallic-roughness
// texture of a material without a normal map, as kRgba8Unorm): mip 0 is the decoded image byte
// for byte; every further mip texel is the mean over its level-0 footprint (mipFootprint of
// normal_gloss_mips.hpp: 2x2 boxes, an odd level's leftover texel folded into the last one), in
// linear light for the colour of an sRGB texture (srgbDecode, mean, srgbEncode of
// shaders/tonemap.glsl, IEC 61966-2-1), in the stored values otherwise and for alpha, rounded to
// nearest. Sums are carried level to level in double, so nothing is lost to intermediate
// rounding (a linear channel's sums are exact integers). Each distinct (glTF texture, colour
// space) is made once and shared by every slot that reads it.
//
// A material with a normal map gets its normal and metallic-roughness textures made together,
// on the normal map's grid, and read through the normal texture's sampler:
//  - level 0: n = normal_fromTangentSpace of each texel (shaders/material.glsl, the normal scale
//    on x and y); roughness = roughnessFactor * G and metallic = metallicFactor * B of the
//    metallic-roughness texel at the same uv, or the factors alone when the material has no such
//    texture (then the stage makes one); gloss = gloss_fromRoughness(roughness). A metallic-
//    roughness texture of another size is resampled bilinearly at the normal map's texel centres
//    through its own sampler's wrap modes (at a 2:1 ratio that is its 2x2 box; past 2:1 texels
//    between the samples are skipped).
//  - mips: buildNormalGlossMips(level 0, method): the normal variation a mip texel averages
//    away becomes roughness in its gloss. A Lambert-only material (no specular lobe) uses Blit
//    whatever the method: its diffuse is linear in the normal, so the normalised mean normal is
//    the footprint's own direction, and there is no lobe to widen (roughness stays the mean).
//  - encoding: normal RGBA8 = round(255 (0.5 + 0.5 n)), alpha 255; metallic-roughness R = the
//    occlusion when the material packs it in the same image (ORM; its occlusion slot then reads
//    this texture) else 255, G = roughness (mip 0: the level-0 roughness itself; further mips:
//    roughness_fromGloss of the mip's gloss), B = metallic (footprint mean), A = 255.
//    factorsFolded is set: the normal scale and the metallic and roughness factors are in the
//    textures (the occlusion strength is not).
//  - cavity (Chan 2018, sec. 4): cavityFromNormals of the scaled level-0 normals, wrap from the
//    normal texture's sampler (REPEAT repeats; CLAMP_TO_EDGE clamps; MIRRORED_REPEAT clamps too:
//    a mirrored field's height solve is the clamped one's, and its horizons differ only within
//    the scan radius of the border), cavityMipChain, cavityToUnorm8: a kR8Unorm texture.
//  - facets: a material with a specular lobe (not Lambert-only) also gets the facet table of
//    its level 0 (facet_table.hpp: the whole tile's facet normals, the map read through its
//    sampler's wrap), a kR16Float texture, unless options.facetTables is off.
// Materials that agree on every input of these (normal texture and scale, metallic-roughness
// texture, factors, packed occlusion, Lambert or not) share the three textures and the table; the
// cavity is shared by every material with the same normal texture and scale.
//
// Skipped: a texture whose image is the level's sky image (SourceLevel::skyImage, an HDR, not a
// material texture) and a glTF texture without an image; the slot reads nothing (a normal map:
// the material has none).
//
// Memory: every decoded image is charged to an ImageMemoryBudget (options.memoryLimitBytes)
// before it is decoded, at its peak working set per texel (kPlainTextureBytesPerTexel,
// kNormalMapBytesPerTexel, a metallic-roughness image at 4), and once a texture is made only
// what it keeps (its mip chain's bytes) stays charged: textures are made one after another, so
// the budget holds the output so far plus one working set. A facet table's bins (4.7 MiB at
// most, whatever the map's size: facet_table.hpp) are not charged.
//
// Deterministic: every texel is a fixed-order function of the level's data, computed in
// parallel rows with TBB (here and in normal_gloss_mips and cavity_map): the same level gives the
// same bytes at any thread count. No NaN reaches a texel: factors and scales that are not finite
// read as their glTF defaults.
//
// Errors (world::Error): an image that cannot be read or decoded, or that the budget refuses,
// named by the level file, the image index and name; a material or texture index out of range.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bake/textures/cavity_map.hpp"
#include "world/images/image_budget.hpp"
#include "world/processed_textures.hpp"
#include "world/source_level.hpp"

namespace onelight::bake {

/// Peak bytes per texel of a plain texture: its decoded RGBA8 (4), its mips (16 / 3) and the
/// double sums of two levels at once (4 channels: 8 for level 1 per level-0 texel, 2 for level 2).
inline constexpr double kPlainTextureBytesPerTexel = 4.0 + 16.0 / 3.0 + 10.0;

/// Peak bytes per normal-map texel of a normal and metallic-roughness pair, inside
/// buildNormalGlossMips: the decoded RGBA8 (4), the metallic and occlusion planes (8), level 0 of
/// normals and gloss (16) and the chain's copy of it with its mips (16 * 4 / 3), the chain's
/// footprint sums (128 for level 0, 32 for level 1), and the three outputs' mips (normal and
/// metallic-roughness 16 / 3 each, cavity 4 / 3). The cavity's height solve (about 50) comes
/// before and needs less.
inline constexpr double kNormalMapBytesPerTexel =
    4.0 + 8.0 + 16.0 + 16.0 * 4.0 / 3.0 + 160.0 + 2.0 * 16.0 / 3.0 + 4.0 / 3.0;

struct TextureStageOptions {
    HorizonScan cavityScan;         // cavityFromHeight's horizon scan
    float cavityDepthScale = 1.0f;  // heightFromNormals' depth scale
    uint64_t memoryLimitBytes = world::kMaxDecodedImageBytes;
    // A facet table per specular normal map (facet_table.hpp); off for the baseline.
    bool facetTables = true;
};

/// Every material texture of `level` processed, the normal and gloss mips by `method` (the level
/// asks for level.glossMips). One MaterialTextureSlots per material, in order.
[[nodiscard]] world::ProcessedTextures processLevelTextures(
    const world::SourceLevel& level, world::GlossMipMethod method,
    const TextureStageOptions& options = {});

/// One processed texture for the bake report.
struct ProcessedTextureRow {
    std::string name;
    world::TexelFormat format = world::TexelFormat::kRgba8Unorm;
    uint32_t width = 0, height = 0, mipCount = 0;
    uint64_t bytes = 0;  // every mip
};

struct TextureStageReport {
    std::vector<ProcessedTextureRow> textures;  // in the order of ProcessedTextures::textures
    uint64_t totalBytes = 0;
};

[[nodiscard]] TextureStageReport textureStageReport(const world::ProcessedTextures& textures);

/// "RGBA8 sRGB", "RGBA8" or "R8".
[[nodiscard]] const char* texelFormatName(world::TexelFormat format);

}  // namespace onelight::bake
