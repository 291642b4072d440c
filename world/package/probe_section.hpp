// Writer and reader of the environment probes' section (35; layout in format.hpp), and the
// RGB9E5 shared-exponent texel encoding it stores. The reader checks every size, count, index
// and value range and throws world::Error naming the section, the record and the bad value.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "world/baked_lighting.hpp"
#include "world/compiled_level.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::world {

/// Texels of a cube of edge `face_size` with every mip down to 1x1: 6 * sum_m (size >> m)^2.
[[nodiscard]] uint64_t probeTexelCount(uint32_t faceSize);

}  // namespace onelight::world

namespace onelight::package {

/// RGB9E5 (EXT_texture_shared_exponent, "Encoding": 9-bit mantissas, 5-bit exponent, bias
/// 15): channels clamped to [0, 65408], NaN to 0. Each channel's error is at most half a step,
/// max(r, g, b) / 512 (plus 2^-25 where the largest channel is below 2^-15).
[[nodiscard]] uint32_t encodeRgb9e5(glm::vec3 rgb);
[[nodiscard]] glm::vec3 decodeRgb9e5(uint32_t packed);

/// Section 35 for serializePackage.
[[nodiscard]] RawSection encodeProbeSection(const std::vector<world::EnvironmentProbe>& probes);

/// The probes a package holds, if any.
struct ProbeContents {
    std::vector<world::EnvironmentProbe> probes;
    bool present = false;  // the package holds section 35
};

/// Decodes section 35 from the raw sections a package reader kept (absent: no probes). `name`
/// prefixes error messages (usually the file path). Throws world::Error.
[[nodiscard]] ProbeContents decodeProbeSection(std::span<const RawSection> sections,
                                               const world::CompiledLevel& level,
                                               const std::string& name);

}  // namespace onelight::package
