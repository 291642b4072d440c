// Writer and reader of the collision sections (41 brushes, 42 triggers; layout in format.hpp).
// The reader checks the header's counts against the section's real size before reading, every
// side's plane index and every brush's side range, the contents bits, that every number is
// finite, planes' normals unit and trigger boxes ordered; it throws world::Error naming the
// section, the record and the bad value.
#pragma once

#include <string>
#include <vector>

#include "world/collision.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::package {

/// Sections 41 and 42 for serializePackage; none when `collision` is empty.
[[nodiscard]] std::vector<RawSection> encodeCollisionSections(
    const world::LevelCollision& collision);

/// The collision in `brushes` (41) and `triggers` (42), either null when absent, whose mover
/// indices are checked against the level's `moverCount`. `name` prefixes errors.
[[nodiscard]] world::LevelCollision decodeCollisionSections(const RawSection* brushes,
                                                            const RawSection* triggers,
                                                            uint32_t moverCount,
                                                            const std::string& name);

}  // namespace onelight::package
