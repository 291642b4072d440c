// Writer and reader of the environment probes' section (35; layout in format.hpp), and the
// RGB9E5 shared-exponent texel encoding it stores. The reader checks every size, count, index
// and value range and names the section, the record and the bad value.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::world {

/// One baked environment probe in memory (DiskProbe's twin): its prefiltered, normalised
/// radiance as RGB9E5 texels, mips from the largest, each 6 faces of rows from the top.
struct EnvironmentProbe {
    glm::vec3 position{0.0f};                // metres, world: the capture point
    glm::vec3 box_min{0.0f}, box_max{0.0f};  // box projection when min < max on every axis
    glm::vec3 irradiance_average{1.0f};      // lux, RGB: E_avg (probeNormalize)
    uint32_t face_size = 0, mip_count = 0;   // mip 0 edge (a power of two); down to 1x1
    uint32_t entity = kNone;                 // the probe entity, kNone when placed
    std::vector<uint32_t> texels;            // RGB9E5, 6 * sum_m (face_size >> m)^2
};

/// Texels of a cube of edge `face_size` with every mip down to 1x1: 6 * sum_m (size >> m)^2.
uint64_t probe_texel_count(uint32_t face_size);

}  // namespace onelight::world

namespace onelight::package {

/// RGB9E5 (EXT_texture_shared_exponent, "Encoding": 9-bit mantissas, 5-bit exponent, bias
/// 15): channels clamped to [0, 65408], NaN to 0. Each channel's error is at most half a step,
/// max(r, g, b) / 512 (plus 2^-25 where the largest channel is below 2^-15).
uint32_t encode_rgb9e5(glm::vec3 rgb);
glm::vec3 decode_rgb9e5(uint32_t packed);

/// Section 35 for serialize_package.
RawSection encode_probe_section(const std::vector<world::EnvironmentProbe>& probes);

struct ProbeReadResult {
    std::vector<world::EnvironmentProbe> probes;
    bool present = false;  // the package holds section 35
    std::string error;     // empty on success
    bool ok() const { return error.empty(); }
};

/// Decodes section 35 from the raw sections a package reader kept (absent: no probes, ok).
/// `name` prefixes error messages (usually the file path).
ProbeReadResult decode_probe_section(std::span<const RawSection> sections,
                                     const world::CompiledLevel& level, const std::string& name);

}  // namespace onelight::package
