#include "world/package/package_writer.hpp"

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/images/image_decode.hpp"
#include "world/package/collision_section.hpp"
#include "world/package/crc32.hpp"
#include "world/package/format.hpp"
#include "world/package/package_decode.hpp"
#include "world/package/package_reader.hpp"
#include "world/package/records.hpp"

namespace onelight::package {
namespace {

using namespace onelight::world;

template <typename T>
void appendRecord(std::vector<uint8_t>& out, const T& record) {
    const auto* p = reinterpret_cast<const uint8_t*>(&record);
    out.insert(out.end(), p, p + sizeof(T));
}

struct Section {
    uint32_t elementSize = 1;
    uint32_t count = 0;
    std::vector<uint8_t> bytes;
};

using Sections = std::array<Section, kCoreSectionCount>;

/// Section `id` of records of type T, toDisk of each of `items` (the extra arguments, such as
/// the blobs, passed along).
template <typename T, typename Item, typename... Extra>
void addRecords(Sections& sections, SectionId id, const std::vector<Item>& items, Extra&... extra) {
    Section& s = sections[id];
    s.elementSize = sizeof(T);
    for (const Item& item : items) {
        const T record = toDisk(item, extra...);
        appendRecord(s.bytes, record);
        ++s.count;
    }
}

/// A section of uint32_t indices.
void addU32(Sections& sections, SectionId id, const std::vector<uint32_t>& values) {
    Section& s = sections[id];
    s.elementSize = sizeof(uint32_t);
    for (uint32_t v : values) appendRecord(s.bytes, v);
    s.count = static_cast<uint32_t>(values.size());
}

/// A section of bytes (element size 1).
void addBytes(Sections& sections, SectionId id, std::vector<uint8_t> bytes) {
    Section& s = sections[id];
    s.elementSize = 1;
    s.count = static_cast<uint32_t>(bytes.size());
    s.bytes = std::move(bytes);
}

/// Every core section, in the order that fills the strings (the bytes depend on it).
void buildSections(const CompiledLevel& level, Sections& sections) {
    BlobWriter blobs;
    addRecords<DiskLevel>(sections, kSectionLevel, std::vector{level.settings});
    addRecords<DiskMaterial>(sections, kSectionMaterials, level.materials, blobs);
    addRecords<DiskTexture>(sections, kSectionTextures, level.textures);
    addRecords<DiskImage>(sections, kSectionImages, level.images, blobs);
    addRecords<DiskLight>(sections, kSectionLights, level.lights, blobs);
    addRecords<DiskCamera>(sections, kSectionCameras, level.cameras, blobs);
    addRecords<DiskVertex>(sections, kSectionVertices, level.vertices);
    addU32(sections, kSectionIndices, level.indices);
    addRecords<DiskSurface>(sections, kSectionSurfaces, level.surfaces);
    addU32(sections, kSectionGivenUpLights, level.givenUpLights);
    addRecords<DiskChart>(sections, kSectionCharts, level.charts);
    addRecords<DiskAtlas>(sections, kSectionAtlases, level.atlases);
    addRecords<DiskBspPlane>(sections, kSectionBspPlanes, level.bspPlanes);
    addRecords<DiskBspNode>(sections, kSectionBspNodes, level.bspNodes);
    addRecords<DiskBspLeaf>(sections, kSectionBspLeaves, level.bspLeaves);
    addRecords<DiskVertex>(sections, kSectionDynamicVertices, level.dynamicVertices);
    addU32(sections, kSectionDynamicIndices, level.dynamicIndices);
    addRecords<DiskDynamicMesh>(sections, kSectionDynamicMeshes, level.dynamicMeshes, blobs);
    addRecords<DiskEntity>(sections, kSectionEntities, level.entities, blobs);
    addRecords<DiskFeatures>(sections, kSectionFeatures, std::vector{level.features});
    addRecords<DiskMover>(sections, kSectionMovers, level.movers.movers);
    addRecords<DiskMoverPoint>(sections, kSectionMoverPoints, level.movers.path);
    addBytes(sections, kSectionStrings, std::move(blobs.strings));
    addBytes(sections, kSectionImageBytes, std::move(blobs.imageBytes));
}

uint64_t alignUp(uint64_t value) {
    return (value + kSectionAlignment - 1) / kSectionAlignment * kSectionAlignment;
}

}  // namespace

std::vector<uint8_t> serializePackage(const world::CompiledLevel& level,
                                      std::span<const RawSection> bakedSections) {
    std::vector<uint8_t> out = serializeUncheckedPackage(level, bakedSections);
    // The reader's checks on every record (package_decode.hpp): a package that its own reader
    // would refuse is never handed to be written.
    try {
        (void)decodePackage(out, "the package as made");
    } catch (const world::Error& e) {
        throw world::Error(std::string(e.what()) +
                           " (the writer runs the reader's checks: nothing was written)");
    }
    return out;
}

std::vector<uint8_t> serializeUncheckedPackage(const world::CompiledLevel& level,
                                               std::span<const RawSection> bakedSections) {
    Sections sections;
    buildSections(level, sections);
    struct Placed {
        uint32_t id;
        const Section* section;
        const RawSection* raw;
    };
    std::vector<Placed> order;
    for (uint32_t id = 0; id < kCoreSectionCount; ++id)
        order.push_back({id, &sections[id], nullptr});
    const std::vector<RawSection> collision = encodeCollisionSections(level.collision);
    for (const RawSection& raw : collision) order.push_back({raw.id, nullptr, &raw});
    for (const RawSection& raw : bakedSections)
        if (raw.id != kSectionCollision && raw.id != kSectionTriggers)  // the level's own above
            order.push_back({raw.id, nullptr, &raw});

    const uint64_t tableEnd = sizeof(FileHeader) + order.size() * sizeof(SectionEntry);
    std::vector<SectionEntry> table(order.size());
    uint64_t offset = alignUp(tableEnd);
    for (size_t i = 0; i < order.size(); ++i) {
        const std::vector<uint8_t>& bytes =
            order[i].section ? order[i].section->bytes : order[i].raw->bytes;
        SectionEntry& e = table[i];
        e = SectionEntry{};
        e.id = order[i].id;
        e.elementSize =
            order[i].section ? order[i].section->elementSize : order[i].raw->elementSize;
        e.count = order[i].section ? order[i].section->count : order[i].raw->count;
        e.offset = offset;
        e.size = bytes.size();
        e.crc32 = crc32(bytes.data(), bytes.size());
        offset = alignUp(offset + bytes.size());
    }
    std::vector<uint8_t> out(offset, 0);
    FileHeader header{};
    header.magic = kMagic;
    header.version = kVersion;
    header.headerSize = sizeof(FileHeader);
    header.sectionCount = static_cast<uint32_t>(order.size());
    header.fileSize = offset;
    header.tableCrc32 = 0;
    std::memcpy(out.data(), &header, sizeof header);
    std::memcpy(out.data() + sizeof header, table.data(), table.size() * sizeof(SectionEntry));
    header.tableCrc32 = crc32(out.data(), tableEnd);
    std::memcpy(out.data(), &header, sizeof header);
    for (size_t i = 0; i < order.size(); ++i) {
        const std::vector<uint8_t>& bytes =
            order[i].section ? order[i].section->bytes : order[i].raw->bytes;
        if (!bytes.empty()) std::memcpy(out.data() + table[i].offset, bytes.data(), bytes.size());
    }
    return out;
}

void placeImagesForPackage(world::CompiledLevel& level, const std::string& packagePath) {
    const std::filesystem::path folder = std::filesystem::absolute(packagePath).parent_path();
    for (world::Image& image : level.images) {
        if (image.uri.empty()) continue;
        std::error_code ec;
        const std::string relative =
            std::filesystem::relative(std::filesystem::absolute(image.uri), folder, ec)
                .generic_string();
        if (!ec && isPathBesideThePackage(relative)) {
            // Named, not read: still a regular file within the image limit (not a FIFO, a
            // device or missing), or the runtime would meet it.
            world::requireRegularFile(image.uri, "an image the level uses",
                                      world::kMaxEncodedImageBytes);
            image.uri = relative;
        } else {
            image.encodedBytes = world::readRegularFile(image.uri, "an image the level uses",
                                                        world::kMaxEncodedImageBytes);
            image.uri.clear();
        }
    }
}

}  // namespace onelight::package
