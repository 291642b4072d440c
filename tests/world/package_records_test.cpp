// The record pairs of world/package/records.hpp: every field of every record survives from_disk
// then to_disk bit for bit (so neither side drops or mixes up a field), and the baked sections'
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
long first_difference(const T& a, const T& b) {
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
    std::vector<uint8_t> image_bytes{9, 9};

    StringRef add_string(const std::string& s) {
        const StringRef ref{uint32_t(strings.size()), uint32_t(s.size())};
        strings.insert(strings.end(), s.begin(), s.end());
        return ref;
    }
    BlobReader reader() const { return BlobReader{strings, image_bytes}; }
    BlobWriter writer() const {
        BlobWriter w;
        w.strings = {'-', '-'};
        w.image_bytes = {9, 9};
        return w;
    }
};

/// Expects from_disk then to_disk to give `d` back byte for byte (and the same blobs).
template <typename Disk>
void expect_round_trip(const Disk& d, const Blobs& blobs = {}) {
    SCOPED_TRACE(typeid(Disk).name());
    if constexpr (requires { from_disk(d, blobs.reader()); }) {
        BlobWriter writer = blobs.writer();
        const Disk back = to_disk(from_disk(d, blobs.reader()), writer);
        EXPECT_EQ(first_difference(back, d), -1) << "byte of the record";
        EXPECT_EQ(writer.strings, blobs.strings);
        EXPECT_EQ(writer.image_bytes, blobs.image_bytes);
    } else {
        const Disk back = to_disk(from_disk(d));
        EXPECT_EQ(first_difference(back, d), -1) << "byte of the record";
    }
}

TEST(PackageRecords, EveryCoreRecordRoundTrips) {
    DiskLevel level = patterned<DiskLevel>();
    level.has_exposure = 1;
    level.reserved = 0;
    expect_round_trip(level);

    Blobs material_blobs;
    DiskMaterial material = patterned<DiskMaterial>();
    material.name = material_blobs.add_string("stone");
    material.alpha_mode = 2;
    material.double_sided = 1;
    material.material_class = 3;
    material.reserved = 0;
    expect_round_trip(material, material_blobs);

    expect_round_trip(patterned<DiskTexture>());

    Blobs image_blobs;
    DiskImage image = patterned<DiskImage>();
    image.name = image_blobs.add_string("albedo");
    image.uri = image_blobs.add_string("textures/albedo.png");
    image.mime_type = image_blobs.add_string("image/png");
    image.first_byte = uint32_t(image_blobs.image_bytes.size());
    image.byte_count = 5;
    image_blobs.image_bytes.insert(image_blobs.image_bytes.end(), {1, 2, 3, 4, 5});
    expect_round_trip(image, image_blobs);

    Blobs light_blobs;
    DiskLight light = patterned<DiskLight>();
    light.name = light_blobs.add_string("sun");
    light.type = 2;
    light.role = 1;
    light.reserved[0] = light.reserved[1] = 0;
    expect_round_trip(light, light_blobs);

    Blobs camera_blobs;
    DiskCamera camera = patterned<DiskCamera>();
    camera.name = camera_blobs.add_string("overview");
    camera.orthographic = 1;
    camera.has_exposure = 1;
    expect_round_trip(camera, camera_blobs);

    expect_round_trip(patterned<DiskVertex>());
    expect_round_trip(patterned<DiskSurface>());

    DiskChart chart = patterned<DiskChart>();
    chart.authored = 1;
    expect_round_trip(chart);

    expect_round_trip(patterned<DiskAtlas>());
    expect_round_trip(patterned<DiskBspPlane>());
    expect_round_trip(patterned<DiskBspNode>());
    expect_round_trip(patterned<DiskBspLeaf>());

    Blobs mesh_blobs;
    DiskDynamicMesh mesh = patterned<DiskDynamicMesh>();
    mesh.name = mesh_blobs.add_string("crate/box");
    expect_round_trip(mesh, mesh_blobs);

    Blobs entity_blobs;
    DiskEntity entity = patterned<DiskEntity>();
    entity.name = entity_blobs.add_string("crate");
    expect_round_trip(entity, entity_blobs);

    expect_round_trip(patterned<DiskFeatures>());
}

TEST(PackageRecords, EveryBakedRecordRoundTrips) {
    expect_round_trip(patterned<DiskLightmapTexel>());
    expect_round_trip(patterned<DiskLightGridCell>());
    DiskLightGridCell no_primary = patterned<DiskLightGridCell>();
    no_primary.dominant_primary = kNoIndex;
    expect_round_trip(no_primary);

    DiskLightGridHeader header = patterned<DiskLightGridHeader>();
    header.cell_count = 3;
    header.reserved = 0;
    world::BakedLighting baked;
    from_disk_grid_header(header, baked);
    baked.grid.cells.resize(header.cell_count);
    EXPECT_EQ(first_difference(to_disk_grid_header(baked), header), -1);

    DiskProbe probe = patterned<DiskProbe>();
    probe.first_texel = 2;
    probe.texel_count = 3;
    probe.reserved = 0;
    const std::vector<uint32_t> texels = {10, 11, 12, 13, 14, 15};
    const std::span<const uint8_t> texel_bytes(reinterpret_cast<const uint8_t*>(texels.data()),
                                               texels.size() * 4);
    const world::EnvironmentProbe p = from_disk(probe, texel_bytes);
    EXPECT_EQ(p.texels, (std::vector<uint32_t>{12, 13, 14}));
    EXPECT_EQ(first_difference(to_disk(p, probe.first_texel), probe), -1);
}

TEST(PackageRecords, FromDiskNeverReadsOutsideItsBlobs) {
    Blobs blobs;
    DiskImage image = patterned<DiskImage>();  // references far outside both blobs
    const world::Image read = from_disk(image, blobs.reader());
    EXPECT_TRUE(read.name.empty());
    EXPECT_TRUE(read.encoded_bytes.empty());
    DiskProbe probe = patterned<DiskProbe>();
    EXPECT_TRUE(from_disk(probe, {}).texels.empty());
}

TEST(PackageRecords, BakedErrorsNameTheElement) {
    world::CompiledLevel level;  // no atlas: no lightmap texels
    world::BakedLighting baked;
    baked.grid.dims = glm::uvec3(1);
    baked.grid.cells.resize(1);
    std::vector<RawSection> sections = encode_baked_sections(baked);
    ASSERT_TRUE(decode_baked_sections(sections, level, "x.olpak").present);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(sections[2].bytes.data() + sizeof(DiskLightGridHeader) +
                    offsetof(DiskLightGridCell, ambient_cube) + (2 * 3 + 1) * 4,
                &nan, 4);
    const std::string error =
        test::errorMessage([&] { (void)decode_baked_sections(sections, level, "x.olpak"); });
    EXPECT_NE(error.find("light_grid cells, record 0: ambient_cube[2][1] = nan"), std::string::npos)
        << error;
}

}  // namespace
}  // namespace onelight::test
