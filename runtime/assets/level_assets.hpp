// A level package loaded for the runtime: the compiled level (world/package reader), its baked
// lighting when the baker filled it (sections 32..34), and its images decoded to RGBA8
// (world/images), from the package's embedded bytes or from files beside it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "world/baked_lighting.hpp"
#include "world/compiled_level.hpp"
#include "world/images/image_decode.hpp"
#include "world/processed_textures.hpp"

namespace onelight::assets {

using world::DecodedImage;

struct LoadedLevel {
    std::string path;               // the .olpak file
    world::CompiledLevel level;     // as the package holds it
    bool hasBakedLighting = false;  // the package holds sections 32..34 (a complete bake)
    world::BakedLighting baked;     // lightmap texels, shadow masks, light grid when present
    // The texture stage's mip chains (package section 38): what the renderer uploads. Packages
    // without the section (made before the stage) decode their images instead, below.
    bool hasProcessedTextures = false;
    world::ProcessedTextures processedTextures;
    std::vector<DecodedImage> images;  // one per level.images, decoded (empty: the sky's, and
                                       // all of them when processed textures are present)
    world::HdrImage sky;               // level.settings.skyImage decoded, else empty
};

/// Reads the package at `path`, its baked lighting and processed textures when present, and
/// decodes the images it still needs (the sky's Radiance .hdr; PNG and JPEG for materials only
/// without processed textures). Throws world::Error naming the
/// file and what was expected (an unmerged part of a sharded bake included).
[[nodiscard]] LoadedLevel loadLevel(const std::string& path);

}  // namespace onelight::assets
