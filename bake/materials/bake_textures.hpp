// The level's material textures for the baker, sampled at ray hits as the runtime's GPU samples
// them: decoded once (world/images), sRGB-decoded where the runtime's image is an _SRGB format
// (base colour and emissive), a 2x2 box-filtered mip chain in linear values (a MASK or BLEND base
// colour's averaged over its alpha's coverage, as the texture stage's mips), the glTF sampler's
// wrap modes, and bilinear filtering between the two mips around a level of detail that comes from
// the ray's footprint (bake/materials/ray_cone.hpp).
//
// Layout: each mip is a row-major array of float RGBA texels (16 bytes, one cache line holds a
// 2x2 bilinear footprint's row pair in most cases), the mips of a texture contiguous in one
// allocation, largest first.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"
#include "world/images/image_decode.hpp"
#include "world/processed_textures.hpp"

namespace onelight::bake {

/// One decoded texture with its mip chain.
struct BakeTexture {
    uint32_t width = 0, height = 0;  // mip 0
    uint32_t mipCount = 0;
    std::vector<glm::vec4> texels;          // every mip, largest first, rows top to bottom
    std::vector<uint64_t> mipOffset;        // first texel of each mip
    uint16_t wrapS = 10497, wrapT = 10497;  // glTF wrap modes: REPEAT, CLAMP_TO_EDGE, MIRRORED
    bool magNearest = false;                // glTF magFilter NEAREST
};

/// The texture of `image` as sampled through `sampler`, sRGB-decoded when `srgb`; its mips' colour
/// averaged over the alpha's coverage when `overCoverage` (a MASK or BLEND material's base
/// colour: the texture stage's plainTexture, bake/textures/texture_stage.cpp).
[[nodiscard]] BakeTexture makeBakeTexture(const world::DecodedImage& image, bool srgb,
                                          bool overCoverage, const world::Sampler& sampler);

/// A texture the texture stage made (bake/textures), its mips as stored: what the runtime uploads,
/// in float (sRGB-decoded for kRgba8Srgb; an R8 texel reads (r, 0, 0, 1) as on the GPU). Empty
/// when its texel bytes do not match its size (the package reader checks them).
[[nodiscard]] BakeTexture makeBakeTexture(const world::ProcessedTexture& processed);

/// The texture at texture coordinate `uv` (glTF: v down) and level of detail `lod` (0 = mip 0;
/// clamped to the chain): bilinear in the two mips around it, linearly blended (trilinear).
[[nodiscard]] glm::vec4 sampleTexture(const BakeTexture& texture, glm::vec2 uv, float lod);

/// Bytes the texels of `texture` hold.
[[nodiscard]] inline uint64_t textureBytes(const BakeTexture& texture) {
    return texture.texels.size() * sizeof(glm::vec4);
}

}  // namespace onelight::bake
