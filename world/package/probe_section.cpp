#include "world/package/probe_section.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "world/error.hpp"
#include "world/package/format.hpp"
#include "world/package/records.hpp"

namespace onelight::world {

uint64_t probeTexelCount(uint32_t faceSize) {
    uint64_t count = 0;
    for (uint64_t size = faceSize; size > 0; size /= 2) count += 6 * size * size;
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
void writeRecord(std::vector<uint8_t>& out, size_t& offset, const T& value) {
    std::memcpy(out.data() + offset, &value, sizeof(T));
    offset += sizeof(T);
}

template <class T>
T readRecord(const std::vector<uint8_t>& bytes, size_t offset) {
    T value;
    std::memcpy(&value, bytes.data() + offset, sizeof(T));
    return value;
}

float clampChannel(float c) {
    // NaN fails both comparisons and becomes 0, as the extension asks.
    return c > 0.0f ? std::min(c, kSharedExpMax) : 0.0f;
}

/// Throws unless every element of the array field `name` is finite; `at` names the record.
template <size_t N>
void checkFinite(const std::string& at, const char* name, const float (&v)[N]) {
    for (size_t k = 0; k < N; ++k)
        if (!std::isfinite(v[k]))
            throw world::Error(at + name + "[" + std::to_string(k) + "] = " + std::to_string(v[k]) +
                               ": not finite");
}

/// Throws unless a probe record's texels start at `nextTexel` of the section's `texelCount` and
/// every field is in range; `at` names the record.
void check(const DiskProbe& d, uint64_t nextTexel, uint32_t texelCount,
           const world::CompiledLevel& level, const std::string& at) {
    checkFinite(at, "position", d.position);
    checkFinite(at, "boxMin", d.boxMin);
    checkFinite(at, "boxMax", d.boxMax);
    const float* e = d.irradianceAverage;
    if (!(std::isfinite(e[0]) && std::isfinite(e[1]) && std::isfinite(e[2])) ||
        !(std::min({e[0], e[1], e[2]}) > 0.0f))
        throw world::Error(at + "irradianceAverage not finite or not > 0");
    for (int f = 0; f < 6; ++f)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(d.irradianceCube[f][c]) || d.irradianceCube[f][c] < 0.0f)
                throw world::Error(
                    at + "irradianceCube[" + std::to_string(f) + "][" + std::to_string(c) +
                    "] = " + std::to_string(d.irradianceCube[f][c]) + ": not finite or negative");
    const bool powerOfTwo = d.faceSize != 0 && (d.faceSize & (d.faceSize - 1)) == 0;
    if (!powerOfTwo || d.faceSize > kMaxFaceSize)
        throw world::Error(at + "faceSize " + std::to_string(d.faceSize) +
                           " is not a power of two <= " + std::to_string(kMaxFaceSize));
    uint32_t mips = 0;
    for (uint32_t s = d.faceSize; s > 0; s /= 2) ++mips;
    if (d.mipCount != mips)
        throw world::Error(at + "mipCount " + std::to_string(d.mipCount) + "; expected " +
                           std::to_string(mips) + " for faceSize " + std::to_string(d.faceSize));
    if (d.texelCount != world::probeTexelCount(d.faceSize))
        throw world::Error(at + "texelCount " + std::to_string(d.texelCount) + "; expected " +
                           std::to_string(world::probeTexelCount(d.faceSize)) + " for faceSize " +
                           std::to_string(d.faceSize));
    if (d.firstTexel != nextTexel || uint64_t(d.firstTexel) + d.texelCount > texelCount)
        throw world::Error(at + "texels [" + std::to_string(d.firstTexel) + ", +" +
                           std::to_string(d.texelCount) + ") not at " + std::to_string(nextTexel) +
                           " or past texelCount " + std::to_string(texelCount));
    if (d.entity != kNoIndex && (d.entity >= level.entities.size() ||
                                 !(level.entities[d.entity].flags & world::kEntityProbe)))
        throw world::Error(at + "entity " + std::to_string(d.entity) +
                           " is not a probe entity of " + std::to_string(level.entities.size()));
    if (d.reserved != 0)
        throw world::Error(at + "reserved " + std::to_string(d.reserved) + "; expected 0");
}

}  // namespace

uint32_t encodeRgb9e5(glm::vec3 rgb) {
    const float r = clampChannel(rgb.r), g = clampChannel(rgb.g), b = clampChannel(rgb.b);
    const float maxC = std::max(r, std::max(g, b));
    // floor(log2(maxC)) exactly: frexp gives maxC = m 2^e with m in [0.5, 1).
    int e = 0;
    std::frexp(maxC, &e);
    const int floorLog2 = maxC > 0.0f ? e - 1 : -kExponentBias - 1;
    int expShared = std::max(-kExponentBias - 1, floorLog2) + 1 + kExponentBias;
    // The mantissa of maxC may round up to 2^N: take the next exponent then.
    if (std::floor(std::ldexp(maxC, kExponentBias + kMantissaBits - expShared) + 0.5f) ==
        float(1 << kMantissaBits))
        ++expShared;
    expShared = std::min(expShared, kMaxExponent);
    const auto mantissa = [&](float c) {
        const float s = std::floor(std::ldexp(c, kExponentBias + kMantissaBits - expShared) + 0.5f);
        return std::min(uint32_t(s), (1u << kMantissaBits) - 1u);
    };
    return mantissa(r) | (mantissa(g) << 9) | (mantissa(b) << 18) | (uint32_t(expShared) << 27);
}

glm::vec3 decodeRgb9e5(uint32_t packed) {
    const int exponent = int(packed >> 27) - kExponentBias - kMantissaBits;
    return glm::vec3(std::ldexp(float(packed & 511u), exponent),
                     std::ldexp(float((packed >> 9) & 511u), exponent),
                     std::ldexp(float((packed >> 18) & 511u), exponent));
}

RawSection encodeProbeSection(const std::vector<world::EnvironmentProbe>& probes) {
    RawSection out;
    out.id = kSectionProbes;
    out.elementSize = 1;
    DiskProbeHeader h{};
    h.probeCount = static_cast<uint32_t>(probes.size());
    uint64_t texels = 0;
    for (const world::EnvironmentProbe& p : probes) texels += p.texels.size();
    h.texelCount = static_cast<uint32_t>(texels);
    h.texelFormat = kProbeTexelRgb9e5;
    out.bytes.resize(sizeof(DiskProbeHeader) + probes.size() * sizeof(DiskProbe) +
                     texels * sizeof(uint32_t));
    size_t offset = 0;
    writeRecord(out.bytes, offset, h);
    uint32_t first = 0;
    for (const world::EnvironmentProbe& p : probes) {
        const DiskProbe d = toDisk(p, first);
        first += d.texelCount;
        writeRecord(out.bytes, offset, d);
    }
    for (const world::EnvironmentProbe& p : probes)
        for (uint32_t t : p.texels) writeRecord(out.bytes, offset, t);
    out.count = static_cast<uint32_t>(out.bytes.size());
    return out;
}

ProbeContents decodeProbeSection(std::span<const RawSection> sections,
                                 const world::CompiledLevel& level, const std::string& name) {
    ProbeContents result;
    const RawSection* section = nullptr;
    for (const RawSection& s : sections) {
        if (s.id != kSectionProbes) continue;
        if (section) {
            throw world::Error(name + ": section " + std::to_string(s.id) + " appears twice");
        }
        section = &s;
    }
    if (!section) return result;
    result.present = true;
    const std::vector<uint8_t>& bytes = section->bytes;
    if (section->elementSize != 1 || bytes.size() != section->count ||
        bytes.size() < sizeof(DiskProbeHeader)) {
        throw world::Error(name + ": section probes: element size " +
                           std::to_string(section->elementSize) + ", count " +
                           std::to_string(section->count) + ", " + std::to_string(bytes.size()) +
                           " bytes; expected element size 1, count == bytes, and a header of " +
                           std::to_string(sizeof(DiskProbeHeader)) + " bytes");
    }
    const auto h = readRecord<DiskProbeHeader>(bytes, 0);
    const uint64_t expectedBytes = sizeof(DiskProbeHeader) +
                                   uint64_t(h.probeCount) * sizeof(DiskProbe) +
                                   uint64_t(h.texelCount) * sizeof(uint32_t);
    if (bytes.size() != expectedBytes) {
        throw world::Error(name + ": section probes: probeCount " + std::to_string(h.probeCount) +
                           ", texelCount " + std::to_string(h.texelCount) + ", " +
                           std::to_string(bytes.size()) + " bytes; expected " +
                           std::to_string(expectedBytes) + " bytes");
    }
    if (h.texelFormat != kProbeTexelRgb9e5 || h.reserved != 0) {
        throw world::Error(name + ": section probes: texelFormat " + std::to_string(h.texelFormat) +
                           ", reserved " + std::to_string(h.reserved) + "; expected " +
                           std::to_string(kProbeTexelRgb9e5) + " (RGB9E5) and 0");
    }
    const size_t texelBase = sizeof(DiskProbeHeader) + size_t(h.probeCount) * sizeof(DiskProbe);
    uint64_t nextTexel = 0;
    result.probes.resize(h.probeCount);
    for (uint32_t i = 0; i < h.probeCount; ++i) {
        const auto d =
            readRecord<DiskProbe>(bytes, sizeof(DiskProbeHeader) + size_t(i) * sizeof(DiskProbe));
        check(d, nextTexel, h.texelCount, level,
              name + ": section probes, record " + std::to_string(i) + ": ");
        result.probes[i] = fromDisk(d, std::span(bytes).subspan(texelBase));
        nextTexel += d.texelCount;
    }
    if (nextTexel != h.texelCount) {
        throw world::Error(name + ": section probes: texelCount " + std::to_string(h.texelCount) +
                           "; the probes own " + std::to_string(nextTexel));
    }
    return result;
}

}  // namespace onelight::package
