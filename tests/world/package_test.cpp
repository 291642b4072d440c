#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>

#include "tests/support/error_message.hpp"
#include "tests/world/level_generator.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/error.hpp"
#include "world/package/crc32.hpp"
#include "world/package/format.hpp"
#include "world/package/package_reader.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::test {
namespace {

using namespace onelight::package;

/// One compiled generated level shared by the package tests.
const world::CompiledLevel& sample_level() {
    static const world::CompiledLevel level = [] {
        GeneratedLevelOptions options = options_for_triangles(600);
        options.buildings = 4;
        return compile_file(write_generated_level(fresh_folder("package"), "package", options))
            .level;
    }();
    return level;
}

SectionEntry entry(const std::vector<uint8_t>& bytes, uint32_t id) {
    FileHeader header;
    std::memcpy(&header, bytes.data(), sizeof header);
    for (uint32_t i = 0; i < header.section_count; ++i) {
        SectionEntry e;
        std::memcpy(&e, bytes.data() + sizeof(FileHeader) + i * sizeof(SectionEntry), sizeof e);
        if (e.id == id) return e;
    }
    ADD_FAILURE() << "no section " << id;
    return {};
}

/// Recomputes every section CRC and the table CRC, so only the semantic checks can object.
void fix_crcs(std::vector<uint8_t>& bytes) {
    FileHeader header;
    std::memcpy(&header, bytes.data(), sizeof header);
    for (uint32_t i = 0; i < header.section_count; ++i) {
        uint8_t* at = bytes.data() + sizeof(FileHeader) + i * sizeof(SectionEntry);
        SectionEntry e;
        std::memcpy(&e, at, sizeof e);
        e.crc32 = crc32(bytes.data() + e.offset, e.size);
        std::memcpy(at, &e, sizeof e);
    }
    header.table_crc32 = 0;
    std::memcpy(bytes.data(), &header, sizeof header);
    header.table_crc32 =
        crc32(bytes.data(), sizeof(FileHeader) + header.section_count * sizeof(SectionEntry));
    std::memcpy(bytes.data(), &header, sizeof header);
}

/// Overwrites a uint32 field of record `record` in section `id`, then fixes the CRCs.
std::vector<uint8_t> patched(std::vector<uint8_t> bytes, uint32_t id, uint32_t record,
                             size_t field_offset, uint32_t value) {
    const SectionEntry e = entry(bytes, id);
    EXPECT_LT(record, e.count);
    std::memcpy(bytes.data() + e.offset + uint64_t(record) * e.element_size + field_offset, &value,
                4);
    fix_crcs(bytes);
    return bytes;
}

void expect_rejected(const std::vector<uint8_t>& bytes, const std::string& fragment) {
    const std::string error = errorMessage([&] { (void)parse_package(bytes, "test.olpak"); });
    ASSERT_NE(error, "") << "expected an error mentioning " << fragment;
    EXPECT_NE(error.find(fragment), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST(Package, RoundTripIsByteIdentical) {
    const std::vector<uint8_t> bytes = serialize_package(sample_level());
    const PackageContents read = parse_package(bytes, "test.olpak");
    EXPECT_EQ(read.level.surfaces.size(), sample_level().surfaces.size());
    EXPECT_EQ(read.level.lights[0].name, sample_level().lights[0].name);
    EXPECT_EQ(serialize_package(read.level), bytes);
}

TEST(Package, ProbeSpacingRoundTripsAndIsChecked) {
    world::CompiledLevel level = sample_level();
    EXPECT_EQ(level.settings.probe_spacing, 0.0f) << "not given";
    level.settings.probe_spacing = 3.5f;
    const std::vector<uint8_t> bytes = serialize_package(level);
    const PackageContents read = parse_package(bytes, "test.olpak");
    EXPECT_EQ(read.level.settings.probe_spacing, 3.5f);
    uint32_t negative;
    const float minus_one = -1.0f;
    std::memcpy(&negative, &minus_one, 4);
    expect_rejected(patched(bytes, section_level, 0, offsetof(DiskLevel, probe_spacing), negative),
                    "probe_spacing");
}

TEST(Package, SkyRoundTripsAndIsChecked) {
    world::CompiledLevel level = sample_level();
    level.settings.sky_radiance = glm::vec3(4000.0f, 5000.0f, 6500.0f);
    const std::vector<uint8_t> bytes = serialize_package(level);
    const PackageContents read = parse_package(bytes, "test.olpak");
    EXPECT_EQ(read.level.settings.sky_radiance, level.settings.sky_radiance);
    for (const float bad :
         {-1.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        uint32_t bits;
        std::memcpy(&bits, &bad, 4);
        expect_rejected(
            patched(bytes, section_level, 0, offsetof(DiskLevel, sky_radiance) + 4, bits),
            "sky_radiance");
    }
}

TEST(Package, BakedSectionsSurviveARoundTrip) {
    RawSection grid;
    grid.id = section_light_grid;
    grid.element_size = 4;
    grid.count = 3;
    grid.bytes = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    const std::vector<uint8_t> bytes = serialize_package(sample_level(), {&grid, 1});
    const PackageContents read = parse_package(bytes, "test.olpak");
    ASSERT_EQ(read.baked_sections.size(), 1u);
    EXPECT_EQ(read.baked_sections[0].bytes, grid.bytes);
    EXPECT_EQ(serialize_package(read.level, read.baked_sections), bytes);
}

TEST(Package, CompileIsDeterministic) {
    GeneratedLevelOptions options = options_for_triangles(2000);
    options.buildings = 6;
    const std::string path =
        write_generated_level(fresh_folder("determinism"), "determinism", options);
    EXPECT_EQ(serialize_package(compile_file(path).level),
              serialize_package(compile_file(path).level));
}

TEST(Package, EveryTruncationIsRejected) {
    const std::vector<uint8_t> bytes = serialize_package(sample_level());
    for (size_t size = 0; size < bytes.size(); ++size) {
        EXPECT_THROW((void)parse_package(std::span(bytes.data(), size), "test.olpak"), world::Error)
            << "truncated to " << size;
    }
}

TEST(Package, EveryBitFlipInTheHeaderAndTableIsRejected) {
    std::vector<uint8_t> bytes = serialize_package(sample_level());
    const size_t header_bytes = sizeof(FileHeader) + core_section_count * sizeof(SectionEntry);
    for (size_t bit = 0; bit < header_bytes * 8; ++bit) {
        bytes[bit / 8] ^= static_cast<uint8_t>(1u << (bit % 8));
        EXPECT_THROW((void)parse_package(bytes, "test.olpak"), world::Error) << "bit " << bit;
        bytes[bit / 8] ^= static_cast<uint8_t>(1u << (bit % 8));
    }
    EXPECT_NO_THROW((void)parse_package(bytes, "test.olpak"));
}

TEST(Package, PayloadCorruptionIsCaughtByTheSectionCrc) {
    std::vector<uint8_t> bytes = serialize_package(sample_level());
    const SectionEntry vertices = entry(bytes, section_vertices);
    bytes[vertices.offset + 5] ^= 0x10;
    expect_rejected(bytes, "section vertices: CRC32 mismatch");
}

TEST(Package, WrongMagicAndVersionAreNamed) {
    std::vector<uint8_t> bytes = serialize_package(sample_level());
    std::vector<uint8_t> magic = bytes;
    magic[0] = 'X';
    expect_rejected(magic, "bad magic");
    std::vector<uint8_t> version = bytes;
    const uint32_t v = kVersion + 1;
    std::memcpy(version.data() + 4, &v, 4);
    expect_rejected(version, "version 2");
}

TEST(Package, OutOfRangeIndicesAreRejected) {
    const std::vector<uint8_t> bytes = serialize_package(sample_level());
    const uint32_t huge = 0x7FFFFFF0u;
    expect_rejected(patched(bytes, section_indices, 5, 0, huge), "section indices record 5: index");
    expect_rejected(patched(bytes, section_surfaces, 0, offsetof(DiskSurface, material), huge),
                    "section surfaces record 0: material");
    expect_rejected(patched(bytes, section_surfaces, 1, offsetof(DiskSurface, chart), huge),
                    "chart");
    expect_rejected(patched(bytes, section_surfaces, 1, offsetof(DiskSurface, primary_light), huge),
                    "primary_light");
    expect_rejected(
        patched(bytes, section_surfaces, 1, offsetof(DiskSurface, index_count), 3u * 0x20000000u),
        "indices [");
    expect_rejected(
        patched(bytes, section_surfaces, 1, offsetof(DiskSurface, first_given_up), huge),
        "given-up lights");
    expect_rejected(patched(bytes, section_surfaces, 1, offsetof(DiskSurface, leaf), huge), "leaf");
    expect_rejected(patched(bytes, section_bsp_nodes, 0, offsetof(DiskBspNode, plane), huge),
                    "section bsp_nodes");
    expect_rejected(patched(bytes, section_bsp_nodes, 1, offsetof(DiskBspNode, front), 0),
                    "child node 0");
    expect_rejected(
        patched(bytes, section_bsp_leaves, 0, offsetof(DiskBspLeaf, triangle_count), huge),
        "triangles");
    expect_rejected(
        patched(bytes, section_bsp_leaves, 0, offsetof(DiskBspLeaf, first_surface), huge),
        "surfaces");
    expect_rejected(patched(bytes, section_charts, 0, offsetof(DiskChart, atlas), huge),
                    "section charts");
    expect_rejected(patched(bytes, section_charts, 0, offsetof(DiskChart, x), huge),
                    "section charts");
    expect_rejected(
        patched(bytes, section_materials, 0, offsetof(DiskMaterial, normal_texture), 99),
        "normal_texture");
    expect_rejected(patched(bytes, section_materials, 0, offsetof(DiskMaterial, name) + 4, huge),
                    "name string");
    expect_rejected(patched(bytes, section_lights, 0, offsetof(DiskLight, name), huge),
                    "section lights");
    expect_rejected(
        patched(bytes, section_dynamic_meshes, 0, offsetof(DiskDynamicMesh, vertex_count), huge),
        "section dynamic_meshes");
    expect_rejected(patched(bytes, section_dynamic_indices, 0, 0, huge), "section dynamic_meshes");
    expect_rejected(
        patched(bytes, section_entities, 0, offsetof(DiskEntity, dynamic_mesh_count), huge),
        "section entities");
    expect_rejected(patched(bytes, section_given_up_lights, 0, 0, huge), "section given_up_lights");
    expect_rejected(patched(bytes, section_atlases, 0, 0, 0), "section atlases");
}

TEST(Package, ANaNIsNamedByItsFieldAndElement) {
    const std::vector<uint8_t> bytes = serialize_package(sample_level());
    const float nan = std::numeric_limits<float>::quiet_NaN();
    uint32_t bits;
    std::memcpy(&bits, &nan, 4);
    struct Case {
        uint32_t section;
        size_t offset;  // bytes into record 0
        const char* error;
    };
    const Case cases[] = {
        {section_entities, offsetof(DiskEntity, scale) + 4,
         "section entities record 0: scale[1] is NaN or Inf"},
        {section_entities, offsetof(DiskEntity, rotation) + 12,
         "section entities record 0: rotation[3] is NaN or Inf"},
        {section_entities, offsetof(DiskEntity, probe_box_max) + 8,
         "section entities record 0: probe_box_max[2] is NaN or Inf"},
        {section_vertices, offsetof(DiskVertex, tangent) + 12,
         "section vertices record 0: tangent[3] is NaN or Inf"},
        {section_vertices, offsetof(DiskVertex, uv1) + 4,
         "section vertices record 0: uv1[1] is NaN or Inf"},
        {section_dynamic_vertices, offsetof(DiskVertex, normal) + 8,
         "section dynamic_vertices record 0: normal[2] is NaN or Inf"},
        {section_cameras, offsetof(DiskCamera, zfar),
         "section cameras record 0: zfar is NaN or Inf"},
        {section_cameras, offsetof(DiskCamera, position),
         "section cameras record 0: position[0] is NaN or Inf"},
        {section_charts, offsetof(DiskChart, axis_v) + 4,
         "section charts record 0: axis_v[1] is NaN or Inf"},
        {section_surfaces, offsetof(DiskSurface, bounds_max),
         "section surfaces record 0: bounds_max[0] is NaN or Inf"},
        {section_bsp_nodes, offsetof(DiskBspNode, bounds_max) + 8,
         "section bsp_nodes record 0: bounds_max[2] is NaN or Inf"},
        {section_bsp_leaves, offsetof(DiskBspLeaf, bounds_min) + 4,
         "section bsp_leaves record 0: bounds_min[1] is NaN or Inf"},
        {section_materials, offsetof(DiskMaterial, emissive) + 8,
         "section materials record 0: emissive[2] is NaN or Inf"},
        {section_lights, offsetof(DiskLight, direction) + 4,
         "section lights record 0: direction[1] is NaN or Inf"},
        {section_level, offsetof(DiskLevel, bounds_max) + 4,
         "section level record 0: bounds_max[1] is NaN or Inf"},
        {section_features, offsetof(DiskFeatures, grid_max) + 8,
         "section features record 0: grid_max[2] is NaN or Inf"},
    };
    for (const Case& c : cases)
        expect_rejected(patched(bytes, c.section, 0, c.offset, bits), c.error);
}

TEST(Package, UnknownEntityFlagsAreRejected) {
    const std::vector<uint8_t> bytes = serialize_package(sample_level());
    expect_rejected(patched(bytes, section_entities, 0, offsetof(DiskEntity, flags),
                            world::kAllEntityFlags + 1),
                    "section entities record 0: flags 16 has unknown bits");
}

TEST(Package, ASurfaceHoldsItsChartsLightmapRectangle) {
    const world::CompiledLevel& level = sample_level();
    const std::vector<uint8_t> bytes = serialize_package(level);
    const auto away_from_the_corner = [&](const world::Surface& s) {
        return level.charts[s.chart].x > 0 && level.charts[s.chart].y > 0;
    };
    const auto it =
        std::find_if(level.surfaces.begin(), level.surfaces.end(), away_from_the_corner);
    ASSERT_NE(it, level.surfaces.end());
    const uint32_t surface = static_cast<uint32_t>(it - level.surfaces.begin());
    const world::Surface& s = *it;
    const world::Chart& c = level.charts[s.chart];
    const std::string chart = "chart " + std::to_string(s.chart) + "'s ";
    struct Case {
        size_t offset;
        uint32_t expected;
        const char* field;
        const char* chart_field;
    };
    const Case cases[] = {
        {offsetof(DiskSurface, lightmap_x), c.x, "lightmap_x", "x"},
        {offsetof(DiskSurface, lightmap_y), c.y, "lightmap_y", "y"},
        {offsetof(DiskSurface, lightmap_width), c.width, "lightmap_width", "width"},
        {offsetof(DiskSurface, lightmap_height), c.height, "lightmap_height", "height"},
    };
    for (const Case& k : cases)
        expect_rejected(patched(bytes, section_surfaces, surface, k.offset, k.expected + 1),
                        "section surfaces record " + std::to_string(surface) + ": " + k.field +
                            " " + std::to_string(k.expected + 1) + "; expected " +
                            std::to_string(k.expected) + ", " + chart + k.chart_field);
}

TEST(Package, TableEntriesAreValidated) {
    const std::vector<uint8_t> bytes = serialize_package(sample_level());
    const auto table_patch = [&](uint32_t index, size_t field, uint64_t value, size_t width) {
        std::vector<uint8_t> b = bytes;
        std::memcpy(b.data() + sizeof(FileHeader) + index * sizeof(SectionEntry) + field, &value,
                    width);
        fix_crcs(b);
        return b;
    };
    expect_rejected(table_patch(3, offsetof(SectionEntry, offset), 1ull << 40, 8), "outside");
    expect_rejected(table_patch(3, offsetof(SectionEntry, count), 1000000, 4), "count");
    expect_rejected(table_patch(3, offsetof(SectionEntry, id), 2, 4), "twice");
    expect_rejected(table_patch(3, offsetof(SectionEntry, id), 25, 4), "unknown section id");
}

TEST(Package, WritesAtomically) {
    const auto folder = fresh_folder("atomic");
    const std::string path = (folder / "level.olpak").string();
    const std::vector<uint8_t> bytes = serialize_package(sample_level());
    write_file_atomically(path, bytes);
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
    EXPECT_EQ(serialize_package(read_package_file(path).level), bytes);
    EXPECT_THROW(write_file_atomically((folder / "missing" / "level.olpak").string(), bytes),
                 world::Error);
    EXPECT_THROW((void)read_package_file((folder / "absent.olpak").string()), world::Error);
}

}  // namespace
}  // namespace onelight::test
