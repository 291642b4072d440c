#include "world/package/package_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/package/collision_section.hpp"
#include "world/package/crc32.hpp"
#include "world/package/format.hpp"
#include "world/package/records.hpp"

namespace onelight::package {
namespace {

using namespace onelight::world;

const char* sectionName(uint32_t id) {
    static constexpr std::array<const char*, kCoreSectionCount> names{
        "strings",     "level",           "materials",        "textures",        "images",
        "image_bytes", "lights",          "cameras",          "vertices",        "indices",
        "surfaces",    "given_up_lights", "charts",           "atlases",         "bsp_planes",
        "bsp_nodes",   "bsp_leaves",      "dynamic_vertices", "dynamic_indices", "dynamic_meshes",
        "entities",    "features",        "movers",           "mover_points"};
    return id < kCoreSectionCount ? names[id] : "baked";
}

uint32_t expectedElementSize(uint32_t id) {
    switch (id) {
        case kSectionStrings:
            return 1;
        case kSectionLevel:
            return sizeof(DiskLevel);
        case kSectionMaterials:
            return sizeof(DiskMaterial);
        case kSectionTextures:
            return sizeof(DiskTexture);
        case kSectionImages:
            return sizeof(DiskImage);
        case kSectionImageBytes:
            return 1;
        case kSectionLights:
            return sizeof(DiskLight);
        case kSectionCameras:
            return sizeof(DiskCamera);
        case kSectionVertices:
            return sizeof(DiskVertex);
        case kSectionIndices:
            return sizeof(uint32_t);
        case kSectionSurfaces:
            return sizeof(DiskSurface);
        case kSectionGivenUpLights:
            return sizeof(uint32_t);
        case kSectionCharts:
            return sizeof(DiskChart);
        case kSectionAtlases:
            return sizeof(DiskAtlas);
        case kSectionBspPlanes:
            return sizeof(DiskBspPlane);
        case kSectionBspNodes:
            return sizeof(DiskBspNode);
        case kSectionBspLeaves:
            return sizeof(DiskBspLeaf);
        case kSectionDynamicVertices:
            return sizeof(DiskVertex);
        case kSectionDynamicIndices:
            return sizeof(uint32_t);
        case kSectionDynamicMeshes:
            return sizeof(DiskDynamicMesh);
        case kSectionEntities:
            return sizeof(DiskEntity);
        case kSectionFeatures:
            return sizeof(DiskFeatures);
        case kSectionMovers:
            return sizeof(DiskMover);
        case kSectionMoverPoints:
            return sizeof(DiskMoverPoint);
        default:
            return 0;
    }
}

class Reader {
public:
    Reader(std::span<const uint8_t> bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    void read(PackageContents& out) {
        readHeaderAndTable(out);
        CompiledLevel& level = out.level;
        loadBlobs();
        level.settings = fromDisk(single<DiskLevel>(kSectionLevel));
        load<DiskImage>(kSectionImages, level, level.images);  // before textures: they index images
        checkIndex(kSectionLevel, 0, "skyImage", level.settings.skyImage, level.images.size(),
                   "images", true);
        load<DiskTexture>(kSectionTextures, level, level.textures);
        load<DiskMaterial>(kSectionMaterials, level, level.materials);
        load<DiskLight>(kSectionLights, level, level.lights);
        load<DiskCamera>(kSectionCameras, level, level.cameras);
        load<DiskVertex>(kSectionVertices, level, level.vertices);
        level.indices = loadIndices(kSectionIndices, level.vertices.size(), "vertices");
        load<DiskAtlas>(kSectionAtlases, level, level.atlases);
        load<DiskChart>(kSectionCharts, level, level.charts);
        loadBsp(level);
        loadGivenUp(level);
        load<DiskSurface>(kSectionSurfaces, level, level.surfaces);
        checkLeavesAgainstSurfaces(level);
        load<DiskVertex>(kSectionDynamicVertices, level, level.dynamicVertices);
        level.dynamicIndices = loadU32(kSectionDynamicIndices);
        load<DiskDynamicMesh>(kSectionDynamicMeshes, level, level.dynamicMeshes);
        load<DiskEntity>(kSectionEntities, level, level.entities);
        level.features = fromDisk(single<DiskFeatures>(kSectionFeatures));
        load<DiskMoverPoint>(kSectionMoverPoints, level, level.movers.path);
        load<DiskMover>(kSectionMovers, level, level.movers.movers);
        checkMoverLinks(level);
    }

private:
    [[noreturn]] void fail(const std::string& message) const {
        throw world::Error(name_ + ": " + message);
    }
    [[noreturn]] void fail(uint32_t id, size_t record, const std::string& message) const {
        fail(std::string("section ") + sectionName(id) + " record " + std::to_string(record) +
             ": " + message);
    }

    void readHeaderAndTable(PackageContents& out) {
        if (bytes_.size() < sizeof(FileHeader))
            fail("file is " + std::to_string(bytes_.size()) + " bytes; expected at least a " +
                 std::to_string(sizeof(FileHeader)) + "-byte header");
        FileHeader header;
        std::memcpy(&header, bytes_.data(), sizeof header);
        if (header.magic != kMagic) fail("bad magic; expected an .olpak file (\"OLPK\")");
        if (header.version != kVersion)
            fail("version " + std::to_string(header.version) + "; this reader reads version " +
                 std::to_string(kVersion));
        if (header.headerSize != sizeof(FileHeader))
            fail("header size " + std::to_string(header.headerSize) + "; expected " +
                 std::to_string(sizeof(FileHeader)));
        if (header.fileSize != bytes_.size())
            fail("header says " + std::to_string(header.fileSize) + " bytes but the file has " +
                 std::to_string(bytes_.size()) + " (truncated or padded)");
        if (header.sectionCount < kCoreSectionCount || header.sectionCount > kMaxSections)
            fail("section count " + std::to_string(header.sectionCount) + "; expected " +
                 std::to_string(kCoreSectionCount) + " to " + std::to_string(kMaxSections));
        const uint64_t tableEnd =
            sizeof(FileHeader) + uint64_t(header.sectionCount) * sizeof(SectionEntry);
        if (tableEnd > bytes_.size()) fail("section table runs past the end of the file");
        if (header.reserved != 0)
            fail("header reserved field is " + std::to_string(header.reserved) + "; expected 0");
        const uint32_t storedCrc = header.tableCrc32;
        FileHeader zeroed = header;
        zeroed.tableCrc32 = 0;
        uint32_t crc = crc32(&zeroed, sizeof zeroed);
        crc = crc32(bytes_.data() + sizeof(FileHeader), tableEnd - sizeof(FileHeader), crc);
        if (crc != storedCrc) fail("header/section table CRC32 mismatch; the file is corrupt");

        for (uint32_t i = 0; i < header.sectionCount; ++i) {
            SectionEntry e;
            std::memcpy(&e, bytes_.data() + sizeof(FileHeader) + i * sizeof(SectionEntry),
                        sizeof e);
            const std::string where =
                "section table entry " + std::to_string(i) + " (id " + std::to_string(e.id) + ")";
            if (e.id >= kSectionIdLimit ||
                (e.id >= kCoreSectionCount && e.id < kSectionLightmapTexels))
                fail(where + ": unknown section id");
            if (e.id < kCoreSectionCount ? core_[e.id] != nullptr
                                         : bakedSeen_[e.id - kSectionLightmapTexels])
                fail(where + ": section appears twice");
            if (e.offset % kSectionAlignment != 0 || e.offset < tableEnd ||
                e.offset > bytes_.size() || e.size > bytes_.size() - e.offset)
                fail(where + ": bytes [" + std::to_string(e.offset) + ", +" +
                     std::to_string(e.size) + ") are outside the file's payload");
            if (e.elementSize == 0 || uint64_t(e.count) * e.elementSize != e.size)
                fail(where + ": count " + std::to_string(e.count) + " x element size " +
                     std::to_string(e.elementSize) + " != size " + std::to_string(e.size));
            if (e.id < kCoreSectionCount && e.elementSize != expectedElementSize(e.id))
                fail(std::string("section ") + sectionName(e.id) + ": record size " +
                     std::to_string(e.elementSize) + "; expected " +
                     std::to_string(expectedElementSize(e.id)));
            if (crc32(bytes_.data() + e.offset, e.size) != e.crc32)
                fail(std::string("section ") + sectionName(e.id) +
                     ": CRC32 mismatch; the file is corrupt");
            if (e.id < kCoreSectionCount) {
                entries_[e.id] = e;
                core_[e.id] = &entries_[e.id];
            } else {
                bakedSeen_[e.id - kSectionLightmapTexels] = true;
                RawSection raw;
                raw.id = e.id;
                raw.elementSize = e.elementSize;
                raw.count = e.count;
                raw.bytes.assign(bytes_.begin() + static_cast<std::ptrdiff_t>(e.offset),
                                 bytes_.begin() + static_cast<std::ptrdiff_t>(e.offset + e.size));
                out.bakedSections.push_back(std::move(raw));
            }
        }
        for (uint32_t id = 0; id < kCoreSectionCount; ++id)
            if (!core_[id]) fail(std::string("section ") + sectionName(id) + " is missing");
    }

    template <typename T>
    std::vector<T> records(uint32_t id) const {
        const SectionEntry& e = *core_[id];
        std::vector<T> out(e.count);
        if (e.size > 0) std::memcpy(out.data(), bytes_.data() + e.offset, e.size);
        return out;
    }

    std::vector<uint32_t> loadU32(uint32_t id) const { return records<uint32_t>(id); }

    void loadBlobs() {
        const SectionEntry& strings = *core_[kSectionStrings];
        const SectionEntry& imageBytes = *core_[kSectionImageBytes];
        blobs_.strings = bytes_.subspan(strings.offset, strings.size);
        blobs_.imageBytes = bytes_.subspan(imageBytes.offset, imageBytes.size);
    }

    /// Section `id`'s records, each checked, then mapped by fromDisk into `out`.
    template <typename Disk, typename Item>
    void load(uint32_t id, const CompiledLevel& level, std::vector<Item>& out) const {
        const auto r = records<Disk>(id);
        out.reserve(r.size());
        for (size_t i = 0; i < r.size(); ++i) {
            check(id, i, r[i], level);
            if constexpr (requires { fromDisk(r[i], blobs_); })
                out.push_back(fromDisk(r[i], blobs_));
            else
                out.push_back(fromDisk(r[i]));
        }
    }

    /// The one record of section `id` (level, features), checked.
    template <typename Disk>
    Disk single(uint32_t id) const {
        const auto r = records<Disk>(id);
        if (r.size() != 1)
            fail(std::string("section ") + sectionName(id) + ": " + std::to_string(r.size()) +
                 " records; expected 1");
        check(id, 0, r[0]);
        return r[0];
    }

    void checkString(uint32_t id, size_t record, const char* field, const StringRef& ref) const {
        const size_t size = blobs_.strings.size();
        if (ref.offset > size || ref.length > size - ref.offset)
            fail(id, record,
                 std::string(field) + " string [" + std::to_string(ref.offset) + ", +" +
                     std::to_string(ref.length) + ") is outside the strings section (" +
                     std::to_string(size) + " bytes)");
    }

    void checkIndex(uint32_t id, size_t record, const char* field, uint32_t value, size_t limit,
                    const char* target, bool noneAllowed) const {
        if (noneAllowed && value == kNoIndex) return;
        if (value >= limit)
            fail(id, record,
                 std::string(field) + " " + std::to_string(value) + " is out of range (" +
                     std::to_string(limit) + " " + target + ")");
    }

    void checkRange(uint32_t id, size_t record, const char* field, uint64_t first, uint64_t count,
                    size_t limit, const char* target) const {
        if (first > limit || count > limit - first)
            fail(id, record,
                 std::string(field) + " [" + std::to_string(first) + ", +" + std::to_string(count) +
                     ") is out of range (" + std::to_string(limit) + " " + target + ")");
    }

    /// Rejects a NaN or Inf in the float field `field`.
    void checkFinite(uint32_t id, size_t record, const char* field, float v) const {
        if (!std::isfinite(v)) fail(id, record, std::string(field) + " is NaN or Inf");
    }

    /// Rejects a NaN or Inf in the array field `field`, naming the element.
    template <size_t N>
    void checkFinite(uint32_t id, size_t record, const char* field, const float (&v)[N]) const {
        for (size_t k = 0; k < N; ++k)
            if (!std::isfinite(v[k]))
                fail(id, record, std::string(field) + "[" + std::to_string(k) + "] is NaN or Inf");
    }

    /// Rejects `value` unless it is `expected`, the value of `source`.
    void checkEqual(uint32_t id, size_t record, const char* field, uint32_t value,
                    uint32_t expected, const std::string& source) const {
        if (value != expected)
            fail(id, record,
                 std::string(field) + " " + std::to_string(value) + "; expected " +
                     std::to_string(expected) + ", " + source);
    }

    void check(uint32_t id, size_t i, const DiskLevel& d) const {
        checkFinite(id, i, "exposureEv100", d.exposureEv100);
        checkFinite(id, i, "boundsMin", d.boundsMin);
        checkFinite(id, i, "boundsMax", d.boundsMax);
        if (!(d.texelsPerMetre > 0.0f) || !std::isfinite(d.texelsPerMetre))
            fail(id, i, "texelsPerMetre " + std::to_string(d.texelsPerMetre) + "; expected > 0");
        if (!(d.probeSpacing >= 0.0f) || !std::isfinite(d.probeSpacing))
            fail(id, i,
                 "probeSpacing " + std::to_string(d.probeSpacing) + "; expected metres >= 0");
        checkFinite(id, i, "skyRadiance", d.skyRadiance);
        if (!(std::min({d.skyRadiance[0], d.skyRadiance[1], d.skyRadiance[2]}) >= 0.0f))
            fail(id, i, "skyRadiance negative; expected cd/m^2 >= 0");
        if (d.diffuseModel > uint8_t(world::DiffuseModel::kMultiscatter))
            fail(id, i,
                 "diffuseModel " + std::to_string(d.diffuseModel) +
                     "; expected 0 (Lambert) or 1 (multiscatter)");
        if (d.glossMips > uint8_t(world::GlossMipMethod::kClean))
            fail(id, i,
                 "glossMips " + std::to_string(d.glossMips) +
                     "; expected 0 (blit), 1 (Black Ops), 2 (WWII) or 3 (CLEAN)");
        if (d.reserved != 0) fail(id, i, "reserved " + std::to_string(d.reserved) + "; expected 0");
    }

    void check(uint32_t id, size_t i, const DiskImage& d, const CompiledLevel&) const {
        checkString(id, i, "name", d.name);
        checkString(id, i, "uri", d.uri);
        checkString(id, i, "mimeType", d.mimeType);
        checkRange(id, i, "bytes", d.firstByte, d.byteCount, blobs_.imageBytes.size(),
                   "image bytes");
        if ((d.uri.length == 0) == (d.byteCount == 0))
            fail(id, i, "expected either a uri or embedded bytes, not both or neither");
        const std::string_view uri(
            reinterpret_cast<const char*>(blobs_.strings.data()) + d.uri.offset, d.uri.length);
        if (d.uri.length > 0 && !isPathBesideThePackage(uri))
            fail(id, i,
                 "uri '" + world::clipForMessage(uri) +
                     "'; expected a relative path to a file beside the package or below its "
                     "folder (no leading '/', no '..', no '\\\\', no ':')");
    }

    void check(uint32_t id, size_t i, const DiskTexture& d, const CompiledLevel& level) const {
        checkIndex(id, i, "image", d.image, level.images.size(), "images", true);
    }

    void check(uint32_t id, size_t i, const DiskMaterial& d, const CompiledLevel& level) const {
        checkString(id, i, "name", d.name);
        checkFinite(id, i, "baseColor", d.baseColor);
        checkFinite(id, i, "metallic", d.metallic);
        checkFinite(id, i, "roughness", d.roughness);
        checkFinite(id, i, "albedo", d.albedo);
        checkFinite(id, i, "specularColor", d.specularColor);
        checkFinite(id, i, "gloss", d.gloss);
        checkFinite(id, i, "emissive", d.emissive);
        checkFinite(id, i, "alphaCutoff", d.alphaCutoff);
        checkFinite(id, i, "normalScale", d.normalScale);
        checkFinite(id, i, "occlusionStrength", d.occlusionStrength);
        const size_t textures = level.textures.size();
        checkIndex(id, i, "baseColorTexture", d.baseColorTexture, textures, "textures", true);
        checkIndex(id, i, "metallicRoughnessTexture", d.metallicRoughnessTexture, textures,
                   "textures", true);
        checkIndex(id, i, "normalTexture", d.normalTexture, textures, "textures", true);
        checkIndex(id, i, "occlusionTexture", d.occlusionTexture, textures, "textures", true);
        checkIndex(id, i, "emissiveTexture", d.emissiveTexture, textures, "textures", true);
        if (d.alphaMode > 2)
            fail(id, i, "alphaMode " + std::to_string(d.alphaMode) + "; expected 0..2");
        if (d.materialClass > 3)
            fail(id, i, "materialClass " + std::to_string(d.materialClass) + "; expected 0..3");
        if ((d.flags & ~kMaterialFlagNoShadows) != 0)
            fail(id, i, "flags " + std::to_string(d.flags) + "; expected 0 or 1 (no shadows)");
        if (d.gloss < 0.0f || d.gloss > 1.0f)
            fail(id, i, "gloss " + std::to_string(d.gloss) + "; expected [0, 1]");
    }

    void check(uint32_t id, size_t i, const DiskLight& d, const CompiledLevel&) const {
        checkString(id, i, "name", d.name);
        if (d.type > 2) fail(id, i, "type " + std::to_string(d.type) + "; expected 0..2");
        if (d.role > 2) fail(id, i, "role " + std::to_string(d.role) + "; expected 0..2");
        checkFinite(id, i, "color", d.color);
        checkFinite(id, i, "position", d.position);
        checkFinite(id, i, "direction", d.direction);
        if (!(d.intensity >= 0.0f) || !std::isfinite(d.intensity))
            fail(id, i, "intensity " + std::to_string(d.intensity) + "; expected finite >= 0");
        if (!(d.range >= 0.0f) || !std::isfinite(d.range))
            fail(id, i, "range " + std::to_string(d.range) + "; expected finite >= 0");
        if (!(d.innerCone >= 0.0f && d.innerCone <= d.outerCone && d.outerCone <= 1.5708f))
            fail(id, i, "cone angles; expected 0 <= inner <= outer <= pi/2");
    }

    void check(uint32_t id, size_t i, const DiskCamera& d, const CompiledLevel&) const {
        checkString(id, i, "name", d.name);
        checkFinite(id, i, "yfov", d.yfov);
        checkFinite(id, i, "aspectRatio", d.aspectRatio);
        checkFinite(id, i, "znear", d.znear);
        checkFinite(id, i, "zfar", d.zfar);
        checkFinite(id, i, "xmag", d.xmag);
        checkFinite(id, i, "ymag", d.ymag);
        checkFinite(id, i, "position", d.position);
        checkFinite(id, i, "rotation", d.rotation);
        checkFinite(id, i, "exposureEv100", d.exposureEv100);
    }

    void check(uint32_t id, size_t i, const DiskVertex& d, const CompiledLevel&) const {
        checkFinite(id, i, "position", d.position);
        checkFinite(id, i, "normal", d.normal);
        checkFinite(id, i, "tangent", d.tangent);
        checkFinite(id, i, "uv0", d.uv0);
        checkFinite(id, i, "uv1", d.uv1);
    }

    std::vector<uint32_t> loadIndices(uint32_t id, size_t vertexCount, const char* target) const {
        std::vector<uint32_t> out = loadU32(id);
        if (out.size() % 3 != 0)
            fail(std::string("section ") + sectionName(id) + ": " + std::to_string(out.size()) +
                 " indices; expected a multiple of 3");
        for (size_t i = 0; i < out.size(); ++i)
            checkIndex(id, i, "index", out[i], vertexCount, target, false);
        return out;
    }

    void check(uint32_t id, size_t i, const DiskAtlas& d, const CompiledLevel&) const {
        if (d.width == 0 || d.height == 0 || d.width > 65536 || d.height > 65536)
            fail(id, i,
                 "size " + std::to_string(d.width) + "x" + std::to_string(d.height) +
                     "; expected 1..65536 texels per side");
    }

    void check(uint32_t id, size_t i, const DiskChart& d, const CompiledLevel& level) const {
        checkIndex(id, i, "atlas", d.atlas, level.atlases.size(), "atlases", false);
        const Atlas& a = level.atlases[d.atlas];
        checkRange(id, i, "x", d.x, d.width, a.width, "texels of atlas width");
        checkRange(id, i, "y", d.y, d.height, a.height, "texels of atlas height");
        if (uint64_t(2) * d.padding >= d.width || uint64_t(2) * d.padding >= d.height)
            fail(id, i,
                 "padding " + std::to_string(d.padding) + " leaves no room in the rectangle");
        checkFinite(id, i, "texelsPerMetre", d.texelsPerMetre);
        checkFinite(id, i, "origin", d.origin);
        checkFinite(id, i, "axisU", d.axisU);
        checkFinite(id, i, "axisV", d.axisV);
    }

    void check(uint32_t id, size_t i, const DiskBspPlane& d, const CompiledLevel&) const {
        const double length = glm::length(glm::dvec3(d.normal[0], d.normal[1], d.normal[2]));
        if (!std::isfinite(length) || std::abs(length - 1.0) > 1e-6)
            fail(id, i, "normal has length " + std::to_string(length) + "; expected unit length");
        if (!std::isfinite(d.distance)) fail(id, i, "distance is NaN or Inf");
    }

    void loadBsp(CompiledLevel& level) {
        load<DiskBspPlane>(kSectionBspPlanes, level, level.bspPlanes);
        const auto leaves = records<DiskBspLeaf>(kSectionBspLeaves);
        const auto nodes = records<DiskBspNode>(kSectionBspNodes);
        if (leaves.empty()) fail("section bsp_leaves: empty; expected at least one leaf");
        if (nodes.empty() && leaves.size() != 1)
            fail("section bsp_leaves: " + std::to_string(leaves.size()) +
                 " leaves without nodes; expected 1");
        const size_t triangles = level.indices.size() / 3;
        std::vector<uint8_t> leafUsed(leaves.size(), 0);
        for (size_t i = 0; i < nodes.size(); ++i) {
            const DiskBspNode& d = nodes[i];
            checkIndex(kSectionBspNodes, i, "plane", d.plane, level.bspPlanes.size(), "planes",
                       false);
            checkFinite(kSectionBspNodes, i, "boundsMin", d.boundsMin);
            checkFinite(kSectionBspNodes, i, "boundsMax", d.boundsMax);
            for (const int32_t child : {d.front, d.back}) {
                if (child >= 0) {
                    // Children come after their parent: no cycles, every walk ends.
                    if (static_cast<size_t>(child) <= i ||
                        static_cast<size_t>(child) >= nodes.size())
                        fail(kSectionBspNodes, i,
                             "child node " + std::to_string(child) + " is out of range (after " +
                                 std::to_string(i) + ", below " + std::to_string(nodes.size()) +
                                 ")");
                } else {
                    const uint64_t leaf = static_cast<uint64_t>(-(int64_t(child) + 1));
                    if (leaf >= leaves.size())
                        fail(kSectionBspNodes, i,
                             "child leaf " + std::to_string(leaf) + " is out of range (" +
                                 std::to_string(leaves.size()) + " leaves)");
                    if (leafUsed[leaf]++)
                        fail(kSectionBspNodes, i,
                             "leaf " + std::to_string(leaf) + " has two parents");
                }
            }
            level.bspNodes.push_back(fromDisk(d));
        }
        for (size_t i = 0; i < leaves.size(); ++i) {
            const DiskBspLeaf& d = leaves[i];
            checkRange(kSectionBspLeaves, i, "triangles", d.firstTriangle, d.triangleCount,
                       triangles, "triangles");
            checkFinite(kSectionBspLeaves, i, "boundsMin", d.boundsMin);
            checkFinite(kSectionBspLeaves, i, "boundsMax", d.boundsMax);
            if (!nodes.empty() && !leafUsed[i])
                fail(kSectionBspLeaves, i, "no node refers to this leaf");
            level.bspLeaves.push_back(fromDisk(d));
        }
    }

    void loadGivenUp(CompiledLevel& level) {
        level.givenUpLights = loadU32(kSectionGivenUpLights);
        for (size_t i = 0; i < level.givenUpLights.size(); ++i)
            checkIndex(kSectionGivenUpLights, i, "light", level.givenUpLights[i],
                       level.lights.size(), "lights", false);
    }

    void check(uint32_t id, size_t i, const DiskSurface& d, const CompiledLevel& level) const {
        if (d.firstIndex % 3 != 0 || d.indexCount % 3 != 0 || d.indexCount == 0)
            fail(id, i,
                 "index range [" + std::to_string(d.firstIndex) + ", +" +
                     std::to_string(d.indexCount) + "); expected non-empty whole triangles");
        checkRange(id, i, "indices", d.firstIndex, d.indexCount, level.indices.size(), "indices");
        checkIndex(id, i, "material", d.material, level.materials.size(), "materials", false);
        checkIndex(id, i, "primaryLight", d.primaryLight, level.lights.size(), "lights", true);
        if (d.primaryLight != kNoIndex && level.lights[d.primaryLight].role != LightRole::kPrimary)
            fail(id, i,
                 "primaryLight " + std::to_string(d.primaryLight) + " is not a primary light");
        checkIndex(id, i, "chart", d.chart, level.charts.size(), "charts", false);
        const Chart& c = level.charts[d.chart];
        const std::string chart = "chart " + std::to_string(d.chart) + "'s ";
        checkEqual(id, i, "atlas", d.atlas, c.atlas, chart + "atlas");
        checkEqual(id, i, "lightmapX", d.lightmapX, c.x, chart + "x");
        checkEqual(id, i, "lightmapY", d.lightmapY, c.y, chart + "y");
        checkEqual(id, i, "lightmapWidth", d.lightmapWidth, c.width, chart + "width");
        checkEqual(id, i, "lightmapHeight", d.lightmapHeight, c.height, chart + "height");
        checkRange(id, i, "given-up lights", d.firstGivenUp, d.givenUpCount,
                   level.givenUpLights.size(), "given-up lights");
        checkIndex(id, i, "leaf", d.leaf, level.bspLeaves.size(), "leaves", false);
        checkFinite(id, i, "boundsMin", d.boundsMin);
        checkFinite(id, i, "boundsMax", d.boundsMax);
    }

    void checkLeavesAgainstSurfaces(const CompiledLevel& level) const {
        for (size_t i = 0; i < level.bspLeaves.size(); ++i) {
            const BspLeaf& l = level.bspLeaves[i];
            checkRange(kSectionBspLeaves, i, "surfaces", l.firstSurface, l.surfaceCount,
                       level.surfaces.size(), "surfaces");
            for (uint32_t s = l.firstSurface; s < l.firstSurface + l.surfaceCount; ++s)
                if (level.surfaces[s].leaf != i)
                    fail(kSectionBspLeaves, i,
                         "surface " + std::to_string(s) + " belongs to leaf " +
                             std::to_string(level.surfaces[s].leaf));
        }
    }

    void check(uint32_t id, size_t i, const DiskDynamicMesh& d, const CompiledLevel& level) const {
        checkString(id, i, "name", d.name);
        checkIndex(id, i, "material", d.material, level.materials.size(), "materials", false);
        checkRange(id, i, "vertices", d.firstVertex, d.vertexCount, level.dynamicVertices.size(),
                   "dynamic vertices");
        if (d.firstIndex % 3 != 0 || d.indexCount % 3 != 0)
            fail(id, i, "index range is not whole triangles");
        checkRange(id, i, "indices", d.firstIndex, d.indexCount, level.dynamicIndices.size(),
                   "dynamic indices");
        for (uint32_t k = d.firstIndex; k < d.firstIndex + d.indexCount; ++k)
            checkIndex(id, i, "index", level.dynamicIndices[k], d.vertexCount,
                       "vertices in the mesh", false);
    }

    void check(uint32_t id, size_t i, const DiskEntity& d, const CompiledLevel& level) const {
        checkString(id, i, "name", d.name);
        if (d.flags & ~kAllEntityFlags)
            fail(id, i, "flags " + std::to_string(d.flags) + " has unknown bits");
        checkRange(id, i, "dynamic meshes", d.firstDynamicMesh, d.dynamicMeshCount,
                   level.dynamicMeshes.size(), "dynamic meshes");
        checkFinite(id, i, "position", d.position);
        checkFinite(id, i, "rotation", d.rotation);
        checkFinite(id, i, "scale", d.scale);
        checkFinite(id, i, "probeBoxMin", d.probeBoxMin);
        checkFinite(id, i, "probeBoxMax", d.probeBoxMax);
        checkFinite(id, i, "itemRespawn", d.itemRespawn);
    }

    void check(uint32_t id, size_t i, const DiskMoverPoint& d, const CompiledLevel&) const {
        checkFinite(id, i, "position", d.position);
        if (!(d.wait >= 0.0f) || !std::isfinite(d.wait))
            fail(id, i, "wait " + std::to_string(d.wait) + "; expected seconds >= 0");
        if (!(d.legSeconds > 0.0f) || !std::isfinite(d.legSeconds))
            fail(id, i, "legSeconds " + std::to_string(d.legSeconds) + "; expected seconds > 0");
    }

    void check(uint32_t id, size_t i, const DiskMover& d, const CompiledLevel& level) const {
        checkIndex(id, i, "entity", d.entity, level.entities.size(), "entities", false);
        if (!(level.entities[d.entity].flags & kEntityMover))
            fail(id, i, "entity " + std::to_string(d.entity) + " is not flagged as moved");
        if (d.kind >= kMoverKindCount)
            fail(id, i,
                 "kind " + std::to_string(d.kind) + "; expected 0 .. " +
                     std::to_string(kMoverKindCount - 1));
        if (d.flags & ~kAllMoverFlags)
            fail(id, i, "flags " + std::to_string(d.flags) + " has unknown bits");
        checkFinite(id, i, "pos1", d.pos1);
        checkFinite(id, i, "pos2", d.pos2);
        checkFinite(id, i, "amplitude", d.amplitude);
        checkFinite(id, i, "axis", d.axis);
        const float axisLength =
            std::sqrt(d.axis[0] * d.axis[0] + d.axis[1] * d.axis[1] + d.axis[2] * d.axis[2]);
        if (!(std::fabs(axisLength - 1.0f) <= 1e-3f))
            fail(id, i, "axis of length " + std::to_string(axisLength) + "; expected 1");
        checkFinite(id, i, "speed", d.speed);
        checkFinite(id, i, "period", d.period);
        checkFinite(id, i, "phase", d.phase);
        checkFinite(id, i, "travelSeconds", d.travelSeconds);
        checkFinite(id, i, "wait", d.wait);
        const MoverKind kind = MoverKind(d.kind);
        if ((kind == MoverKind::kShuttle || kind == MoverKind::kBobbing ||
             kind == MoverKind::kPendulum) &&
            !(d.period > 0.0f))
            fail(id, i, "period " + std::to_string(d.period) + "; expected seconds > 0");
        if (isBinaryMover(kind) && !(d.travelSeconds > 0.0f))
            fail(id, i,
                 "travelSeconds " + std::to_string(d.travelSeconds) + "; expected seconds > 0");
        checkRange(id, i, "points", d.firstPoint, d.pointCount, level.movers.path.size(),
                   "mover points");
        if ((kind == MoverKind::kTrain) != (d.pointCount >= 2))
            fail(id, i,
                 std::to_string(d.pointCount) +
                     " points; expected at least 2 for a train (kind 7), none otherwise");
        if (d.reserved != 0) fail(id, i, "reserved " + std::to_string(d.reserved) + "; expected 0");
    }

    /// Across the movers: one mover an entity, every team master its own master.
    void checkMoverLinks(const CompiledLevel& level) const {
        std::vector<bool> moved(level.entities.size(), false);
        const std::vector<Mover>& movers = level.movers.movers;
        for (size_t i = 0; i < movers.size(); ++i) {
            if (moved[movers[i].entity])
                fail(kSectionMovers, i,
                     "entity " + std::to_string(movers[i].entity) + " has a mover already");
            moved[movers[i].entity] = true;
            const uint32_t master = movers[i].teamMaster;
            if (master != kNoIndex &&
                (master >= movers.size() || master == i || movers[master].teamMaster != kNoIndex))
                fail(kSectionMovers, i,
                     "teamMaster " + std::to_string(master) + " of " +
                         std::to_string(movers.size()) +
                         " movers; expected another mover whose teamMaster is none");
        }
    }

    void check(uint32_t id, size_t i, const DiskFeatures& d) const {
        checkFinite(id, i, "gridMin", d.gridMin);
        checkFinite(id, i, "gridMax", d.gridMax);
    }

    std::span<const uint8_t> bytes_;
    const std::string& name_;
    std::array<SectionEntry, kCoreSectionCount> entries_{};
    std::array<const SectionEntry*, kCoreSectionCount> core_{};
    std::array<bool, kSectionIdLimit - kSectionLightmapTexels> bakedSeen_{};
    BlobReader blobs_;
};

}  // namespace

bool isPathBesideThePackage(std::string_view uri) {
    if (uri.empty() || uri.front() == '/') return false;
    if (uri.find('\\') != std::string_view::npos || uri.find(':') != std::string_view::npos ||
        uri.find('\0') != std::string_view::npos)
        return false;
    size_t start = 0;
    while (start <= uri.size()) {
        size_t end = uri.find('/', start);
        if (end == std::string_view::npos) end = uri.size();
        const std::string_view part = uri.substr(start, end - start);
        if (part == ".." || part.empty()) return false;
        start = end + 1;
    }
    return true;
}

PackageContents parsePackage(std::span<const uint8_t> bytes, const std::string& name) {
    PackageContents contents;
    try {
        Reader(bytes, name).read(contents);
        // The collision sections belong to the level: decoded, not kept raw.
        const RawSection* brushes = nullptr;
        const RawSection* triggers = nullptr;
        for (const RawSection& raw : contents.bakedSections) {
            if (raw.id == kSectionCollision) brushes = &raw;
            if (raw.id == kSectionTriggers) triggers = &raw;
        }
        contents.level.collision = decodeCollisionSections(
            brushes, triggers, uint32_t(contents.level.movers.movers.size()), name);
        std::erase_if(contents.bakedSections, [](const RawSection& raw) {
            return raw.id == kSectionCollision || raw.id == kSectionTriggers;
        });
    } catch (const std::bad_alloc&) {
        throw world::Error(name + ": out of memory while reading");
    }
    return contents;
}

PackageContents readPackageFile(const std::string& path) {
    const std::vector<uint8_t> bytes = world::readRegularFile(path, "a .olpak package");
    return parsePackage(bytes, path);
}

}  // namespace onelight::package
