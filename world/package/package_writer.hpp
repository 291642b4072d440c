// Writes a compiled level as an .olpak package (format.hpp): deterministic bytes (no time
// stamps, zeroed padding), written to a temporary file and renamed when complete.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "world/compiled_level.hpp"

namespace onelight::package {

/// A section the package library does not interpret (the baker's lighting sections).
struct RawSection {
    uint32_t id = 0;             // SectionId >= 32
    uint32_t elementSize = 1;    // bytes per record
    uint32_t count = 0;          // records
    std::vector<uint8_t> bytes;  // count * elementSize
};

/// The package's bytes: every core section, then `baked_sections` in the order given.
[[nodiscard]] std::vector<uint8_t> serializePackage(const world::CompiledLevel& level,
                                                    std::span<const RawSection> bakedSections = {});

/// Makes the level's image file references (as imported: relative to the working folder or
/// absolute) relative to the folder of the package at `packagePath`, where the runtime looks
/// for them. An image outside that folder is read and embedded instead: a package refers only
/// to files beside it (package::isPathBesideThePackage). Throws world::Error naming an image
/// that cannot be read.
void placeImagesForPackage(world::CompiledLevel& level, const std::string& packagePath);

/// Writes `bytes` to `path` through `path.tmp` and a rename, so that `path` is never
/// half-written; makes `path`'s folder when it is missing. Throws world::Error naming the file.
void writeFileAtomically(const std::string& path, std::span<const uint8_t> bytes);

}  // namespace onelight::package
