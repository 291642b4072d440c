#include "world/package/texture_section.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include <glm/gtc/packing.hpp>

#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/images/image_budget.hpp"
#include "world/images/image_decode.hpp"
#include "world/package/format.hpp"
#include "world/package/records.hpp"

namespace onelight::package {
namespace {

using world::TexelFormat;

uint64_t alignUp(uint64_t bytes) {
    return (bytes + kProcessedTexelAlignment - 1) / kProcessedTexelAlignment *
           kProcessedTexelAlignment;
}

template <class T>
void writeRecord(std::vector<uint8_t>& out, uint64_t offset, const T& value) {
    std::memcpy(out.data() + offset, &value, sizeof(T));
}

template <class T>
T readRecord(const std::vector<uint8_t>& bytes, uint64_t offset) {
    T value;
    std::memcpy(&value, bytes.data() + offset, sizeof(T));
    return value;
}

const char* formatName(TexelFormat format) {
    switch (format) {
        case TexelFormat::kRgba8Srgb:
            return "RGBA8 sRGB";
        case TexelFormat::kRgba8Unorm:
            return "RGBA8 UNORM";
        case TexelFormat::kR8Unorm:
            return "R8 UNORM";
        case TexelFormat::kR16Float:
            return "R16 float";
    }
    return "unknown";
}

bool isFilter(uint16_t filter) {
    return filter == 0 || filter == 9728 || filter == 9729 || (filter >= 9984 && filter <= 9987);
}

bool isWrap(uint16_t wrap) {
    return wrap == 10497 || wrap == 33071 || wrap == 33648;
}

/// Where records, names and texels lie in a section of the given counts (64-bit: no count of
/// 32 bits overflows it).
struct SectionLayout {
    uint64_t texturesOffset = 0;
    uint64_t materialsOffset = 0;
    uint64_t namesOffset = 0;
    uint64_t recordsEnd = 0;  // the end of the names
    uint64_t texelBase = 0;   // recordsEnd rounded up to kProcessedTexelAlignment
};

SectionLayout layoutOf(uint32_t textureCount, uint32_t materialCount, uint32_t nameBytes) {
    SectionLayout l;
    l.texturesOffset = sizeof(DiskProcessedTexturesHeader);
    l.materialsOffset = l.texturesOffset + uint64_t(textureCount) * sizeof(DiskProcessedTexture);
    l.namesOffset = l.materialsOffset + uint64_t(materialCount) * sizeof(DiskMaterialTextureSlots);
    l.recordsEnd = l.namesOffset + nameBytes;
    l.texelBase = alignUp(l.recordsEnd);
    return l;
}

/// Whether bytes [first, end) of `bytes` are all zero.
bool allZero(const std::vector<uint8_t>& bytes, uint64_t first, uint64_t end) {
    for (uint64_t i = first; i < end; ++i)
        if (bytes[i] != 0) return false;
    return true;
}

template <size_t N>
void checkReserved(const std::string& at, const uint8_t (&reserved)[N]) {
    for (size_t k = 0; k < N; ++k)
        if (reserved[k] != 0)
            throw world::Error(at + "reserved[" + std::to_string(k) + "] " +
                               std::to_string(reserved[k]) + "; expected 0");
}

/// Throws unless texture record `d` (at `at`) is a known format, a size in range, a full mip
/// chain whose bytes are its chain's, stored at `nextByte` inside the section's `sectionBytes`,
/// after the records that end at `texelBase`, with a glTF sampler and a name at `nextName` of
/// the section's `nameBytes`.
void check(const DiskProcessedTexture& d, uint64_t nextName, uint32_t nameBytes, uint64_t texelBase,
           uint64_t nextByte, uint64_t sectionBytes, const std::string& at) {
    if (d.nameLength > kMaxProcessedTextureNameBytes)
        throw world::Error(at + "nameLength " + std::to_string(d.nameLength) +
                           "; expected at most " + std::to_string(kMaxProcessedTextureNameBytes));
    if (d.nameOffset != nextName)
        throw world::Error(at + "nameOffset " + std::to_string(d.nameOffset) + "; expected " +
                           std::to_string(nextName) + " (names in order, without gaps)");
    if (uint64_t(d.nameOffset) + d.nameLength > nameBytes)
        throw world::Error(at + "name [" + std::to_string(d.nameOffset) + ", +" +
                           std::to_string(d.nameLength) + ") is outside the section's " +
                           std::to_string(nameBytes) + " name bytes");
    if (d.format > uint8_t(TexelFormat::kR16Float))
        throw world::Error(at + "format " + std::to_string(d.format) +
                           "; expected 0 (RGBA8 sRGB), 1 (RGBA8 UNORM), 2 (R8 UNORM) or 3 (R16 "
                           "float)");
    checkReserved(at, d.reserved);
    const std::string extents = "; expected 1.." + std::to_string(world::kMaxImageExtent);
    if (d.width == 0 || d.width > world::kMaxImageExtent)
        throw world::Error(at + "width " + std::to_string(d.width) + extents);
    if (d.height == 0 || d.height > world::kMaxImageExtent)
        throw world::Error(at + "height " + std::to_string(d.height) + extents);
    const std::string size = std::to_string(d.width) + "x" + std::to_string(d.height);
    const uint32_t mips = world::fullMipCount(d.width, d.height);
    if (d.mipCount != mips)
        throw world::Error(at + "mipCount " + std::to_string(d.mipCount) + "; expected " +
                           std::to_string(mips) + " for " + size + " (down to 1x1)");
    const char* filters = "; expected 0 (unset), 9728, 9729 or 9984..9987";
    if (!isFilter(d.magFilter))
        throw world::Error(at + "magFilter " + std::to_string(d.magFilter) + filters);
    if (!isFilter(d.minFilter))
        throw world::Error(at + "minFilter " + std::to_string(d.minFilter) + filters);
    const char* wraps = "; expected 10497 (repeat), 33071 (clamp) or 33648 (mirrored)";
    if (!isWrap(d.wrapS)) throw world::Error(at + "wrapS " + std::to_string(d.wrapS) + wraps);
    if (!isWrap(d.wrapT)) throw world::Error(at + "wrapT " + std::to_string(d.wrapT) + wraps);
    const auto format = static_cast<TexelFormat>(d.format);
    const uint64_t chainBytes = world::mipChainBytes(format, d.width, d.height, d.mipCount);
    if (d.byteCount != chainBytes)
        throw world::Error(at + "byteCount " + std::to_string(d.byteCount) + "; expected " +
                           std::to_string(chainBytes) + " for a " + size + " " +
                           formatName(format) + " chain of " + std::to_string(mips) + " mips");
    if (d.firstByte < texelBase)
        throw world::Error(at + "firstByte " + std::to_string(d.firstByte) +
                           " overlaps the section's records and names (texels start at byte " +
                           std::to_string(texelBase) + ")");
    if (d.firstByte != nextByte)
        throw world::Error(at + "firstByte " + std::to_string(d.firstByte) + "; expected " +
                           std::to_string(nextByte) + " (chains in order, each at the next " +
                           "multiple of " + std::to_string(kProcessedTexelAlignment) + ")");
    if (d.firstByte > sectionBytes || d.byteCount > sectionBytes - d.firstByte)
        throw world::Error(at + "texels [" + std::to_string(d.firstByte) + ", +" +
                           std::to_string(d.byteCount) + ") run past the end of the section (" +
                           std::to_string(sectionBytes) + " bytes)");
}

/// Throws unless every texel of an R16 float chain is finite and >= 0 (a facet table's
/// densities): an infinity or a NaN would reach the pixels that read it.
void checkHalfTexels(const world::ProcessedTexture& t, const std::string& at) {
    for (size_t i = 0; i + 1 < t.texels.size(); i += 2) {
        const uint16_t half = uint16_t(t.texels[i] | (t.texels[i + 1] << 8));
        const float value = glm::unpackHalf1x16(half);
        if (!std::isfinite(value) || value < 0.0f)
            throw world::Error(at + "texel " + std::to_string(i / 2) + " of its chain is " +
                               (std::isfinite(value) ? "negative" : "not finite") +
                               " (R16 float bits " + std::to_string(half) +
                               "); expected a finite value >= 0");
    }
}

/// The format each of a material's slots needs, in DiskMaterialTextureSlots' order.
struct SlotRule {
    const char* name;
    uint32_t DiskMaterialTextureSlots::*disk;
    TexelFormat format;
};
constexpr SlotRule kSlotRules[] = {
    {"baseColor", &DiskMaterialTextureSlots::baseColor, TexelFormat::kRgba8Srgb},
    {"metallicRoughness", &DiskMaterialTextureSlots::metallicRoughness, TexelFormat::kRgba8Unorm},
    {"normal", &DiskMaterialTextureSlots::normal, TexelFormat::kRgba8Unorm},
    {"occlusion", &DiskMaterialTextureSlots::occlusion, TexelFormat::kRgba8Unorm},
    {"emissive", &DiskMaterialTextureSlots::emissive, TexelFormat::kRgba8Srgb},
    {"cavity", &DiskMaterialTextureSlots::cavity, TexelFormat::kR8Unorm},
    {"facets", &DiskMaterialTextureSlots::facets, TexelFormat::kR16Float},
};

/// Throws unless every slot of `d` (at `at`) is none or a texture of `textures` in the format
/// the slot needs, and the flags and reserved bytes are valid.
void check(const DiskMaterialTextureSlots& d, const std::vector<world::ProcessedTexture>& textures,
           const std::string& at) {
    for (const SlotRule& rule : kSlotRules) {
        const uint32_t index = d.*rule.disk;
        if (index == kNoIndex) continue;
        if (index >= textures.size())
            throw world::Error(at + rule.name + " " + std::to_string(index) +
                               "; expected a texture index < " + std::to_string(textures.size()) +
                               " or none (" + std::to_string(kNoIndex) + ")");
        const world::ProcessedTexture& t = textures[index];
        if (t.format != rule.format)
            throw world::Error(at + rule.name + " is texture " + std::to_string(index) + " '" +
                               world::clipForMessage(t.name, 60) + "' of format " +
                               formatName(t.format) + "; expected " + formatName(rule.format));
    }
    if (d.factorsFolded > 1)
        throw world::Error(at + "factorsFolded " + std::to_string(d.factorsFolded) +
                           "; expected 0 or 1");
    if (d.baseRoughnessInAlpha > 1)
        throw world::Error(at + "baseRoughnessInAlpha " + std::to_string(d.baseRoughnessInAlpha) +
                           "; expected 0 or 1");
    if (d.baseRoughnessInAlpha == 1 && d.metallicRoughness == kNoIndex)
        throw world::Error(at +
                           "baseRoughnessInAlpha 1 without a metallicRoughness texture; "
                           "expected 0");
    if (d.slopeKurtosisInNormalAlpha > 1)
        throw world::Error(at + "slopeKurtosisInNormalAlpha " +
                           std::to_string(d.slopeKurtosisInNormalAlpha) + "; expected 0 or 1");
    if (d.slopeKurtosisInNormalAlpha == 1 && d.normal == kNoIndex)
        throw world::Error(at +
                           "slopeKurtosisInNormalAlpha 1 without a normal texture; expected 0");
    checkReserved(at, d.reserved);
}

}  // namespace

RawSection encodeTextureSection(const world::ProcessedTextures& textures) {
    DiskProcessedTexturesHeader h{};
    h.textureCount = static_cast<uint32_t>(textures.textures.size());
    h.materialCount = static_cast<uint32_t>(textures.materials.size());
    uint64_t nameBytes = 0;
    for (const world::ProcessedTexture& t : textures.textures) nameBytes += t.name.size();
    h.nameBytes = static_cast<uint32_t>(nameBytes);
    h.method = static_cast<uint8_t>(textures.method);
    const SectionLayout layout = layoutOf(h.textureCount, h.materialCount, h.nameBytes);
    uint64_t texelBytes = 0;
    for (const world::ProcessedTexture& t : textures.textures)
        texelBytes += alignUp(t.texels.size());
    h.texelBytes = texelBytes;

    RawSection out;
    out.id = kSectionProcessedTextures;
    out.elementSize = 1;
    out.bytes.resize(layout.texelBase + texelBytes);  // zero: the padding stays zero
    writeRecord(out.bytes, 0, h);
    uint64_t nextName = 0, nextByte = layout.texelBase;
    for (size_t i = 0; i < textures.textures.size(); ++i) {
        const world::ProcessedTexture& t = textures.textures[i];
        writeRecord(out.bytes, layout.texturesOffset + i * sizeof(DiskProcessedTexture),
                    toDisk(t, static_cast<uint32_t>(nextName), nextByte));
        if (!t.name.empty())
            std::memcpy(out.bytes.data() + layout.namesOffset + nextName, t.name.data(),
                        t.name.size());
        if (!t.texels.empty())
            std::memcpy(out.bytes.data() + nextByte, t.texels.data(), t.texels.size());
        nextName += t.name.size();
        nextByte += alignUp(t.texels.size());
    }
    for (size_t m = 0; m < textures.materials.size(); ++m) {
        writeRecord(out.bytes, layout.materialsOffset + m * sizeof(DiskMaterialTextureSlots),
                    toDisk(textures.materials[m]));
    }
    out.count = static_cast<uint32_t>(out.bytes.size());
    return out;
}

TextureContents decodeTextureSection(std::span<const RawSection> sections,
                                     const world::CompiledLevel& level, const std::string& name) {
    const std::string at = name + ": section textures (38)";
    TextureContents result;
    const RawSection* section = nullptr;
    for (const RawSection& s : sections) {
        if (s.id != kSectionProcessedTextures) continue;
        if (section) throw world::Error(at + " appears twice; expected at most once");
        section = &s;
    }
    if (!section) return result;
    result.present = true;
    const std::vector<uint8_t>& bytes = section->bytes;
    const uint64_t size = bytes.size();
    if (section->elementSize != 1 || size != section->count ||
        size < sizeof(DiskProcessedTexturesHeader))
        throw world::Error(at + ": element size " + std::to_string(section->elementSize) +
                           ", count " + std::to_string(section->count) + ", " +
                           std::to_string(size) +
                           " bytes; expected element size 1, count == bytes, and a header of " +
                           std::to_string(sizeof(DiskProcessedTexturesHeader)) + " bytes");

    // The header: counts against the section's size before anything is read or allocated.
    const auto h = readRecord<DiskProcessedTexturesHeader>(bytes, 0);
    const std::string atHeader = at + ", header: ";
    const SectionLayout layout = layoutOf(h.textureCount, h.materialCount, h.nameBytes);
    if (layout.texelBase > size)
        throw world::Error(atHeader + "textureCount " + std::to_string(h.textureCount) +
                           ", materialCount " + std::to_string(h.materialCount) + ", nameBytes " +
                           std::to_string(h.nameBytes) + " need " +
                           std::to_string(layout.texelBase) + " bytes; the section has " +
                           std::to_string(size));
    if (h.texelBytes != size - layout.texelBase)
        throw world::Error(atHeader + "texelBytes " + std::to_string(h.texelBytes) + "; expected " +
                           std::to_string(size - layout.texelBase) +
                           " (the section's bytes after its records and names)");
    if (h.texelBytes > world::kMaxDecodedImageBytes)
        throw world::Error(atHeader + "texelBytes " + std::to_string(h.texelBytes) +
                           "; expected at most " + std::to_string(world::kMaxDecodedImageBytes));
    if (h.method > uint8_t(world::GlossMipMethod::kClean))
        throw world::Error(atHeader + "method " + std::to_string(h.method) +
                           "; expected 0 (blit), 1 (Black Ops), 2 (WWII) or 3 (CLEAN)");
    checkReserved(atHeader, h.reserved);
    if (h.materialCount != level.materials.size())
        throw world::Error(atHeader + "materialCount " + std::to_string(h.materialCount) +
                           "; expected " + std::to_string(level.materials.size()) +
                           " (the level's materials)");
    if (!allZero(bytes, layout.recordsEnd, layout.texelBase))
        throw world::Error(atHeader + "the padding after the names is not zero");

    world::ProcessedTextures& out = result.textures;
    out.method = static_cast<world::GlossMipMethod>(h.method);
    out.textures.resize(h.textureCount);
    const std::span<const uint8_t> names(bytes.data() + layout.namesOffset, h.nameBytes);
    uint64_t nextName = 0, nextByte = layout.texelBase;
    for (uint32_t i = 0; i < h.textureCount; ++i) {
        const std::string atTexture = at + ", texture " + std::to_string(i) + ": ";
        const auto d = readRecord<DiskProcessedTexture>(
            bytes, layout.texturesOffset + uint64_t(i) * sizeof(DiskProcessedTexture));
        check(d, nextName, h.nameBytes, layout.texelBase, nextByte, size, atTexture);
        const uint64_t end = d.firstByte + d.byteCount;
        const uint64_t padded = alignUp(end);
        if (!allZero(bytes, end, padded < size ? padded : size))
            throw world::Error(atTexture + "the padding after its texels is not zero");
        out.textures[i] = fromDisk(d, names, bytes);
        if (out.textures[i].format == TexelFormat::kR16Float)
            checkHalfTexels(out.textures[i], atTexture);
        nextName += d.nameLength;
        nextByte = padded;
    }
    if (nextName != h.nameBytes)
        throw world::Error(atHeader + "nameBytes " + std::to_string(h.nameBytes) + "; expected " +
                           std::to_string(nextName) + " (the textures' name lengths)");
    if (nextByte != size)
        throw world::Error(atHeader + "texelBytes " + std::to_string(h.texelBytes) + "; expected " +
                           std::to_string(nextByte - layout.texelBase) +
                           " (the textures' chains, each padded to a multiple of " +
                           std::to_string(kProcessedTexelAlignment) + ")");

    out.materials.resize(h.materialCount);
    for (uint32_t m = 0; m < h.materialCount; ++m) {
        const auto d = readRecord<DiskMaterialTextureSlots>(
            bytes, layout.materialsOffset + uint64_t(m) * sizeof(DiskMaterialTextureSlots));
        check(d, out.textures, at + ", material " + std::to_string(m) + ": ");
        out.materials[m] = fromDisk(d);
    }
    return result;
}

}  // namespace onelight::package
