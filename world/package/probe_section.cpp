#include "world/package/probe_section.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "world/error.hpp"
#include "world/package/format.hpp"
#include "world/package/records.hpp"

namespace onelight::world {

uint64_t probe_texel_count(uint32_t face_size) {
    uint64_t count = 0;
    for (uint64_t size = face_size; size > 0; size /= 2) count += 6 * size * size;
    return count;
}

}  // namespace onelight::world

namespace onelight::package {
namespace {

constexpr int kMantissaBits = 9;
constexpr int kExponentBias = 15;
constexpr int kMaxExponent = 31;
// (2^N - 1) / 2^N * 2^(Emax - B): the largest value RGB9E5 holds.
constexpr float kSharedExpMax = 511.0f / 512.0f * 65536.0f;
constexpr uint32_t kMaxFaceSize = 4096;

// Into bytes already sized (inserting small records one by one trips GCC 12's
// -Wstringop-overflow false positive).
template <class T>
void write_record(std::vector<uint8_t>& out, size_t& offset, const T& value) {
    std::memcpy(out.data() + offset, &value, sizeof(T));
    offset += sizeof(T);
}

template <class T>
T read_record(const std::vector<uint8_t>& bytes, size_t offset) {
    T value;
    std::memcpy(&value, bytes.data() + offset, sizeof(T));
    return value;
}

float clamp_channel(float c) {
    // NaN fails both comparisons and becomes 0, as the extension asks.
    return c > 0.0f ? std::min(c, kSharedExpMax) : 0.0f;
}

/// Throws unless every element of the array field `name` is finite; `at` names the record.
template <size_t N>
void check_finite(const std::string& at, const char* name, const float (&v)[N]) {
    for (size_t k = 0; k < N; ++k)
        if (!std::isfinite(v[k]))
            throw world::Error(at + name + "[" + std::to_string(k) + "] = " + std::to_string(v[k]) +
                               ": not finite");
}

/// Throws unless a probe record's texels start at `next_texel` of the section's `texel_count` and
/// every field is in range; `at` names the record.
void check(const DiskProbe& d, uint64_t next_texel, uint32_t texel_count,
           const world::CompiledLevel& level, const std::string& at) {
    check_finite(at, "position", d.position);
    check_finite(at, "box_min", d.box_min);
    check_finite(at, "box_max", d.box_max);
    const float* e = d.irradiance_average;
    if (!(std::isfinite(e[0]) && std::isfinite(e[1]) && std::isfinite(e[2])) ||
        !(std::min({e[0], e[1], e[2]}) > 0.0f))
        throw world::Error(at + "irradiance_average not finite or not > 0");
    const bool power_of_two = d.face_size != 0 && (d.face_size & (d.face_size - 1)) == 0;
    if (!power_of_two || d.face_size > kMaxFaceSize)
        throw world::Error(at + "face_size " + std::to_string(d.face_size) +
                           " is not a power of two <= " + std::to_string(kMaxFaceSize));
    uint32_t mips = 0;
    for (uint32_t s = d.face_size; s > 0; s /= 2) ++mips;
    if (d.mip_count != mips)
        throw world::Error(at + "mip_count " + std::to_string(d.mip_count) + "; expected " +
                           std::to_string(mips) + " for face_size " + std::to_string(d.face_size));
    if (d.texel_count != world::probe_texel_count(d.face_size))
        throw world::Error(at + "texel_count " + std::to_string(d.texel_count) + "; expected " +
                           std::to_string(world::probe_texel_count(d.face_size)) +
                           " for face_size " + std::to_string(d.face_size));
    if (d.first_texel != next_texel || uint64_t(d.first_texel) + d.texel_count > texel_count)
        throw world::Error(at + "texels [" + std::to_string(d.first_texel) + ", +" +
                           std::to_string(d.texel_count) + ") not at " +
                           std::to_string(next_texel) + " or past texel_count " +
                           std::to_string(texel_count));
    if (d.entity != kNoIndex && (d.entity >= level.entities.size() ||
                                 !(level.entities[d.entity].flags & world::entity_probe)))
        throw world::Error(at + "entity " + std::to_string(d.entity) +
                           " is not a probe entity of " + std::to_string(level.entities.size()));
    if (d.reserved != 0)
        throw world::Error(at + "reserved " + std::to_string(d.reserved) + "; expected 0");
}

}  // namespace

uint32_t encode_rgb9e5(glm::vec3 rgb) {
    const float r = clamp_channel(rgb.r), g = clamp_channel(rgb.g), b = clamp_channel(rgb.b);
    const float max_c = std::max(r, std::max(g, b));
    // floor(log2(max_c)) exactly: frexp gives max_c = m 2^e with m in [0.5, 1).
    int e = 0;
    std::frexp(max_c, &e);
    const int floor_log2 = max_c > 0.0f ? e - 1 : -kExponentBias - 1;
    int exp_shared = std::max(-kExponentBias - 1, floor_log2) + 1 + kExponentBias;
    // The mantissa of max_c may round up to 2^N: take the next exponent then.
    if (std::floor(std::ldexp(max_c, kExponentBias + kMantissaBits - exp_shared) + 0.5f) ==
        float(1 << kMantissaBits))
        ++exp_shared;
    exp_shared = std::min(exp_shared, kMaxExponent);
    const auto mantissa = [&](float c) {
        const float s =
            std::floor(std::ldexp(c, kExponentBias + kMantissaBits - exp_shared) + 0.5f);
        return std::min(uint32_t(s), (1u << kMantissaBits) - 1u);
    };
    return mantissa(r) | (mantissa(g) << 9) | (mantissa(b) << 18) | (uint32_t(exp_shared) << 27);
}

glm::vec3 decode_rgb9e5(uint32_t packed) {
    const int exponent = int(packed >> 27) - kExponentBias - kMantissaBits;
    return glm::vec3(std::ldexp(float(packed & 511u), exponent),
                     std::ldexp(float((packed >> 9) & 511u), exponent),
                     std::ldexp(float((packed >> 18) & 511u), exponent));
}

RawSection encode_probe_section(const std::vector<world::EnvironmentProbe>& probes) {
    RawSection out;
    out.id = section_probes;
    out.element_size = 1;
    DiskProbeHeader h{};
    h.probe_count = static_cast<uint32_t>(probes.size());
    uint64_t texels = 0;
    for (const world::EnvironmentProbe& p : probes) texels += p.texels.size();
    h.texel_count = static_cast<uint32_t>(texels);
    h.texel_format = probe_texel_rgb9e5;
    out.bytes.resize(sizeof(DiskProbeHeader) + probes.size() * sizeof(DiskProbe) +
                     texels * sizeof(uint32_t));
    size_t offset = 0;
    write_record(out.bytes, offset, h);
    uint32_t first = 0;
    for (const world::EnvironmentProbe& p : probes) {
        const DiskProbe d = to_disk(p, first);
        first += d.texel_count;
        write_record(out.bytes, offset, d);
    }
    for (const world::EnvironmentProbe& p : probes)
        for (uint32_t t : p.texels) write_record(out.bytes, offset, t);
    out.count = static_cast<uint32_t>(out.bytes.size());
    return out;
}

ProbeContents decode_probe_section(std::span<const RawSection> sections,
                                   const world::CompiledLevel& level, const std::string& name) {
    ProbeContents result;
    const RawSection* section = nullptr;
    for (const RawSection& s : sections) {
        if (s.id != section_probes) continue;
        if (section) {
            throw world::Error(name + ": section " + std::to_string(s.id) + " appears twice");
        }
        section = &s;
    }
    if (!section) return result;
    result.present = true;
    const std::vector<uint8_t>& bytes = section->bytes;
    if (section->element_size != 1 || bytes.size() != section->count ||
        bytes.size() < sizeof(DiskProbeHeader)) {
        throw world::Error(name + ": section probes: element size " +
                           std::to_string(section->element_size) + ", count " +
                           std::to_string(section->count) + ", " + std::to_string(bytes.size()) +
                           " bytes; expected element size 1, count == bytes, and a header of " +
                           std::to_string(sizeof(DiskProbeHeader)) + " bytes");
    }
    const auto h = read_record<DiskProbeHeader>(bytes, 0);
    const uint64_t expected_bytes = sizeof(DiskProbeHeader) +
                                    uint64_t(h.probe_count) * sizeof(DiskProbe) +
                                    uint64_t(h.texel_count) * sizeof(uint32_t);
    if (bytes.size() != expected_bytes) {
        throw world::Error(name + ": section probes: probe_count " + std::to_string(h.probe_count) +
                           ", texel_count " + std::to_string(h.texel_count) + ", " +
                           std::to_string(bytes.size()) + " bytes; expected " +
                           std::to_string(expected_bytes) + " bytes");
    }
    if (h.texel_format != probe_texel_rgb9e5 || h.reserved != 0) {
        throw world::Error(name + ": section probes: texel_format " +
                           std::to_string(h.texel_format) + ", reserved " +
                           std::to_string(h.reserved) + "; expected " +
                           std::to_string(probe_texel_rgb9e5) + " (RGB9E5) and 0");
    }
    const size_t texel_base = sizeof(DiskProbeHeader) + size_t(h.probe_count) * sizeof(DiskProbe);
    uint64_t next_texel = 0;
    result.probes.resize(h.probe_count);
    for (uint32_t i = 0; i < h.probe_count; ++i) {
        const auto d =
            read_record<DiskProbe>(bytes, sizeof(DiskProbeHeader) + size_t(i) * sizeof(DiskProbe));
        check(d, next_texel, h.texel_count, level,
              name + ": section probes, record " + std::to_string(i) + ": ");
        result.probes[i] = from_disk(d, std::span(bytes).subspan(texel_base));
        next_texel += d.texel_count;
    }
    if (next_texel != h.texel_count) {
        throw world::Error(name + ": section probes: texel_count " + std::to_string(h.texel_count) +
                           "; the probes own " + std::to_string(next_texel));
    }
    return result;
}

}  // namespace onelight::package
