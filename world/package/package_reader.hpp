// Reads an .olpak package. Validates the magic, version, header and table CRC, every section's
// place, size, record size and CRC, then loads each section with its own loader that checks
// every index and range. Anything wrong throws world::Error, one line naming the section, the
// record and the bad value; nothing is read out of bounds.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "world/compiled_level.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::package {

/// What a package holds: the compiled level and the sections this library does not interpret.
struct PackageContents {
    world::CompiledLevel level;
    std::vector<RawSection> bakedSections;  // ids >= 32, kept as bytes
};

/// Whether an image uri may appear in a package: a relative path to a file in the package's
/// folder or below it. No leading '/', no '..' or empty component, no '\\' or ':' (a drive or
/// a share): a package that could name any path would make the runtime read anything.
[[nodiscard]] bool isPathBesideThePackage(std::string_view uri);

/// Parses a whole package; `name` prefixes error messages (usually the file path). Throws
/// world::Error.
[[nodiscard]] PackageContents parsePackage(std::span<const uint8_t> bytes, const std::string& name);

/// Reads the whole file, then parsePackage. Throws world::Error.
[[nodiscard]] PackageContents readPackageFile(const std::string& path);

}  // namespace onelight::package
