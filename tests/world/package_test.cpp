#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/error_message.hpp"
#include "tests/world/level_generator.hpp"
#include "tests/world/package_patch.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/error.hpp"
#include "world/file_write.hpp"
#include "world/package/crc32.hpp"
#include "world/package/format.hpp"
#include "world/package/package_reader.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::test {
namespace {

using namespace onelight::package;

/// One compiled generated level shared by the package tests.
const world::CompiledLevel& sampleLevel() {
    static const world::CompiledLevel level = [] {
        GeneratedLevelOptions options = optionsForTriangles(600);
        options.buildings = 4;
        return compileFile(writeGeneratedLevel(freshFolder("package"), "package", options)).level;
    }();
    return level;
}

void expectRejected(const std::vector<uint8_t>& bytes, const std::string& fragment) {
    const std::string error = errorMessage([&] { (void)parsePackage(bytes, "test.olpak"); });
    ASSERT_NE(error, "") << "expected an error mentioning " << fragment;
    EXPECT_NE(error.find(fragment), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST(Package, RoundTripIsByteIdentical) {
    const std::vector<uint8_t> bytes = serializePackage(sampleLevel());
    const PackageContents read = parsePackage(bytes, "test.olpak");
    EXPECT_EQ(read.level.surfaces.size(), sampleLevel().surfaces.size());
    EXPECT_EQ(read.level.lights[0].name, sampleLevel().lights[0].name);
    EXPECT_EQ(serializePackage(read.level), bytes);
}

TEST(Package, ProbeSpacingRoundTripsAndIsChecked) {
    world::CompiledLevel level = sampleLevel();
    EXPECT_EQ(level.settings.probeSpacing, 0.0f) << "not given";
    level.settings.probeSpacing = 3.5f;
    const std::vector<uint8_t> bytes = serializePackage(level);
    const PackageContents read = parsePackage(bytes, "test.olpak");
    EXPECT_EQ(read.level.settings.probeSpacing, 3.5f);
    uint32_t negative;
    const float minusOne = -1.0f;
    std::memcpy(&negative, &minusOne, 4);
    expectRejected(patched(bytes, kSectionLevel, 0, offsetof(DiskLevel, probeSpacing), negative),
                   "probeSpacing");
}

TEST(Package, SkyRoundTripsAndIsChecked) {
    world::CompiledLevel level = sampleLevel();
    level.settings.skyRadiance = glm::vec3(4000.0f, 5000.0f, 6500.0f);
    const std::vector<uint8_t> bytes = serializePackage(level);
    const PackageContents read = parsePackage(bytes, "test.olpak");
    EXPECT_EQ(read.level.settings.skyRadiance, level.settings.skyRadiance);
    for (const float bad :
         {-1.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        uint32_t bits;
        std::memcpy(&bits, &bad, 4);
        expectRejected(patched(bytes, kSectionLevel, 0, offsetof(DiskLevel, skyRadiance) + 4, bits),
                       "skyRadiance");
    }
    // The sky's image indexes the images.
    EXPECT_EQ(read.level.settings.skyImage, world::kNoIndex);
    world::Image sky;
    sky.name = "sky";
    sky.uri = "sky.hdr";
    level.images.push_back(sky);
    level.settings.skyImage = uint32_t(level.images.size() - 1);
    const std::vector<uint8_t> withImage = serializePackage(level);
    EXPECT_EQ(parsePackage(withImage, "test.olpak").level.settings.skyImage,
              level.settings.skyImage);
    expectRejected(patched(withImage, kSectionLevel, 0, offsetof(DiskLevel, skyImage),
                           uint32_t(level.images.size())),
                   "skyImage");
}

TEST(Package, BakedSectionsSurviveARoundTrip) {
    RawSection grid;
    grid.id = kSectionLightGrid;
    grid.elementSize = 4;
    grid.count = 3;
    grid.bytes = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    // A light grid alone, which a loader refuses: the writer's unchecked bytes.
    const std::vector<uint8_t> bytes = serializeUncheckedPackage(sampleLevel(), {&grid, 1});
    const PackageContents read = parsePackage(bytes, "test.olpak");
    ASSERT_EQ(read.bakedSections.size(), 1u);
    EXPECT_EQ(read.bakedSections[0].bytes, grid.bytes);
    EXPECT_EQ(serializeUncheckedPackage(read.level, read.bakedSections), bytes);
}

TEST(Package, CompileIsDeterministic) {
    GeneratedLevelOptions options = optionsForTriangles(2000);
    options.buildings = 6;
    const std::string path =
        writeGeneratedLevel(freshFolder("determinism"), "determinism", options);
    EXPECT_EQ(serializePackage(compileFile(path).level), serializePackage(compileFile(path).level));
}

TEST(Package, EveryTruncationIsRejected) {
    const std::vector<uint8_t> bytes = serializePackage(sampleLevel());
    for (size_t size = 0; size < bytes.size(); ++size) {
        EXPECT_THROW((void)parsePackage(std::span(bytes.data(), size), "test.olpak"), world::Error)
            << "truncated to " << size;
    }
}

TEST(Package, EveryBitFlipInTheHeaderAndTableIsRejected) {
    std::vector<uint8_t> bytes = serializePackage(sampleLevel());
    const size_t headerBytes = sizeof(FileHeader) + kCoreSectionCount * sizeof(SectionEntry);
    for (size_t bit = 0; bit < headerBytes * 8; ++bit) {
        bytes[bit / 8] ^= static_cast<uint8_t>(1u << (bit % 8));
        EXPECT_THROW((void)parsePackage(bytes, "test.olpak"), world::Error) << "bit " << bit;
        bytes[bit / 8] ^= static_cast<uint8_t>(1u << (bit % 8));
    }
    EXPECT_NO_THROW((void)parsePackage(bytes, "test.olpak"));
}

TEST(Package, PayloadCorruptionIsCaughtByTheSectionCrc) {
    std::vector<uint8_t> bytes = serializePackage(sampleLevel());
    const SectionEntry vertices = entry(bytes, kSectionVertices);
    bytes[vertices.offset + 5] ^= 0x10;
    expectRejected(bytes, "section vertices: CRC32 mismatch");
}

TEST(Package, WrongMagicAndVersionAreNamed) {
    std::vector<uint8_t> bytes = serializePackage(sampleLevel());
    std::vector<uint8_t> magic = bytes;
    magic[0] = 'X';
    expectRejected(magic, "bad magic");
    std::vector<uint8_t> version = bytes;
    const uint32_t v = kVersion + 1;
    std::memcpy(version.data() + 4, &v, 4);
    expectRejected(version, "version " + std::to_string(kVersion + 1));
}

TEST(Package, OutOfRangeIndicesAreRejected) {
    const std::vector<uint8_t> bytes = serializePackage(sampleLevel());
    const uint32_t huge = 0x7FFFFFF0u;
    expectRejected(patched(bytes, kSectionIndices, 5, 0, huge), "section indices record 5: index");
    expectRejected(patched(bytes, kSectionSurfaces, 0, offsetof(DiskSurface, material), huge),
                   "section surfaces record 0: material");
    expectRejected(patched(bytes, kSectionSurfaces, 1, offsetof(DiskSurface, chart), huge),
                   "chart");
    expectRejected(patched(bytes, kSectionSurfaces, 1, offsetof(DiskSurface, primaryLight), huge),
                   "primaryLight");
    expectRejected(
        patched(bytes, kSectionSurfaces, 1, offsetof(DiskSurface, indexCount), 3u * 0x20000000u),
        "indices [");
    expectRejected(patched(bytes, kSectionSurfaces, 1, offsetof(DiskSurface, firstGivenUp), huge),
                   "given-up lights");
    expectRejected(patched(bytes, kSectionSurfaces, 1, offsetof(DiskSurface, leaf), huge), "leaf");
    expectRejected(patched(bytes, kSectionBspNodes, 0, offsetof(DiskBspNode, plane), huge),
                   "section bsp_nodes");
    expectRejected(patched(bytes, kSectionBspNodes, 1, offsetof(DiskBspNode, front), 0),
                   "child node 0");
    expectRejected(patched(bytes, kSectionBspLeaves, 0, offsetof(DiskBspLeaf, triangleCount), huge),
                   "triangles");
    expectRejected(patched(bytes, kSectionBspLeaves, 0, offsetof(DiskBspLeaf, firstSurface), huge),
                   "surfaces");
    expectRejected(patched(bytes, kSectionCharts, 0, offsetof(DiskChart, atlas), huge),
                   "section charts");
    expectRejected(patched(bytes, kSectionCharts, 0, offsetof(DiskChart, x), huge),
                   "section charts");
    expectRejected(patched(bytes, kSectionMaterials, 0, offsetof(DiskMaterial, normalTexture), 99),
                   "normalTexture");
    expectRejected(patched(bytes, kSectionMaterials, 0, offsetof(DiskMaterial, name) + 4, huge),
                   "name string");
    expectRejected(patched(bytes, kSectionLights, 0, offsetof(DiskLight, name), huge),
                   "section lights");
    expectRejected(
        patched(bytes, kSectionDynamicMeshes, 0, offsetof(DiskDynamicMesh, vertexCount), huge),
        "section dynamic_meshes");
    expectRejected(patched(bytes, kSectionDynamicIndices, 0, 0, huge), "section dynamic_meshes");
    expectRejected(
        patched(bytes, kSectionEntities, 0, offsetof(DiskEntity, dynamicMeshCount), huge),
        "section entities");
    expectRejected(patched(bytes, kSectionGivenUpLights, 0, 0, huge), "section given_up_lights");
    expectRejected(patched(bytes, kSectionAtlases, 0, 0, 0), "section atlases");
}

TEST(Package, ANaNIsNamedByItsFieldAndElement) {
    const std::vector<uint8_t> bytes = serializePackage(sampleLevel());
    const float nan = std::numeric_limits<float>::quiet_NaN();
    uint32_t bits;
    std::memcpy(&bits, &nan, 4);
    struct Case {
        uint32_t section;
        size_t offset;  // bytes into record 0
        const char* error;
    };
    const Case cases[] = {
        {kSectionEntities, offsetof(DiskEntity, scale) + 4,
         "section entities record 0: scale[1] is NaN or Inf"},
        {kSectionEntities, offsetof(DiskEntity, rotation) + 12,
         "section entities record 0: rotation[3] is NaN or Inf"},
        {kSectionEntities, offsetof(DiskEntity, probeBoxMax) + 8,
         "section entities record 0: probeBoxMax[2] is NaN or Inf"},
        {kSectionVertices, offsetof(DiskVertex, tangent) + 12,
         "section vertices record 0: tangent[3] is NaN or Inf"},
        {kSectionVertices, offsetof(DiskVertex, uv1) + 4,
         "section vertices record 0: uv1[1] is NaN or Inf"},
        {kSectionDynamicVertices, offsetof(DiskVertex, normal) + 8,
         "section dynamic_vertices record 0: normal[2] is NaN or Inf"},
        {kSectionCameras, offsetof(DiskCamera, zfar),
         "section cameras record 0: zfar is NaN or Inf"},
        {kSectionCameras, offsetof(DiskCamera, position),
         "section cameras record 0: position[0] is NaN or Inf"},
        {kSectionCharts, offsetof(DiskChart, axisV) + 4,
         "section charts record 0: axisV[1] is NaN or Inf"},
        {kSectionSurfaces, offsetof(DiskSurface, boundsMax),
         "section surfaces record 0: boundsMax[0] is NaN or Inf"},
        {kSectionBspNodes, offsetof(DiskBspNode, boundsMax) + 8,
         "section bsp_nodes record 0: boundsMax[2] is NaN or Inf"},
        {kSectionBspLeaves, offsetof(DiskBspLeaf, boundsMin) + 4,
         "section bsp_leaves record 0: boundsMin[1] is NaN or Inf"},
        {kSectionMaterials, offsetof(DiskMaterial, emissive) + 8,
         "section materials record 0: emissive[2] is NaN or Inf"},
        {kSectionLights, offsetof(DiskLight, direction) + 4,
         "section lights record 0: direction[1] is NaN or Inf"},
        {kSectionLevel, offsetof(DiskLevel, boundsMax) + 4,
         "section level record 0: boundsMax[1] is NaN or Inf"},
        {kSectionFeatures, offsetof(DiskFeatures, gridMax) + 8,
         "section features record 0: gridMax[2] is NaN or Inf"},
    };
    for (const Case& c : cases)
        expectRejected(patched(bytes, c.section, 0, c.offset, bits), c.error);
}

TEST(Package, UnknownEntityFlagsAreRejected) {
    const std::vector<uint8_t> bytes = serializePackage(sampleLevel());
    expectRejected(patched(bytes, kSectionEntities, 0, offsetof(DiskEntity, flags),
                           world::kAllEntityFlags + 1),
                   "section entities record 0: flags 64 has unknown bits");
}

// A material's flags byte (the last of the word that starts at alphaMode): bit 0, "casts no
// shadow", reads back as castsShadows false; any other bit is refused by name.
TEST(Package, MaterialFlagsReadBackAndUnknownBitsAreRejected) {
    world::CompiledLevel level = sampleLevel();
    ASSERT_FALSE(level.materials.empty());
    level.materials[0].castsShadows = false;
    const std::vector<uint8_t> bytes = serializePackage(level);
    EXPECT_FALSE(parsePackage(bytes, "test.olpak").level.materials[0].castsShadows);
    const size_t at =
        size_t(entry(bytes, kSectionMaterials).offset) + offsetof(DiskMaterial, alphaMode);
    uint32_t word;
    std::memcpy(&word, &bytes[at], 4);
    EXPECT_EQ(word >> 24, uint32_t(kMaterialFlagNoShadows));
    expectRejected(patched(bytes, kSectionMaterials, 0, offsetof(DiskMaterial, alphaMode),
                           (word & 0x00FFFFFFu) | (2u << 24)),
                   "section materials record 0: flags 2; expected 0 or 1 (no shadows)");
}

TEST(Package, ASurfaceHoldsItsChartsLightmapRectangle) {
    const world::CompiledLevel& level = sampleLevel();
    const std::vector<uint8_t> bytes = serializePackage(level);
    const auto awayFromTheCorner = [&](const world::Surface& s) {
        return level.charts[s.chart].x > 0 && level.charts[s.chart].y > 0;
    };
    const auto it = std::find_if(level.surfaces.begin(), level.surfaces.end(), awayFromTheCorner);
    ASSERT_NE(it, level.surfaces.end());
    const uint32_t surface = static_cast<uint32_t>(it - level.surfaces.begin());
    const world::Surface& s = *it;
    const world::Chart& c = level.charts[s.chart];
    const std::string chart = "chart " + std::to_string(s.chart) + "'s ";
    struct Case {
        size_t offset;
        uint32_t expected;
        const char* field;
        const char* chartField;
    };
    const Case cases[] = {
        {offsetof(DiskSurface, lightmapX), c.x, "lightmapX", "x"},
        {offsetof(DiskSurface, lightmapY), c.y, "lightmapY", "y"},
        {offsetof(DiskSurface, lightmapWidth), c.width, "lightmapWidth", "width"},
        {offsetof(DiskSurface, lightmapHeight), c.height, "lightmapHeight", "height"},
    };
    for (const Case& k : cases)
        expectRejected(patched(bytes, kSectionSurfaces, surface, k.offset, k.expected + 1),
                       "section surfaces record " + std::to_string(surface) + ": " + k.field + " " +
                           std::to_string(k.expected + 1) + "; expected " +
                           std::to_string(k.expected) + ", " + chart + k.chartField);
}

TEST(Package, TableEntriesAreValidated) {
    const std::vector<uint8_t> bytes = serializePackage(sampleLevel());
    const auto tablePatch = [&](uint32_t index, size_t field, uint64_t value, size_t width) {
        std::vector<uint8_t> b = bytes;
        std::memcpy(b.data() + sizeof(FileHeader) + index * sizeof(SectionEntry) + field, &value,
                    width);
        fixCrcs(b);
        return b;
    };
    expectRejected(tablePatch(3, offsetof(SectionEntry, offset), 1ull << 40, 8), "outside");
    expectRejected(tablePatch(3, offsetof(SectionEntry, count), 1000000, 4), "count");
    expectRejected(tablePatch(3, offsetof(SectionEntry, id), 2, 4), "twice");
    expectRejected(tablePatch(3, offsetof(SectionEntry, id), 25, 4), "unknown section id");
}

// The atomic write itself is tested in file_write_test.cpp.
TEST(Package, ReadsTheFileItWrote) {
    const auto folder = freshFolder("package_file");
    const std::string path = (folder / "level.olpak").string();
    const std::vector<uint8_t> bytes = serializePackage(sampleLevel());
    world::writeFileAtomically(path, bytes);
    EXPECT_EQ(serializePackage(readPackageFile(path).level), bytes);
    EXPECT_THROW((void)readPackageFile((folder / "absent.olpak").string()), world::Error);
}

}  // namespace
}  // namespace onelight::test
