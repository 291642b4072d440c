// Writer and reader of the processed textures' section (38; layout in format.hpp): the mip
// chains the texture stage made and which of them each material reads in each slot. The reader
// checks every size, count, index, range and enumeration against the section's real size with
// overflow-free arithmetic, and throws world::Error naming the section, the record and the bad
// value.
#pragma once

#include <span>
#include <string>

#include "world/compiled_level.hpp"
#include "world/package/package_writer.hpp"
#include "world/processed_textures.hpp"

namespace onelight::package {

/// Section 38 for serializePackage. Each texture's byte count is its texels' size as given: a
/// texture whose texels are not its mip chain is written, and refused by the reader.
[[nodiscard]] RawSection encodeTextureSection(const world::ProcessedTextures& textures);

/// The processed textures a package holds, if any.
struct TextureContents {
    world::ProcessedTextures textures;
    bool present = false;  // the package holds section 38
};

/// Decodes section 38 from the raw sections a package reader kept (absent: present false),
/// checked against `level`'s materials. `name` prefixes error messages (usually the file path).
/// Throws world::Error.
[[nodiscard]] TextureContents decodeTextureSection(std::span<const RawSection> sections,
                                                   const world::CompiledLevel& level,
                                                   const std::string& name);

}  // namespace onelight::package
