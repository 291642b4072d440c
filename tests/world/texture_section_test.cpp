// The processed textures' section (38, world/package/texture_section.hpp): a byte-exact round
// trip, on its own and through a whole package, and one hostile section per check, each
// refused with a one-line message naming the section, the record and the field.
#include <cstddef>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/error_message.hpp"
#include "world/package/format.hpp"
#include "world/package/package_reader.hpp"
#include "world/package/package_writer.hpp"
#include "world/package/texture_section.hpp"

namespace onelight::test {
namespace {

using namespace onelight::package;
using world::TexelFormat;

world::ProcessedTexture texture(const std::string& name, TexelFormat format, uint32_t width,
                                uint32_t height, uint8_t seed) {
    world::ProcessedTexture t;
    t.name = name;
    t.format = format;
    t.width = width;
    t.height = height;
    t.mipCount = world::fullMipCount(width, height);
    t.sampler.magFilter = 9729;
    t.sampler.minFilter = 9987;
    t.sampler.wrapS = 33071;
    t.sampler.wrapT = 33648;
    t.texels.resize(world::mipChainBytes(format, width, height, t.mipCount));
    for (size_t i = 0; i < t.texels.size(); ++i) t.texels[i] = uint8_t(i * 7 + seed);
    return t;
}

/// Three textures (a chain of 44 bytes, one of 340 and one of 18, so two need padding) read by
/// two materials; and the level they belong to.
world::ProcessedTextures sampleTextures() {
    world::ProcessedTextures p;
    p.method = world::GlossMipMethod::kBlackOps;
    p.textures.push_back(texture("stone base colour", TexelFormat::kRgba8Srgb, 4, 2, 1));
    p.textures.push_back(texture("stone normal", TexelFormat::kRgba8Unorm, 8, 8, 2));
    p.textures.push_back(texture("stone cavity", TexelFormat::kR8Unorm, 5, 3, 3));
    world::MaterialTextureSlots stone;
    stone.baseColor = 0;
    stone.normal = 1;
    stone.metallicRoughness = 1;  // a format test: any RGBA8 UNORM texture will do
    stone.cavity = 2;
    stone.factorsFolded = true;
    stone.baseRoughnessInAlpha = true;
    stone.slopeKurtosisInNormalAlpha = true;
    p.materials.push_back(stone);
    p.materials.push_back(world::MaterialTextureSlots{});
    return p;
}

world::CompiledLevel levelWithMaterials(size_t count) {
    world::CompiledLevel level;
    level.materials.resize(count);
    level.settings.texelsPerMetre = 16.0f;  // as a compiled level has it
    level.bspLeaves.resize(1);              // an empty level has one empty leaf
    return level;
}

constexpr uint64_t kHeader = sizeof(DiskProcessedTexturesHeader);

uint64_t textureField(uint32_t texture, size_t field) {
    return kHeader + uint64_t(texture) * sizeof(DiskProcessedTexture) + field;
}

uint64_t materialField(uint32_t material, size_t field) {
    return kHeader + 3 * sizeof(DiskProcessedTexture) +
           uint64_t(material) * sizeof(DiskMaterialTextureSlots) + field;
}

template <class T>
T read(const RawSection& s, uint64_t offset) {
    T value;
    std::memcpy(&value, s.bytes.data() + offset, sizeof(T));
    return value;
}

/// `s` with the field at byte `offset` set to `value`.
template <class T>
RawSection patched(RawSection s, uint64_t offset, T value) {
    std::memcpy(s.bytes.data() + offset, &value, sizeof(T));
    return s;
}

/// `s` with `bytes` bytes fewer (negative: more, zero) at its end and its count to match.
RawSection resized(RawSection s, int64_t bytes) {
    s.bytes.resize(size_t(int64_t(s.bytes.size()) - bytes));
    s.count = uint32_t(s.bytes.size());
    return s;
}

void expectRejected(const RawSection& s, const std::string& fragment,
                    const world::CompiledLevel& level = levelWithMaterials(2)) {
    const std::string error =
        errorMessage([&] { (void)decodeTextureSection(std::span(&s, 1), level, "test.olpak"); });
    ASSERT_NE(error, "") << "expected an error mentioning " << fragment;
    EXPECT_NE(error.find("test.olpak: section textures (38)"), std::string::npos) << error;
    EXPECT_NE(error.find(fragment), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

void expectSame(const world::ProcessedTextures& a, const world::ProcessedTextures& b) {
    EXPECT_EQ(a.method, b.method);
    ASSERT_EQ(a.textures.size(), b.textures.size());
    for (size_t i = 0; i < a.textures.size(); ++i) {
        const world::ProcessedTexture &x = a.textures[i], &y = b.textures[i];
        EXPECT_EQ(x.name, y.name) << i;
        EXPECT_EQ(x.format, y.format) << i;
        EXPECT_EQ(x.width, y.width) << i;
        EXPECT_EQ(x.height, y.height) << i;
        EXPECT_EQ(x.mipCount, y.mipCount) << i;
        EXPECT_EQ(x.sampler.magFilter, y.sampler.magFilter) << i;
        EXPECT_EQ(x.sampler.minFilter, y.sampler.minFilter) << i;
        EXPECT_EQ(x.sampler.wrapS, y.sampler.wrapS) << i;
        EXPECT_EQ(x.sampler.wrapT, y.sampler.wrapT) << i;
        EXPECT_EQ(x.texels, y.texels) << i;
    }
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (size_t m = 0; m < a.materials.size(); ++m) {
        const world::MaterialTextureSlots &x = a.materials[m], &y = b.materials[m];
        EXPECT_EQ(x.baseColor, y.baseColor) << m;
        EXPECT_EQ(x.metallicRoughness, y.metallicRoughness) << m;
        EXPECT_EQ(x.normal, y.normal) << m;
        EXPECT_EQ(x.occlusion, y.occlusion) << m;
        EXPECT_EQ(x.emissive, y.emissive) << m;
        EXPECT_EQ(x.cavity, y.cavity) << m;
        EXPECT_EQ(x.facets, y.facets) << m;
        EXPECT_EQ(x.factorsFolded, y.factorsFolded) << m;
        EXPECT_EQ(x.baseRoughnessInAlpha, y.baseRoughnessInAlpha) << m;
        EXPECT_EQ(x.slopeKurtosisInNormalAlpha, y.slopeKurtosisInNormalAlpha) << m;
    }
}

TEST(TextureSection, RoundTripIsByteExact) {
    const world::ProcessedTextures textures = sampleTextures();
    const RawSection section = encodeTextureSection(textures);
    EXPECT_EQ(section.id, kSectionProcessedTextures);
    EXPECT_EQ(section.elementSize, 1u);
    EXPECT_EQ(section.count, section.bytes.size());
    // Records 24 + 3 x 48 + 2 x 32 = 232, names 41 (to 273, padded to 280), then the chains
    // padded to 8: 44 -> 48, 340 -> 344, 18 -> 24.
    EXPECT_EQ(section.bytes.size(), 280u + 48 + 344 + 24);
    EXPECT_EQ(read<uint64_t>(section, textureField(0, offsetof(DiskProcessedTexture, firstByte))),
              280u);
    EXPECT_EQ(read<uint64_t>(section, textureField(2, offsetof(DiskProcessedTexture, firstByte))),
              280u + 48 + 344);

    const TextureContents read =
        decodeTextureSection(std::span(&section, 1), levelWithMaterials(2), "test.olpak");
    ASSERT_TRUE(read.present);
    expectSame(read.textures, textures);
    EXPECT_EQ(encodeTextureSection(read.textures).bytes, section.bytes);
}

TEST(TextureSection, RoundTripsThroughAPackage) {
    const world::CompiledLevel level = levelWithMaterials(2);
    const RawSection section = encodeTextureSection(sampleTextures());
    const std::vector<uint8_t> bytes = serializePackage(level, std::span(&section, 1));
    const PackageContents contents = parsePackage(bytes, "test.olpak");
    const TextureContents read =
        decodeTextureSection(contents.bakedSections, contents.level, "test.olpak");
    ASSERT_TRUE(read.present);
    expectSame(read.textures, sampleTextures());
    EXPECT_EQ(serializePackage(contents.level, contents.bakedSections), bytes);
}

TEST(TextureSection, NoTexturesAndNoMaterialsRoundTrip) {
    const RawSection section = encodeTextureSection(world::ProcessedTextures{});
    EXPECT_EQ(section.bytes.size(), kHeader);
    const TextureContents read =
        decodeTextureSection(std::span(&section, 1), levelWithMaterials(0), "test.olpak");
    EXPECT_TRUE(read.present);
    EXPECT_TRUE(read.textures.textures.empty());
    EXPECT_TRUE(read.textures.materials.empty());
}

TEST(TextureSection, AbsentSectionIsNotPresent) {
    RawSection other;
    other.id = kSectionVisibility;
    const TextureContents read =
        decodeTextureSection(std::span(&other, 1), levelWithMaterials(2), "test.olpak");
    EXPECT_FALSE(read.present);
    EXPECT_TRUE(read.textures.textures.empty());
    EXPECT_FALSE(decodeTextureSection({}, levelWithMaterials(2), "test.olpak").present);
}

TEST(TextureSection, RejectsASecondSection) {
    const RawSection section = encodeTextureSection(sampleTextures());
    const std::vector<RawSection> twice = {section, section};
    const std::string error = errorMessage(
        [&] { (void)decodeTextureSection(twice, levelWithMaterials(2), "test.olpak"); });
    EXPECT_NE(error.find("section textures (38) appears twice"), std::string::npos) << error;
}

TEST(TextureSection, RejectsASlotOfTheWrongFormat) {
    const RawSection s = encodeTextureSection(sampleTextures());
    const size_t normal = offsetof(DiskMaterialTextureSlots, normal);
    expectRejected(patched<uint32_t>(s, materialField(0, normal), 0),
                   "material 0: normal is texture 0 'stone base colour' of format RGBA8 sRGB; "
                   "expected RGBA8 UNORM");
    const size_t cavity = offsetof(DiskMaterialTextureSlots, cavity);
    expectRejected(patched<uint32_t>(s, materialField(1, cavity), 1),
                   "material 1: cavity is texture 1");
    const size_t emissive = offsetof(DiskMaterialTextureSlots, emissive);
    expectRejected(patched<uint32_t>(s, materialField(1, emissive), 2),
                   "material 1: emissive is texture 2");
}

TEST(TextureSection, RejectsASlotIndexOutOfRange) {
    const RawSection s = encodeTextureSection(sampleTextures());
    const size_t baseColor = offsetof(DiskMaterialTextureSlots, baseColor);
    expectRejected(patched<uint32_t>(s, materialField(1, baseColor), 3),
                   "material 1: baseColor 3; expected a texture index < 3");
    const size_t occlusion = offsetof(DiskMaterialTextureSlots, occlusion);
    expectRejected(patched<uint32_t>(s, materialField(0, occlusion), 0xFFFFFFFEu),
                   "occlusion 4294967294");
}

TEST(TextureSection, RejectsAMipCountLie) {
    const RawSection s = encodeTextureSection(sampleTextures());
    const size_t mipCount = offsetof(DiskProcessedTexture, mipCount);
    expectRejected(patched<uint32_t>(s, textureField(1, mipCount), 3),
                   "texture 1: mipCount 3; expected 4 for 8x8");
    expectRejected(patched<uint32_t>(s, textureField(1, mipCount), 0xFFFFFFFFu),
                   "mipCount 4294967295");
}

TEST(TextureSection, RejectsAByteCountLie) {
    const RawSection s = encodeTextureSection(sampleTextures());
    const size_t byteCount = offsetof(DiskProcessedTexture, byteCount);
    expectRejected(patched<uint64_t>(s, textureField(2, byteCount), 19),
                   "texture 2: byteCount 19; expected 18");
    expectRejected(patched<uint64_t>(s, textureField(2, byteCount), 17),
                   "texture 2: byteCount 17; expected 18");
    expectRejected(patched<uint64_t>(s, textureField(0, byteCount), ~uint64_t(0)),
                   "texture 0: byteCount 18446744073709551615");
    // The same lie from the data: texels that are not the texture's chain.
    world::ProcessedTextures textures = sampleTextures();
    textures.textures[1].texels.push_back(0);
    expectRejected(encodeTextureSection(textures), "texture 1: byteCount 341; expected 340");
}

TEST(TextureSection, RejectsAZeroOrHugeSize) {
    const RawSection s = encodeTextureSection(sampleTextures());
    const size_t width = offsetof(DiskProcessedTexture, width);
    const size_t height = offsetof(DiskProcessedTexture, height);
    expectRejected(patched<uint32_t>(s, textureField(0, width), 0),
                   "texture 0: width 0; expected 1..16384");
    expectRejected(patched<uint32_t>(s, textureField(0, width), 16385), "width 16385");
    expectRejected(patched<uint32_t>(s, textureField(2, height), 0xFFFFFFFFu),
                   "texture 2: height 4294967295");
}

TEST(TextureSection, RejectsTexelsOutsideTheirPlace) {
    const RawSection s = encodeTextureSection(sampleTextures());
    const size_t firstByte = offsetof(DiskProcessedTexture, firstByte);
    // The last chain (18 bytes, padded to 24) cut off, the header agreeing.
    RawSection cut = resized(s, 24);
    const uint64_t texelBytes =
        read<uint64_t>(s, offsetof(DiskProcessedTexturesHeader, texelBytes));
    cut =
        patched<uint64_t>(cut, offsetof(DiskProcessedTexturesHeader, texelBytes), texelBytes - 24);
    expectRejected(cut, "texture 2: texels [672, +18) run past the end of the section (672 bytes)");
    expectRejected(patched<uint64_t>(s, textureField(0, firstByte), 200),
                   "texture 0: firstByte 200 overlaps the section's records and names");
    expectRejected(patched<uint64_t>(s, textureField(1, firstByte), 336),
                   "texture 1: firstByte 336; expected 328");
    expectRejected(patched<uint64_t>(s, textureField(2, firstByte), ~uint64_t(0)),
                   "texture 2: firstByte 18446744073709551615");
}

TEST(TextureSection, RejectsHiddenOrNonZeroBytes) {
    const RawSection s = encodeTextureSection(sampleTextures());
    // Eight bytes more at the end, the header agreeing: texels no texture owns.
    RawSection longer = resized(s, -8);
    const size_t texelBytes = offsetof(DiskProcessedTexturesHeader, texelBytes);
    longer = patched<uint64_t>(longer, texelBytes, read<uint64_t>(s, texelBytes) + 8);
    expectRejected(longer, "header: texelBytes 424; expected 416");
    // ... and the header disagreeing.
    expectRejected(resized(s, -8), "header: texelBytes 416; expected 424");
    expectRejected(patched<uint8_t>(s, 280 + 44, 1), "texture 0: the padding after its texels");
    expectRejected(patched<uint8_t>(s, 276, 1), "header: the padding after the names");
}

TEST(TextureSection, RejectsAMaterialCountMismatch) {
    const RawSection s = encodeTextureSection(sampleTextures());
    expectRejected(s, "header: materialCount 2; expected 3 (the level's materials)",
                   levelWithMaterials(3));
    expectRejected(s, "header: materialCount 2; expected 1", levelWithMaterials(1));
}

TEST(TextureSection, RejectsAnUnknownEnumeration) {
    const RawSection s = encodeTextureSection(sampleTextures());
    expectRejected(patched<uint8_t>(s, offsetof(DiskProcessedTexturesHeader, method), 4),
                   "header: method 4; expected 0 (blit), 1 (Black Ops), 2 (WWII) or 3 (CLEAN)");
    expectRejected(patched<uint8_t>(s, textureField(1, offsetof(DiskProcessedTexture, format)), 4),
                   "texture 1: format 4; expected 0 (RGBA8 sRGB), 1 (RGBA8 UNORM), 2 (R8 UNORM) or "
                   "3 (R16 float)");
    expectRejected(
        patched<uint16_t>(s, textureField(0, offsetof(DiskProcessedTexture, magFilter)), 9730),
        "texture 0: magFilter 9730");
    expectRejected(
        patched<uint16_t>(s, textureField(0, offsetof(DiskProcessedTexture, minFilter)), 9988),
        "texture 0: minFilter 9988");
    expectRejected(patched<uint16_t>(s, textureField(2, offsetof(DiskProcessedTexture, wrapS)), 0),
                   "texture 2: wrapS 0; expected 10497 (repeat), 33071 (clamp) or 33648");
    expectRejected(
        patched<uint16_t>(s, textureField(2, offsetof(DiskProcessedTexture, wrapT)), 33072),
        "texture 2: wrapT 33072");
    const size_t folded = offsetof(DiskMaterialTextureSlots, factorsFolded);
    expectRejected(patched<uint8_t>(s, materialField(0, folded), 2),
                   "material 0: factorsFolded 2; expected 0 or 1");
    const size_t base = offsetof(DiskMaterialTextureSlots, baseRoughnessInAlpha);
    expectRejected(patched<uint8_t>(s, materialField(0, base), 2),
                   "material 0: baseRoughnessInAlpha 2; expected 0 or 1");
    // The flag speaks of the metallic-roughness texture: without one it is a lie.
    expectRejected(patched<uint8_t>(s, materialField(1, base), 1),
                   "material 1: baseRoughnessInAlpha 1 without a metallicRoughness texture; "
                   "expected 0");
    const size_t kurtosis = offsetof(DiskMaterialTextureSlots, slopeKurtosisInNormalAlpha);
    expectRejected(patched<uint8_t>(s, materialField(0, kurtosis), 3),
                   "material 0: slopeKurtosisInNormalAlpha 3; expected 0 or 1");
    // ... and this one of the normal texture.
    expectRejected(patched<uint8_t>(s, materialField(1, kurtosis), 1),
                   "material 1: slopeKurtosisInNormalAlpha 1 without a normal texture; expected 0");
}

/// A material whose facet table (R16 float, 4x4: 21 texels of 2 bytes) holds `texel` at texel 5
/// of its chain, beside an RGBA8 normal texture.
world::ProcessedTextures facetTextures(uint16_t texel) {
    world::ProcessedTextures p;
    p.method = world::GlossMipMethod::kClean;
    p.textures.push_back(texture("bumps normal", TexelFormat::kRgba8Unorm, 2, 2, 1));
    world::ProcessedTexture facets = texture("bumps facets", TexelFormat::kR16Float, 4, 4, 0);
    for (size_t i = 0; i < facets.texels.size(); i += 2) {
        const uint16_t half = i == 10 ? texel : uint16_t(0x3c00u + i);  // 1.0 and up
        std::memcpy(facets.texels.data() + i, &half, 2);
    }
    p.textures.push_back(facets);
    world::MaterialTextureSlots bumps;
    bumps.normal = 0;
    bumps.facets = 1;
    p.materials.push_back(bumps);
    return p;
}

TEST(TextureSection, AFacetTableRoundTripsAndItsTexelsAreChecked) {
    const world::ProcessedTextures in = facetTextures(0x3555u);  // 1/3
    const RawSection s = encodeTextureSection(in);
    const TextureContents out = decodeTextureSection(std::span(&s, 1), levelWithMaterials(1), "t");
    expectSame(in, out.textures);
    EXPECT_EQ(out.textures.materials[0].facets, 1u);
    // A density that is not finite or is negative would reach the pixels that read it.
    for (const auto& [bits, what] : {std::pair<uint16_t, const char*>{0x7c00u, "not finite"},
                                     {0x7e00u, "not finite"},
                                     {0xbc00u, "negative"}}) {
        const RawSection bad = encodeTextureSection(facetTextures(bits));
        expectRejected(bad, std::string("texture 1: texel 5 of its chain is ") + what,
                       levelWithMaterials(1));
    }
    // Negative zero is zero.
    const RawSection zero = encodeTextureSection(facetTextures(0x8000u));
    EXPECT_NO_THROW((void)decodeTextureSection(std::span(&zero, 1), levelWithMaterials(1), "t"));
    // The slot takes an R16 float table, and the normal slot no table.
    const size_t facets =
        kHeader + 2 * sizeof(DiskProcessedTexture) + offsetof(DiskMaterialTextureSlots, facets);
    expectRejected(patched<uint32_t>(s, facets, 0),
                   "material 0: facets is texture 0 'bumps normal' of format RGBA8 UNORM; "
                   "expected R16 float",
                   levelWithMaterials(1));
    const size_t normal =
        kHeader + 2 * sizeof(DiskProcessedTexture) + offsetof(DiskMaterialTextureSlots, normal);
    expectRejected(patched<uint32_t>(s, normal, 1),
                   "material 0: normal is texture 1 'bumps facets' of format R16 float",
                   levelWithMaterials(1));
    expectRejected(patched<uint32_t>(s, facets, 2),
                   "material 0: facets 2; expected a texture index < 2", levelWithMaterials(1));
}

TEST(TextureSection, RejectsANonZeroReservedField) {
    const RawSection s = encodeTextureSection(sampleTextures());
    expectRejected(patched<uint8_t>(s, offsetof(DiskProcessedTexturesHeader, reserved) + 1, 1),
                   "header: reserved[1] 1; expected 0");
    expectRejected(
        patched<uint8_t>(s, textureField(2, offsetof(DiskProcessedTexture, reserved)), 9),
        "texture 2: reserved[0] 9");
    expectRejected(
        patched<uint8_t>(s, materialField(1, offsetof(DiskMaterialTextureSlots, reserved)), 1),
        "material 1: reserved[0] 1");
}

TEST(TextureSection, RejectsBadNames) {
    const RawSection s = encodeTextureSection(sampleTextures());
    const size_t nameOffset = offsetof(DiskProcessedTexture, nameOffset);
    const size_t nameLength = offsetof(DiskProcessedTexture, nameLength);
    expectRejected(patched<uint32_t>(s, textureField(1, nameOffset), 0),
                   "texture 1: nameOffset 0; expected 17");
    expectRejected(patched<uint32_t>(s, textureField(2, nameLength), 30),
                   "texture 2: name [29, +30) is outside the section's 41 name bytes");
    expectRejected(patched<uint32_t>(s, textureField(2, nameLength), 11),
                   "header: nameBytes 41; expected 40");
    world::ProcessedTextures textures = sampleTextures();
    textures.textures[0].name.assign(kMaxProcessedTextureNameBytes + 1, 'n');
    expectRejected(encodeTextureSection(textures),
                   "texture 0: nameLength 257; expected at most 256");
}

TEST(TextureSection, RejectsCountsBeyondTheSection) {
    const RawSection s = encodeTextureSection(sampleTextures());
    expectRejected(
        patched<uint32_t>(s, offsetof(DiskProcessedTexturesHeader, textureCount), 0xFFFFFFFFu),
        "header: textureCount 4294967295, materialCount 2, nameBytes 41 need 206158430296 bytes; "
        "the section has 696");
    expectRejected(
        patched<uint32_t>(s, offsetof(DiskProcessedTexturesHeader, materialCount), 0xFFFFFFFFu),
        "materialCount 4294967295");
    expectRejected(
        patched<uint32_t>(s, offsetof(DiskProcessedTexturesHeader, nameBytes), 0xFFFFFFFFu),
        "nameBytes 4294967295");
}

TEST(TextureSection, RejectsATruncatedHeader) {
    RawSection s = encodeTextureSection(sampleTextures());
    expectRejected(resized(s, int64_t(s.bytes.size()) - 10),
                   "10 bytes; expected element size 1, count == bytes, and a header of 24 bytes");
    s.count += 1;
    expectRejected(s, "count 697, 696 bytes");
    s = encodeTextureSection(sampleTextures());
    s.elementSize = 4;
    expectRejected(s, "element size 4");
}

}  // namespace
}  // namespace onelight::test
