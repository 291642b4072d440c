// A whole package decoded as the runtime reads it: the core sections (package_reader), the baked
// lighting (baked_sections) and the processed textures (texture_section), every record through
// its reader's checks. The one check of a package: the runtime's loader reads packages with it,
// and the writer runs it on the bytes it made before they are written, so a package the compiler
// or the baker writes always loads.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "world/package/baked_sections.hpp"
#include "world/package/package_reader.hpp"
#include "world/package/texture_section.hpp"

namespace onelight::package {

struct DecodedPackage {
    PackageContents contents;  // the compiled level and the raw sections
    BakedContents baked;       // sections 32..35, 37 when present
    TextureContents textures;  // section 38 when present
};

/// Throws world::Error starting with `name` on the first record a reader refuses.
[[nodiscard]] DecodedPackage decodePackage(std::span<const uint8_t> bytes, const std::string& name);

}  // namespace onelight::package
