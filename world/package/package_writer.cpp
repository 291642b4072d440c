#include "world/package/package_writer.hpp"

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "world/error.hpp"
#include "world/package/crc32.hpp"
#include "world/package/format.hpp"
#include "world/package/records.hpp"

namespace onelight::package {
namespace {

using namespace onelight::world;

template <typename T>
void append_record(std::vector<uint8_t>& out, const T& record) {
    const auto* p = reinterpret_cast<const uint8_t*>(&record);
    out.insert(out.end(), p, p + sizeof(T));
}

struct Section {
    uint32_t element_size = 1;
    uint32_t count = 0;
    std::vector<uint8_t> bytes;
};

using Sections = std::array<Section, core_section_count>;

/// Section `id` of records of type T, to_disk of each of `items` (the extra arguments, such as
/// the blobs, passed along).
template <typename T, typename Item, typename... Extra>
void add_records(Sections& sections, SectionId id, const std::vector<Item>& items,
                 Extra&... extra) {
    Section& s = sections[id];
    s.element_size = sizeof(T);
    for (const Item& item : items) {
        const T record = to_disk(item, extra...);
        append_record(s.bytes, record);
        ++s.count;
    }
}

/// A section of uint32_t indices.
void add_u32(Sections& sections, SectionId id, const std::vector<uint32_t>& values) {
    Section& s = sections[id];
    s.element_size = sizeof(uint32_t);
    for (uint32_t v : values) append_record(s.bytes, v);
    s.count = static_cast<uint32_t>(values.size());
}

/// A section of bytes (element size 1).
void add_bytes(Sections& sections, SectionId id, std::vector<uint8_t> bytes) {
    Section& s = sections[id];
    s.element_size = 1;
    s.count = static_cast<uint32_t>(bytes.size());
    s.bytes = std::move(bytes);
}

/// Every core section, in the order that fills the strings (the bytes depend on it).
void build_sections(const CompiledLevel& level, Sections& sections) {
    BlobWriter blobs;
    add_records<DiskLevel>(sections, section_level, std::vector{level.settings});
    add_records<DiskMaterial>(sections, section_materials, level.materials, blobs);
    add_records<DiskTexture>(sections, section_textures, level.textures);
    add_records<DiskImage>(sections, section_images, level.images, blobs);
    add_records<DiskLight>(sections, section_lights, level.lights, blobs);
    add_records<DiskCamera>(sections, section_cameras, level.cameras, blobs);
    add_records<DiskVertex>(sections, section_vertices, level.vertices);
    add_u32(sections, section_indices, level.indices);
    add_records<DiskSurface>(sections, section_surfaces, level.surfaces);
    add_u32(sections, section_given_up_lights, level.given_up_lights);
    add_records<DiskChart>(sections, section_charts, level.charts);
    add_records<DiskAtlas>(sections, section_atlases, level.atlases);
    add_records<DiskBspPlane>(sections, section_bsp_planes, level.bsp_planes);
    add_records<DiskBspNode>(sections, section_bsp_nodes, level.bsp_nodes);
    add_records<DiskBspLeaf>(sections, section_bsp_leaves, level.bsp_leaves);
    add_records<DiskVertex>(sections, section_dynamic_vertices, level.dynamic_vertices);
    add_u32(sections, section_dynamic_indices, level.dynamic_indices);
    add_records<DiskDynamicMesh>(sections, section_dynamic_meshes, level.dynamic_meshes, blobs);
    add_records<DiskEntity>(sections, section_entities, level.entities, blobs);
    add_records<DiskFeatures>(sections, section_features, std::vector{level.features});
    add_bytes(sections, section_strings, std::move(blobs.strings));
    add_bytes(sections, section_image_bytes, std::move(blobs.image_bytes));
}

uint64_t align_up(uint64_t value) {
    return (value + kSectionAlignment - 1) / kSectionAlignment * kSectionAlignment;
}

}  // namespace

std::vector<uint8_t> serialize_package(const world::CompiledLevel& level,
                                       std::span<const RawSection> baked_sections) {
    Sections sections;
    build_sections(level, sections);
    struct Placed {
        uint32_t id;
        const Section* section;
        const RawSection* raw;
    };
    std::vector<Placed> order;
    for (uint32_t id = 0; id < core_section_count; ++id)
        order.push_back({id, &sections[id], nullptr});
    for (const RawSection& raw : baked_sections) order.push_back({raw.id, nullptr, &raw});

    const uint64_t table_end = sizeof(FileHeader) + order.size() * sizeof(SectionEntry);
    std::vector<SectionEntry> table(order.size());
    uint64_t offset = align_up(table_end);
    for (size_t i = 0; i < order.size(); ++i) {
        const std::vector<uint8_t>& bytes =
            order[i].section ? order[i].section->bytes : order[i].raw->bytes;
        SectionEntry& e = table[i];
        e = SectionEntry{};
        e.id = order[i].id;
        e.element_size =
            order[i].section ? order[i].section->element_size : order[i].raw->element_size;
        e.count = order[i].section ? order[i].section->count : order[i].raw->count;
        e.offset = offset;
        e.size = bytes.size();
        e.crc32 = crc32(bytes.data(), bytes.size());
        offset = align_up(offset + bytes.size());
    }
    std::vector<uint8_t> out(offset, 0);
    FileHeader header{};
    header.magic = kMagic;
    header.version = kVersion;
    header.header_size = sizeof(FileHeader);
    header.section_count = static_cast<uint32_t>(order.size());
    header.file_size = offset;
    header.table_crc32 = 0;
    std::memcpy(out.data(), &header, sizeof header);
    std::memcpy(out.data() + sizeof header, table.data(), table.size() * sizeof(SectionEntry));
    header.table_crc32 = crc32(out.data(), table_end);
    std::memcpy(out.data(), &header, sizeof header);
    for (size_t i = 0; i < order.size(); ++i) {
        const std::vector<uint8_t>& bytes =
            order[i].section ? order[i].section->bytes : order[i].raw->bytes;
        if (!bytes.empty()) std::memcpy(out.data() + table[i].offset, bytes.data(), bytes.size());
    }
    return out;
}

void write_file_atomically(const std::string& path, std::span<const uint8_t> bytes) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
        if (!file) throw world::Error(path + ": cannot create " + temporary);
        file.write(reinterpret_cast<const char*>(bytes.data()),
                   static_cast<std::streamsize>(bytes.size()));
        file.flush();
        if (!file) {
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            throw world::Error(path + ": writing " + temporary + " failed (disk full?)");
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        throw world::Error(path + ": cannot rename " + temporary + " into place");
    }
}

}  // namespace onelight::package
