// Writer and reader of the visibility section (37; layout in format.hpp). The reader checks
// the header's sizes against the section's real size with overflow-free arithmetic, every
// cluster and row index, and the unused bits, and throws world::Error naming the section and
// the bad value.
#pragma once

#include <span>
#include <string>

#include "world/compiled_level.hpp"
#include "world/package/package_writer.hpp"
#include "world/visibility.hpp"

namespace onelight::package {

/// Section 37 for serializePackage; `visibility` must not be empty.
[[nodiscard]] RawSection encodeVisibilitySection(const world::Visibility& visibility);

/// The visibility in `section`, checked against `level`'s surfaces. `name` prefixes errors.
[[nodiscard]] world::Visibility decodeVisibilitySection(const RawSection& section,
                                                        const world::CompiledLevel& level,
                                                        const std::string& name);

}  // namespace onelight::package
