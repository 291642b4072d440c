// The record pairs of world/package/records.hpp: every field of every record survives fromDisk
// then toDisk bit for bit (so neither side drops or mixes up a field), and the baked sections'
// readers name the exact element they reject.
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <typeinfo>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/error_message.hpp"
#include "world/package/baked_sections.hpp"
#include "world/package/records.hpp"

namespace onelight::test {
namespace {

using namespace onelight::package;

/// A record whose every 4-byte word holds a different float (1.25, 2.25, ...), so that a field
/// that one side drops or swaps comes back different.
template <typename T>
T patterned() {
    static_assert(sizeof(T) % 4 == 0);
    T record;
    for (size_t k = 0; k < sizeof(T) / 4; ++k) {
        const float v = 1.25f + float(k);
        std::memcpy(reinterpret_cast<uint8_t*>(&record) + 4 * k, &v, 4);
    }
    return record;
}

/// The first byte where `a` and `b` differ, -1 when they are equal.
template <typename T>
long firstDifference(const T& a, const T& b) {
    const auto* x = reinterpret_cast<const uint8_t*>(&a);
    const auto* y = reinterpret_cast<const uint8_t*>(&b);
    for (size_t k = 0; k < sizeof(T); ++k)
        if (x[k] != y[k]) return long(k);
    return -1;
}

/// The strings and image bytes records refer into: both start with bytes of no record, so
/// that no reference is 0; a writer made by writer() starts the same way and so rebuilds
/// the same references.
struct Blobs {
    std::vector<uint8_t> strings{'-', '-'};
    std::vector<uint8_t> imageBytes{9, 9};

    StringRef addString(const std::string& s) {
        const StringRef ref{uint32_t(strings.size()), uint32_t(s.size())};
        strings.insert(strings.end(), s.begin(), s.end());
        return ref;
    }
    BlobReader reader() const { return BlobReader{strings, imageBytes}; }
    BlobWriter writer() const {
        BlobWriter w;
        w.strings = {'-', '-'};
        w.imageBytes = {9, 9};
        return w;
    }
};

/// Expects fromDisk then toDisk to give `d` back byte for byte (and the same blobs).
template <typename Disk>
void expectRoundTrip(const Disk& d, const Blobs& blobs = {}) {
    SCOPED_TRACE(typeid(Disk).name());
    if constexpr (requires { fromDisk(d, blobs.reader()); }) {
        BlobWriter writer = blobs.writer();
        const Disk back = toDisk(fromDisk(d, blobs.reader()), writer);
        EXPECT_EQ(firstDifference(back, d), -1) << "byte of the record";
        EXPECT_EQ(writer.strings, blobs.strings);
        EXPECT_EQ(writer.imageBytes, blobs.imageBytes);
    } else {
        const Disk back = toDisk(fromDisk(d));
        EXPECT_EQ(firstDifference(back, d), -1) << "byte of the record";
    }
}

TEST(PackageRecords, EveryCoreRecordRoundTrips) {
    DiskLevel level = patterned<DiskLevel>();
    level.hasExposure = 1;
    level.diffuseModel = 1;
    level.glossMips = 2;
    level.reserved = 0;
    expectRoundTrip(level);

    Blobs materialBlobs;
    DiskMaterial material = patterned<DiskMaterial>();
    material.name = materialBlobs.addString("stone");
    material.alphaMode = 2;
    material.doubleSided = 1;
    material.materialClass = 3;
    material.flags = kMaterialFlagNoShadows;
    expectRoundTrip(material, materialBlobs);

    expectRoundTrip(patterned<DiskTexture>());

    Blobs imageBlobs;
    DiskImage image = patterned<DiskImage>();
    image.name = imageBlobs.addString("albedo");
    image.uri = imageBlobs.addString("textures/albedo.png");
    image.mimeType = imageBlobs.addString("image/png");
    image.firstByte = uint32_t(imageBlobs.imageBytes.size());
    image.byteCount = 5;
    imageBlobs.imageBytes.insert(imageBlobs.imageBytes.end(), {1, 2, 3, 4, 5});
    expectRoundTrip(image, imageBlobs);

    Blobs lightBlobs;
    DiskLight light = patterned<DiskLight>();
    light.name = lightBlobs.addString("sun");
    light.type = 2;
    light.role = 1;
    light.reserved[0] = light.reserved[1] = 0;
    expectRoundTrip(light, lightBlobs);

    Blobs cameraBlobs;
    DiskCamera camera = patterned<DiskCamera>();
    camera.name = cameraBlobs.addString("overview");
    camera.orthographic = 1;
    camera.hasExposure = 1;
    expectRoundTrip(camera, cameraBlobs);

    expectRoundTrip(patterned<DiskVertex>());
    expectRoundTrip(patterned<DiskSurface>());

    DiskChart chart = patterned<DiskChart>();
    chart.authored = 1;
    expectRoundTrip(chart);

    expectRoundTrip(patterned<DiskAtlas>());
    expectRoundTrip(patterned<DiskBspPlane>());
    expectRoundTrip(patterned<DiskBspNode>());
    expectRoundTrip(patterned<DiskBspLeaf>());

    Blobs meshBlobs;
    DiskDynamicMesh mesh = patterned<DiskDynamicMesh>();
    mesh.name = meshBlobs.addString("crate/box");
    expectRoundTrip(mesh, meshBlobs);

    Blobs entityBlobs;
    DiskEntity entity = patterned<DiskEntity>();
    entity.name = entityBlobs.addString("crate");
    expectRoundTrip(entity, entityBlobs);

    expectRoundTrip(patterned<DiskFeatures>());
}

TEST(PackageRecords, EveryBakedRecordRoundTrips) {
    expectRoundTrip(patterned<DiskLightmapTexel>());
    expectRoundTrip(patterned<DiskLightGridCell>());
    DiskLightGridCell noPrimary = patterned<DiskLightGridCell>();
    noPrimary.dominantPrimary = kNoIndex;
    expectRoundTrip(noPrimary);

    DiskLightGridHeader header = patterned<DiskLightGridHeader>();
    header.cellCount = 3;
    header.reserved = 0;
    world::BakedLighting baked;
    fromDiskGridHeader(header, baked);
    baked.grid.cells.resize(header.cellCount);
    EXPECT_EQ(firstDifference(toDiskGridHeader(baked), header), -1);

    DiskProbe probe = patterned<DiskProbe>();
    probe.firstTexel = 2;
    probe.texelCount = 3;
    probe.reserved = 0;
    const std::vector<uint32_t> texels = {10, 11, 12, 13, 14, 15};
    const std::span<const uint8_t> texelBytes(reinterpret_cast<const uint8_t*>(texels.data()),
                                              texels.size() * 4);
    const world::EnvironmentProbe p = fromDisk(probe, texelBytes);
    EXPECT_EQ(p.texels, (std::vector<uint32_t>{12, 13, 14}));
    EXPECT_EQ(firstDifference(toDisk(p, probe.firstTexel), probe), -1);
}

TEST(PackageRecords, EveryOptionalSectionRecordRoundTrips) {
    expectRoundTrip(patterned<DiskErrorBudget>());
    DiskShardRange range = patterned<DiskShardRange>();
    range.reserved = 0;
    expectRoundTrip(range);
    DiskMaterialTextureSlots slots = patterned<DiskMaterialTextureSlots>();
    slots.factorsFolded = 1;
    slots.baseRoughnessInAlpha = 1;
    slots.slopeKurtosisInNormalAlpha = 1;
    std::memset(slots.reserved, 0, sizeof(slots.reserved));
    expectRoundTrip(slots);

    const DiskImportedTexel imported = patterned<DiskImportedTexel>();
    const world::LightmapTexel texel = fromDisk(imported, world::kLightmapTexelDilated);
    EXPECT_EQ(texel.flags, world::kLightmapTexelDilated);
    EXPECT_EQ(firstDifference(toDiskImported(texel), imported), -1);

    DiskVisibilityHeader visibility = patterned<DiskVisibilityHeader>();
    visibility.cellCount = 2;
    visibility.surfaceCount = 3;
    visibility.clusterCount = 40;  // two words a row
    visibility.rowCount = 1;
    visibility.reserved = 0;
    world::Visibility v;
    fromDiskVisibilityHeader(visibility, v);
    v.cellRow.resize(visibility.cellCount);
    v.surfaceCluster.resize(visibility.surfaceCount);
    v.rows.resize(2);
    EXPECT_EQ(firstDifference(toDiskVisibilityHeader(v), visibility), -1);

    DiskProcessedTexture texture = patterned<DiskProcessedTexture>();
    std::memset(texture.reserved, 0, sizeof(texture.reserved));
    texture.nameOffset = 1;
    texture.nameLength = 3;
    texture.firstByte = 2;
    texture.byteCount = 4;
    const std::vector<uint8_t> names = {'-', 'a', 'b', 'c', '-'};
    const std::vector<uint8_t> section = {0, 1, 2, 3, 4, 5, 6, 7};
    const world::ProcessedTexture t = fromDisk(texture, names, section);
    EXPECT_EQ(t.name, "abc");
    EXPECT_EQ(t.texels, (std::vector<uint8_t>{2, 3, 4, 5}));
    EXPECT_EQ(firstDifference(toDisk(t, texture.nameOffset, texture.firstByte), texture), -1);
}

TEST(PackageRecords, FromDiskNeverReadsOutsideItsBlobs) {
    Blobs blobs;
    DiskImage image = patterned<DiskImage>();  // references far outside both blobs
    const world::Image read = fromDisk(image, blobs.reader());
    EXPECT_TRUE(read.name.empty());
    EXPECT_TRUE(read.encodedBytes.empty());
    DiskProbe probe = patterned<DiskProbe>();
    EXPECT_TRUE(fromDisk(probe, {}).texels.empty());
}

TEST(PackageRecords, BakedErrorsNameTheElement) {
    world::CompiledLevel level;  // no atlas: no lightmap texels
    world::BakedLighting baked;
    baked.grid.dims = glm::uvec3(1);
    baked.grid.cells.resize(1);
    std::vector<RawSection> sections = encodeBakedSections(baked);
    ASSERT_TRUE(decodeBakedSections(sections, level, "x.olpak").present);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(sections[2].bytes.data() + sizeof(DiskLightGridHeader) +
                    offsetof(DiskLightGridCell, ambientCube) + (2 * 3 + 1) * 4,
                &nan, 4);
    const std::string error =
        test::errorMessage([&] { (void)decodeBakedSections(sections, level, "x.olpak"); });
    EXPECT_NE(error.find("light_grid cells, record 0: ambientCube[2][1] = nan"), std::string::npos)
        << error;
}

}  // namespace
}  // namespace onelight::test
