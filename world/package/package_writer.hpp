// Writes a compiled level as an .olpak package (format.hpp): deterministic bytes (no time
// stamps, zeroed padding), which the caller writes with world::writeFileAtomically
// (world/file_write.hpp).
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

/// The package's bytes: every core section, then `baked_sections` in the order given, checked by
/// the package's reader (package_decode.hpp) before they are returned. Throws world::Error with
/// the reader's message when a record would be refused.
[[nodiscard]] std::vector<uint8_t> serializePackage(const world::CompiledLevel& level,
                                                    std::span<const RawSection> bakedSections = {});

/// The same bytes unchecked: for the reader's own tests, which need packages it must refuse.
[[nodiscard]] std::vector<uint8_t> serializeUncheckedPackage(
    const world::CompiledLevel& level, std::span<const RawSection> bakedSections = {});

/// Makes the level's image file references (as imported: relative to the working folder or
/// absolute) relative to the folder of the package at `packagePath`, where the runtime looks
/// for them. An image outside that folder is read and embedded instead: a package refers only
/// to files beside it (package::isPathBesideThePackage). Throws world::Error naming an image
/// that cannot be read.
void placeImagesForPackage(world::CompiledLevel& level, const std::string& packagePath);

}  // namespace onelight::package
