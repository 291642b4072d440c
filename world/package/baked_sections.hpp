// Writer and reader of the baked-lighting sections (32 lightmap texels, 33 shadow masks,
// 34 light grid, 35 probes through probe_section.hpp, 37 visibility through
// visibility_section.hpp; layouts in format.hpp). The reader
// checks every size, count, index and value range against the compiled level and throws
// world::Error naming the section and the bad value.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "world/baked_lighting.hpp"
#include "world/compiled_level.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::package {

/// Sections 32, 33 and 34, in that order, then 35 when there are probes, for serializePackage.
[[nodiscard]] std::vector<RawSection> encodeBakedSections(const world::BakedLighting& baked);

/// The baked lighting a package holds, if any.
struct BakedContents {
    world::BakedLighting baked;
    bool present = false;  // the package holds baked lighting
};

/// Decodes sections 32..34 from the raw sections a package reader kept, and 35 when present.
/// All of 32..34 or none must be present, and 35 only with them. `name` prefixes error messages
/// (usually the file path). Throws world::Error.
[[nodiscard]] BakedContents decodeBakedSections(std::span<const RawSection> sections,
                                                const world::CompiledLevel& level,
                                                const std::string& name);

}  // namespace onelight::package
