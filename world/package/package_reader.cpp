#include "world/package/package_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "world/error.hpp"
#include "world/package/crc32.hpp"
#include "world/package/format.hpp"
#include "world/package/records.hpp"

namespace onelight::package {
namespace {

using namespace onelight::world;

const char* section_name(uint32_t id) {
    static constexpr std::array<const char*, core_section_count> names{
        "strings",     "level",           "materials",        "textures",        "images",
        "image_bytes", "lights",          "cameras",          "vertices",        "indices",
        "surfaces",    "given_up_lights", "charts",           "atlases",         "bsp_planes",
        "bsp_nodes",   "bsp_leaves",      "dynamic_vertices", "dynamic_indices", "dynamic_meshes",
        "entities",    "features"};
    return id < core_section_count ? names[id] : "baked";
}

uint32_t expected_element_size(uint32_t id) {
    switch (id) {
        case section_strings:
            return 1;
        case section_level:
            return sizeof(DiskLevel);
        case section_materials:
            return sizeof(DiskMaterial);
        case section_textures:
            return sizeof(DiskTexture);
        case section_images:
            return sizeof(DiskImage);
        case section_image_bytes:
            return 1;
        case section_lights:
            return sizeof(DiskLight);
        case section_cameras:
            return sizeof(DiskCamera);
        case section_vertices:
            return sizeof(DiskVertex);
        case section_indices:
            return sizeof(uint32_t);
        case section_surfaces:
            return sizeof(DiskSurface);
        case section_given_up_lights:
            return sizeof(uint32_t);
        case section_charts:
            return sizeof(DiskChart);
        case section_atlases:
            return sizeof(DiskAtlas);
        case section_bsp_planes:
            return sizeof(DiskBspPlane);
        case section_bsp_nodes:
            return sizeof(DiskBspNode);
        case section_bsp_leaves:
            return sizeof(DiskBspLeaf);
        case section_dynamic_vertices:
            return sizeof(DiskVertex);
        case section_dynamic_indices:
            return sizeof(uint32_t);
        case section_dynamic_meshes:
            return sizeof(DiskDynamicMesh);
        case section_entities:
            return sizeof(DiskEntity);
        case section_features:
            return sizeof(DiskFeatures);
        default:
            return 0;
    }
}

class Reader {
public:
    Reader(std::span<const uint8_t> bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    void read(PackageContents& out) {
        read_header_and_table(out);
        CompiledLevel& level = out.level;
        load_blobs();
        level.settings = from_disk(single<DiskLevel>(section_level));
        load<DiskImage>(section_images, level, level.images);  // before textures: they index images
        load<DiskTexture>(section_textures, level, level.textures);
        load<DiskMaterial>(section_materials, level, level.materials);
        load<DiskLight>(section_lights, level, level.lights);
        load<DiskCamera>(section_cameras, level, level.cameras);
        load<DiskVertex>(section_vertices, level, level.vertices);
        level.indices = load_indices(section_indices, level.vertices.size(), "vertices");
        load<DiskAtlas>(section_atlases, level, level.atlases);
        load<DiskChart>(section_charts, level, level.charts);
        load_bsp(level);
        load_given_up(level);
        load<DiskSurface>(section_surfaces, level, level.surfaces);
        check_leaves_against_surfaces(level);
        load<DiskVertex>(section_dynamic_vertices, level, level.dynamic_vertices);
        level.dynamic_indices = load_u32(section_dynamic_indices);
        load<DiskDynamicMesh>(section_dynamic_meshes, level, level.dynamic_meshes);
        load<DiskEntity>(section_entities, level, level.entities);
        level.features = from_disk(single<DiskFeatures>(section_features));
    }

private:
    [[noreturn]] void fail(const std::string& message) const {
        throw world::Error(name_ + ": " + message);
    }
    [[noreturn]] void fail(uint32_t id, size_t record, const std::string& message) const {
        fail(std::string("section ") + section_name(id) + " record " + std::to_string(record) +
             ": " + message);
    }

    void read_header_and_table(PackageContents& out) {
        if (bytes_.size() < sizeof(FileHeader))
            fail("file is " + std::to_string(bytes_.size()) + " bytes; expected at least a " +
                 std::to_string(sizeof(FileHeader)) + "-byte header");
        FileHeader header;
        std::memcpy(&header, bytes_.data(), sizeof header);
        if (header.magic != kMagic) fail("bad magic; expected an .olpak file (\"OLPK\")");
        if (header.version != kVersion)
            fail("version " + std::to_string(header.version) + "; this reader reads version " +
                 std::to_string(kVersion));
        if (header.header_size != sizeof(FileHeader))
            fail("header size " + std::to_string(header.header_size) + "; expected " +
                 std::to_string(sizeof(FileHeader)));
        if (header.file_size != bytes_.size())
            fail("header says " + std::to_string(header.file_size) + " bytes but the file has " +
                 std::to_string(bytes_.size()) + " (truncated or padded)");
        if (header.section_count < core_section_count || header.section_count > kMaxSections)
            fail("section count " + std::to_string(header.section_count) + "; expected " +
                 std::to_string(core_section_count) + " to " + std::to_string(kMaxSections));
        const uint64_t table_end =
            sizeof(FileHeader) + uint64_t(header.section_count) * sizeof(SectionEntry);
        if (table_end > bytes_.size()) fail("section table runs past the end of the file");
        if (header.reserved != 0)
            fail("header reserved field is " + std::to_string(header.reserved) + "; expected 0");
        const uint32_t stored_crc = header.table_crc32;
        FileHeader zeroed = header;
        zeroed.table_crc32 = 0;
        uint32_t crc = crc32(&zeroed, sizeof zeroed);
        crc = crc32(bytes_.data() + sizeof(FileHeader), table_end - sizeof(FileHeader), crc);
        if (crc != stored_crc) fail("header/section table CRC32 mismatch; the file is corrupt");

        for (uint32_t i = 0; i < header.section_count; ++i) {
            SectionEntry e;
            std::memcpy(&e, bytes_.data() + sizeof(FileHeader) + i * sizeof(SectionEntry),
                        sizeof e);
            const std::string where =
                "section table entry " + std::to_string(i) + " (id " + std::to_string(e.id) + ")";
            if (e.id >= section_id_limit ||
                (e.id >= core_section_count && e.id < section_lightmap_texels))
                fail(where + ": unknown section id");
            if (e.id < core_section_count ? core_[e.id] != nullptr
                                          : baked_seen_[e.id - section_lightmap_texels])
                fail(where + ": section appears twice");
            if (e.offset % kSectionAlignment != 0 || e.offset < table_end ||
                e.offset > bytes_.size() || e.size > bytes_.size() - e.offset)
                fail(where + ": bytes [" + std::to_string(e.offset) + ", +" +
                     std::to_string(e.size) + ") are outside the file's payload");
            if (e.element_size == 0 || uint64_t(e.count) * e.element_size != e.size)
                fail(where + ": count " + std::to_string(e.count) + " x element size " +
                     std::to_string(e.element_size) + " != size " + std::to_string(e.size));
            if (e.id < core_section_count && e.element_size != expected_element_size(e.id))
                fail(std::string("section ") + section_name(e.id) + ": record size " +
                     std::to_string(e.element_size) + "; expected " +
                     std::to_string(expected_element_size(e.id)));
            if (crc32(bytes_.data() + e.offset, e.size) != e.crc32)
                fail(std::string("section ") + section_name(e.id) +
                     ": CRC32 mismatch; the file is corrupt");
            if (e.id < core_section_count) {
                entries_[e.id] = e;
                core_[e.id] = &entries_[e.id];
            } else {
                baked_seen_[e.id - section_lightmap_texels] = true;
                RawSection raw;
                raw.id = e.id;
                raw.element_size = e.element_size;
                raw.count = e.count;
                raw.bytes.assign(bytes_.begin() + static_cast<std::ptrdiff_t>(e.offset),
                                 bytes_.begin() + static_cast<std::ptrdiff_t>(e.offset + e.size));
                out.baked_sections.push_back(std::move(raw));
            }
        }
        for (uint32_t id = 0; id < core_section_count; ++id)
            if (!core_[id]) fail(std::string("section ") + section_name(id) + " is missing");
    }

    template <typename T>
    std::vector<T> records(uint32_t id) const {
        const SectionEntry& e = *core_[id];
        std::vector<T> out(e.count);
        if (e.size > 0) std::memcpy(out.data(), bytes_.data() + e.offset, e.size);
        return out;
    }

    std::vector<uint32_t> load_u32(uint32_t id) const { return records<uint32_t>(id); }

    void load_blobs() {
        const SectionEntry& strings = *core_[section_strings];
        const SectionEntry& image_bytes = *core_[section_image_bytes];
        blobs_.strings = bytes_.subspan(strings.offset, strings.size);
        blobs_.image_bytes = bytes_.subspan(image_bytes.offset, image_bytes.size);
    }

    /// Section `id`'s records, each checked, then mapped by from_disk into `out`.
    template <typename Disk, typename Item>
    void load(uint32_t id, const CompiledLevel& level, std::vector<Item>& out) const {
        const auto r = records<Disk>(id);
        out.reserve(r.size());
        for (size_t i = 0; i < r.size(); ++i) {
            check(id, i, r[i], level);
            if constexpr (requires { from_disk(r[i], blobs_); })
                out.push_back(from_disk(r[i], blobs_));
            else
                out.push_back(from_disk(r[i]));
        }
    }

    /// The one record of section `id` (level, features), checked.
    template <typename Disk>
    Disk single(uint32_t id) const {
        const auto r = records<Disk>(id);
        if (r.size() != 1)
            fail(std::string("section ") + section_name(id) + ": " + std::to_string(r.size()) +
                 " records; expected 1");
        check(id, 0, r[0]);
        return r[0];
    }

    void check_string(uint32_t id, size_t record, const char* field, const StringRef& ref) const {
        const size_t size = blobs_.strings.size();
        if (ref.offset > size || ref.length > size - ref.offset)
            fail(id, record,
                 std::string(field) + " string [" + std::to_string(ref.offset) + ", +" +
                     std::to_string(ref.length) + ") is outside the strings section (" +
                     std::to_string(size) + " bytes)");
    }

    void check_index(uint32_t id, size_t record, const char* field, uint32_t value, size_t limit,
                     const char* target, bool none_allowed) const {
        if (none_allowed && value == kNoIndex) return;
        if (value >= limit)
            fail(id, record,
                 std::string(field) + " " + std::to_string(value) + " is out of range (" +
                     std::to_string(limit) + " " + target + ")");
    }

    void check_range(uint32_t id, size_t record, const char* field, uint64_t first, uint64_t count,
                     size_t limit, const char* target) const {
        if (first > limit || count > limit - first)
            fail(id, record,
                 std::string(field) + " [" + std::to_string(first) + ", +" + std::to_string(count) +
                     ") is out of range (" + std::to_string(limit) + " " + target + ")");
    }

    /// Rejects a NaN or Inf in the float field `field`.
    void check_finite(uint32_t id, size_t record, const char* field, float v) const {
        if (!std::isfinite(v)) fail(id, record, std::string(field) + " is NaN or Inf");
    }

    /// Rejects a NaN or Inf in the array field `field`, naming the element.
    template <size_t N>
    void check_finite(uint32_t id, size_t record, const char* field, const float (&v)[N]) const {
        for (size_t k = 0; k < N; ++k)
            if (!std::isfinite(v[k]))
                fail(id, record, std::string(field) + "[" + std::to_string(k) + "] is NaN or Inf");
    }

    /// Rejects `value` unless it is `expected`, the value of `source`.
    void check_equal(uint32_t id, size_t record, const char* field, uint32_t value,
                     uint32_t expected, const std::string& source) const {
        if (value != expected)
            fail(id, record,
                 std::string(field) + " " + std::to_string(value) + "; expected " +
                     std::to_string(expected) + ", " + source);
    }

    void check(uint32_t id, size_t i, const DiskLevel& d) const {
        check_finite(id, i, "exposure_ev100", d.exposure_ev100);
        check_finite(id, i, "bounds_min", d.bounds_min);
        check_finite(id, i, "bounds_max", d.bounds_max);
        if (!(d.texels_per_metre > 0.0f) || !std::isfinite(d.texels_per_metre))
            fail(id, i,
                 "texels_per_metre " + std::to_string(d.texels_per_metre) + "; expected > 0");
        if (!(d.probe_spacing >= 0.0f) || !std::isfinite(d.probe_spacing))
            fail(id, i,
                 "probe_spacing " + std::to_string(d.probe_spacing) + "; expected metres >= 0");
        check_finite(id, i, "sky_radiance", d.sky_radiance);
        if (!(std::min({d.sky_radiance[0], d.sky_radiance[1], d.sky_radiance[2]}) >= 0.0f))
            fail(id, i, "sky_radiance negative; expected cd/m^2 >= 0");
        if (d.reserved != 0) fail(id, i, "reserved " + std::to_string(d.reserved) + "; expected 0");
    }

    void check(uint32_t id, size_t i, const DiskImage& d, const CompiledLevel&) const {
        check_string(id, i, "name", d.name);
        check_string(id, i, "uri", d.uri);
        check_string(id, i, "mime_type", d.mime_type);
        check_range(id, i, "bytes", d.first_byte, d.byte_count, blobs_.image_bytes.size(),
                    "image bytes");
        if ((d.uri.length == 0) == (d.byte_count == 0))
            fail(id, i, "expected either a uri or embedded bytes, not both or neither");
    }

    void check(uint32_t id, size_t i, const DiskTexture& d, const CompiledLevel& level) const {
        check_index(id, i, "image", d.image, level.images.size(), "images", true);
    }

    void check(uint32_t id, size_t i, const DiskMaterial& d, const CompiledLevel& level) const {
        check_string(id, i, "name", d.name);
        check_finite(id, i, "base_color", d.base_color);
        check_finite(id, i, "metallic", d.metallic);
        check_finite(id, i, "roughness", d.roughness);
        check_finite(id, i, "albedo", d.albedo);
        check_finite(id, i, "specular_color", d.specular_color);
        check_finite(id, i, "gloss", d.gloss);
        check_finite(id, i, "emissive", d.emissive);
        check_finite(id, i, "alpha_cutoff", d.alpha_cutoff);
        check_finite(id, i, "normal_scale", d.normal_scale);
        check_finite(id, i, "occlusion_strength", d.occlusion_strength);
        const size_t textures = level.textures.size();
        check_index(id, i, "base_color_texture", d.base_color_texture, textures, "textures", true);
        check_index(id, i, "metallic_roughness_texture", d.metallic_roughness_texture, textures,
                    "textures", true);
        check_index(id, i, "normal_texture", d.normal_texture, textures, "textures", true);
        check_index(id, i, "occlusion_texture", d.occlusion_texture, textures, "textures", true);
        check_index(id, i, "emissive_texture", d.emissive_texture, textures, "textures", true);
        if (d.alpha_mode > 2)
            fail(id, i, "alpha_mode " + std::to_string(d.alpha_mode) + "; expected 0..2");
        if (d.material_class > 3)
            fail(id, i, "material_class " + std::to_string(d.material_class) + "; expected 0..3");
        if (d.gloss < 0.0f || d.gloss > 1.0f)
            fail(id, i, "gloss " + std::to_string(d.gloss) + "; expected [0, 1]");
    }

    void check(uint32_t id, size_t i, const DiskLight& d, const CompiledLevel&) const {
        check_string(id, i, "name", d.name);
        if (d.type > 2) fail(id, i, "type " + std::to_string(d.type) + "; expected 0..2");
        if (d.role > 2) fail(id, i, "role " + std::to_string(d.role) + "; expected 0..2");
        check_finite(id, i, "color", d.color);
        check_finite(id, i, "position", d.position);
        check_finite(id, i, "direction", d.direction);
        if (!(d.intensity >= 0.0f) || !std::isfinite(d.intensity))
            fail(id, i, "intensity " + std::to_string(d.intensity) + "; expected finite >= 0");
        if (!(d.range >= 0.0f) || !std::isfinite(d.range))
            fail(id, i, "range " + std::to_string(d.range) + "; expected finite >= 0");
        if (!(d.inner_cone >= 0.0f && d.inner_cone <= d.outer_cone && d.outer_cone <= 1.5708f))
            fail(id, i, "cone angles; expected 0 <= inner <= outer <= pi/2");
    }

    void check(uint32_t id, size_t i, const DiskCamera& d, const CompiledLevel&) const {
        check_string(id, i, "name", d.name);
        check_finite(id, i, "yfov", d.yfov);
        check_finite(id, i, "aspect_ratio", d.aspect_ratio);
        check_finite(id, i, "znear", d.znear);
        check_finite(id, i, "zfar", d.zfar);
        check_finite(id, i, "xmag", d.xmag);
        check_finite(id, i, "ymag", d.ymag);
        check_finite(id, i, "position", d.position);
        check_finite(id, i, "rotation", d.rotation);
        check_finite(id, i, "exposure_ev100", d.exposure_ev100);
    }

    void check(uint32_t id, size_t i, const DiskVertex& d, const CompiledLevel&) const {
        check_finite(id, i, "position", d.position);
        check_finite(id, i, "normal", d.normal);
        check_finite(id, i, "tangent", d.tangent);
        check_finite(id, i, "uv0", d.uv0);
        check_finite(id, i, "uv1", d.uv1);
    }

    std::vector<uint32_t> load_indices(uint32_t id, size_t vertex_count, const char* target) const {
        std::vector<uint32_t> out = load_u32(id);
        if (out.size() % 3 != 0)
            fail(std::string("section ") + section_name(id) + ": " + std::to_string(out.size()) +
                 " indices; expected a multiple of 3");
        for (size_t i = 0; i < out.size(); ++i)
            check_index(id, i, "index", out[i], vertex_count, target, false);
        return out;
    }

    void check(uint32_t id, size_t i, const DiskAtlas& d, const CompiledLevel&) const {
        if (d.width == 0 || d.height == 0 || d.width > 65536 || d.height > 65536)
            fail(id, i,
                 "size " + std::to_string(d.width) + "x" + std::to_string(d.height) +
                     "; expected 1..65536 texels per side");
    }

    void check(uint32_t id, size_t i, const DiskChart& d, const CompiledLevel& level) const {
        check_index(id, i, "atlas", d.atlas, level.atlases.size(), "atlases", false);
        const Atlas& a = level.atlases[d.atlas];
        check_range(id, i, "x", d.x, d.width, a.width, "texels of atlas width");
        check_range(id, i, "y", d.y, d.height, a.height, "texels of atlas height");
        if (uint64_t(2) * d.padding >= d.width || uint64_t(2) * d.padding >= d.height)
            fail(id, i,
                 "padding " + std::to_string(d.padding) + " leaves no room in the rectangle");
        check_finite(id, i, "texels_per_metre", d.texels_per_metre);
        check_finite(id, i, "origin", d.origin);
        check_finite(id, i, "axis_u", d.axis_u);
        check_finite(id, i, "axis_v", d.axis_v);
    }

    void check(uint32_t id, size_t i, const DiskBspPlane& d, const CompiledLevel&) const {
        const double length = glm::length(glm::dvec3(d.normal[0], d.normal[1], d.normal[2]));
        if (!std::isfinite(length) || std::abs(length - 1.0) > 1e-6)
            fail(id, i, "normal has length " + std::to_string(length) + "; expected unit length");
        if (!std::isfinite(d.distance)) fail(id, i, "distance is NaN or Inf");
    }

    void load_bsp(CompiledLevel& level) {
        load<DiskBspPlane>(section_bsp_planes, level, level.bsp_planes);
        const auto leaves = records<DiskBspLeaf>(section_bsp_leaves);
        const auto nodes = records<DiskBspNode>(section_bsp_nodes);
        if (leaves.empty()) fail("section bsp_leaves: empty; expected at least one leaf");
        if (nodes.empty() && leaves.size() != 1)
            fail("section bsp_leaves: " + std::to_string(leaves.size()) +
                 " leaves without nodes; expected 1");
        const size_t triangles = level.indices.size() / 3;
        std::vector<uint8_t> leaf_used(leaves.size(), 0);
        for (size_t i = 0; i < nodes.size(); ++i) {
            const DiskBspNode& d = nodes[i];
            check_index(section_bsp_nodes, i, "plane", d.plane, level.bsp_planes.size(), "planes",
                        false);
            check_finite(section_bsp_nodes, i, "bounds_min", d.bounds_min);
            check_finite(section_bsp_nodes, i, "bounds_max", d.bounds_max);
            for (const int32_t child : {d.front, d.back}) {
                if (child >= 0) {
                    // Children come after their parent: no cycles, every walk ends.
                    if (static_cast<size_t>(child) <= i ||
                        static_cast<size_t>(child) >= nodes.size())
                        fail(section_bsp_nodes, i,
                             "child node " + std::to_string(child) + " is out of range (after " +
                                 std::to_string(i) + ", below " + std::to_string(nodes.size()) +
                                 ")");
                } else {
                    const uint64_t leaf = static_cast<uint64_t>(-(int64_t(child) + 1));
                    if (leaf >= leaves.size())
                        fail(section_bsp_nodes, i,
                             "child leaf " + std::to_string(leaf) + " is out of range (" +
                                 std::to_string(leaves.size()) + " leaves)");
                    if (leaf_used[leaf]++)
                        fail(section_bsp_nodes, i,
                             "leaf " + std::to_string(leaf) + " has two parents");
                }
            }
            level.bsp_nodes.push_back(from_disk(d));
        }
        for (size_t i = 0; i < leaves.size(); ++i) {
            const DiskBspLeaf& d = leaves[i];
            check_range(section_bsp_leaves, i, "triangles", d.first_triangle, d.triangle_count,
                        triangles, "triangles");
            check_finite(section_bsp_leaves, i, "bounds_min", d.bounds_min);
            check_finite(section_bsp_leaves, i, "bounds_max", d.bounds_max);
            if (!nodes.empty() && !leaf_used[i])
                fail(section_bsp_leaves, i, "no node refers to this leaf");
            level.bsp_leaves.push_back(from_disk(d));
        }
    }

    void load_given_up(CompiledLevel& level) {
        level.given_up_lights = load_u32(section_given_up_lights);
        for (size_t i = 0; i < level.given_up_lights.size(); ++i)
            check_index(section_given_up_lights, i, "light", level.given_up_lights[i],
                        level.lights.size(), "lights", false);
    }

    void check(uint32_t id, size_t i, const DiskSurface& d, const CompiledLevel& level) const {
        if (d.first_index % 3 != 0 || d.index_count % 3 != 0 || d.index_count == 0)
            fail(id, i,
                 "index range [" + std::to_string(d.first_index) + ", +" +
                     std::to_string(d.index_count) + "); expected non-empty whole triangles");
        check_range(id, i, "indices", d.first_index, d.index_count, level.indices.size(),
                    "indices");
        check_index(id, i, "material", d.material, level.materials.size(), "materials", false);
        check_index(id, i, "primary_light", d.primary_light, level.lights.size(), "lights", true);
        if (d.primary_light != kNoIndex && level.lights[d.primary_light].role != LightRole::primary)
            fail(id, i,
                 "primary_light " + std::to_string(d.primary_light) + " is not a primary light");
        check_index(id, i, "chart", d.chart, level.charts.size(), "charts", false);
        const Chart& c = level.charts[d.chart];
        const std::string chart = "chart " + std::to_string(d.chart) + "'s ";
        check_equal(id, i, "atlas", d.atlas, c.atlas, chart + "atlas");
        check_equal(id, i, "lightmap_x", d.lightmap_x, c.x, chart + "x");
        check_equal(id, i, "lightmap_y", d.lightmap_y, c.y, chart + "y");
        check_equal(id, i, "lightmap_width", d.lightmap_width, c.width, chart + "width");
        check_equal(id, i, "lightmap_height", d.lightmap_height, c.height, chart + "height");
        check_range(id, i, "given-up lights", d.first_given_up, d.given_up_count,
                    level.given_up_lights.size(), "given-up lights");
        check_index(id, i, "leaf", d.leaf, level.bsp_leaves.size(), "leaves", false);
        check_finite(id, i, "bounds_min", d.bounds_min);
        check_finite(id, i, "bounds_max", d.bounds_max);
    }

    void check_leaves_against_surfaces(const CompiledLevel& level) const {
        for (size_t i = 0; i < level.bsp_leaves.size(); ++i) {
            const BspLeaf& l = level.bsp_leaves[i];
            check_range(section_bsp_leaves, i, "surfaces", l.first_surface, l.surface_count,
                        level.surfaces.size(), "surfaces");
            for (uint32_t s = l.first_surface; s < l.first_surface + l.surface_count; ++s)
                if (level.surfaces[s].leaf != i)
                    fail(section_bsp_leaves, i,
                         "surface " + std::to_string(s) + " belongs to leaf " +
                             std::to_string(level.surfaces[s].leaf));
        }
    }

    void check(uint32_t id, size_t i, const DiskDynamicMesh& d, const CompiledLevel& level) const {
        check_string(id, i, "name", d.name);
        check_index(id, i, "material", d.material, level.materials.size(), "materials", false);
        check_range(id, i, "vertices", d.first_vertex, d.vertex_count,
                    level.dynamic_vertices.size(), "dynamic vertices");
        if (d.first_index % 3 != 0 || d.index_count % 3 != 0)
            fail(id, i, "index range is not whole triangles");
        check_range(id, i, "indices", d.first_index, d.index_count, level.dynamic_indices.size(),
                    "dynamic indices");
        for (uint32_t k = d.first_index; k < d.first_index + d.index_count; ++k)
            check_index(id, i, "index", level.dynamic_indices[k], d.vertex_count,
                        "vertices in the mesh", false);
    }

    void check(uint32_t id, size_t i, const DiskEntity& d, const CompiledLevel& level) const {
        check_string(id, i, "name", d.name);
        if (d.flags & ~kAllEntityFlags)
            fail(id, i, "flags " + std::to_string(d.flags) + " has unknown bits");
        check_range(id, i, "dynamic meshes", d.first_dynamic_mesh, d.dynamic_mesh_count,
                    level.dynamic_meshes.size(), "dynamic meshes");
        check_finite(id, i, "mover_period", d.mover_period);
        check_finite(id, i, "position", d.position);
        check_finite(id, i, "rotation", d.rotation);
        check_finite(id, i, "scale", d.scale);
        check_finite(id, i, "mover_offset", d.mover_offset);
        check_finite(id, i, "probe_box_min", d.probe_box_min);
        check_finite(id, i, "probe_box_max", d.probe_box_max);
    }

    void check(uint32_t id, size_t i, const DiskFeatures& d) const {
        check_finite(id, i, "grid_min", d.grid_min);
        check_finite(id, i, "grid_max", d.grid_max);
    }

    std::span<const uint8_t> bytes_;
    const std::string& name_;
    std::array<SectionEntry, core_section_count> entries_{};
    std::array<const SectionEntry*, core_section_count> core_{};
    std::array<bool, section_id_limit - section_lightmap_texels> baked_seen_{};
    BlobReader blobs_;
};

}  // namespace

PackageContents parse_package(std::span<const uint8_t> bytes, const std::string& name) {
    PackageContents contents;
    try {
        Reader(bytes, name).read(contents);
    } catch (const std::bad_alloc&) {
        throw world::Error(name + ": out of memory while reading");
    }
    return contents;
}

PackageContents read_package_file(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw world::Error(path + ": cannot open; expected a readable .olpak file");
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                                     std::istreambuf_iterator<char>());
    return parse_package(bytes, path);
}

}  // namespace onelight::package
