#include "world/package/package_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "world/package/crc32.hpp"
#include "world/package/format.hpp"

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

bool finite(const float* v, size_t n) {
    for (size_t i = 0; i < n; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

glm::vec3 vec3_of(const float* v) {
    return glm::vec3(v[0], v[1], v[2]);
}
glm::quat quat_of(const float* v) {
    return glm::quat(v[3], v[0], v[1], v[2]);
}

/// Signals a rejected package; caught in parse_package and turned into the error string.
struct Rejected {
    std::string message;
};

class Reader {
public:
    Reader(std::span<const uint8_t> bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    void read(PackageReadResult& out) {
        read_header_and_table(out);
        CompiledLevel& level = out.level;
        load_strings();
        load_level(level);
        load_images(level);  // before textures: textures index images
        load_textures(level);
        load_materials(level);
        load_lights(level);
        load_cameras(level);
        level.vertices = load_vertices(section_vertices);
        level.indices = load_indices(section_indices, level.vertices.size(), "vertices");
        load_atlases(level);
        load_charts(level);
        load_bsp(level);
        load_given_up(level);
        load_surfaces(level);
        check_leaves_against_surfaces(level);
        level.dynamic_vertices = load_vertices(section_dynamic_vertices);
        level.dynamic_indices = load_u32(section_dynamic_indices);
        load_dynamic_meshes(level);
        load_entities(level);
        load_features(level);
    }

private:
    [[noreturn]] void fail(const std::string& message) const {
        throw Rejected{name_ + ": " + message};
    }
    [[noreturn]] void fail(uint32_t id, size_t record, const std::string& message) const {
        fail(std::string("section ") + section_name(id) + " record " + std::to_string(record) +
             ": " + message);
    }

    void read_header_and_table(PackageReadResult& out) {
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

    void load_strings() {
        const SectionEntry& e = *core_[section_strings];
        strings_ = std::string(reinterpret_cast<const char*>(bytes_.data() + e.offset), e.size);
    }

    std::string string(const StringRef& ref, uint32_t id, size_t record, const char* field) const {
        if (ref.offset > strings_.size() || ref.length > strings_.size() - ref.offset)
            fail(id, record,
                 std::string(field) + " string [" + std::to_string(ref.offset) + ", +" +
                     std::to_string(ref.length) + ") is outside the strings section (" +
                     std::to_string(strings_.size()) + " bytes)");
        return strings_.substr(ref.offset, ref.length);
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

    void check_finite(uint32_t id, size_t record, const float* v, size_t n,
                      const char* field) const {
        if (!finite(v, n)) fail(id, record, std::string(field) + " is NaN or Inf");
    }

    void load_level(CompiledLevel& level) {
        const auto r = records<DiskLevel>(section_level);
        if (r.size() != 1)
            fail(std::string("section level: ") + std::to_string(r.size()) +
                 " records; expected 1");
        const DiskLevel& d = r[0];
        check_finite(section_level, 0, &d.exposure_ev100, 1, "exposure");
        check_finite(section_level, 0, d.bounds_min, 3, "bounds_min");
        check_finite(section_level, 0, d.bounds_max, 3, "bounds_max");
        if (!(d.texels_per_metre > 0.0f) || !std::isfinite(d.texels_per_metre))
            fail(section_level, 0,
                 "texels_per_metre " + std::to_string(d.texels_per_metre) + "; expected > 0");
        if (!(d.probe_spacing >= 0.0f) || !std::isfinite(d.probe_spacing))
            fail(section_level, 0,
                 "probe_spacing " + std::to_string(d.probe_spacing) + "; expected metres >= 0");
        level.settings.exposure_ev100 = d.exposure_ev100;
        level.settings.has_exposure = d.has_exposure != 0;
        level.settings.texels_per_metre = d.texels_per_metre;
        check_finite(section_level, 0, d.sky_radiance, 3, "sky_radiance");
        if (!(std::min({d.sky_radiance[0], d.sky_radiance[1], d.sky_radiance[2]}) >= 0.0f))
            fail(section_level, 0, "sky_radiance negative; expected cd/m^2 >= 0");
        if (d.reserved != 0)
            fail(section_level, 0, "reserved " + std::to_string(d.reserved) + "; expected 0");
        level.settings.probe_spacing = d.probe_spacing;
        level.settings.sky_radiance = vec3_of(d.sky_radiance);
        level.settings.bounds_min = vec3_of(d.bounds_min);
        level.settings.bounds_max = vec3_of(d.bounds_max);
    }

    void load_images(CompiledLevel& level) {
        const auto r = records<DiskImage>(section_images);
        const SectionEntry& bytes = *core_[section_image_bytes];
        for (size_t i = 0; i < r.size(); ++i) {
            Image image;
            image.name = string(r[i].name, section_images, i, "name");
            image.uri = string(r[i].uri, section_images, i, "uri");
            image.mime_type = string(r[i].mime_type, section_images, i, "mime_type");
            check_range(section_images, i, "bytes", r[i].first_byte, r[i].byte_count, bytes.size,
                        "image bytes");
            if (image.uri.empty() == (r[i].byte_count == 0))
                fail(section_images, i,
                     "expected either a uri or embedded bytes, not both or neither");
            const uint8_t* p = bytes_.data() + bytes.offset + r[i].first_byte;
            image.encoded_bytes.assign(p, p + r[i].byte_count);
            level.images.push_back(std::move(image));
        }
    }

    void load_textures(CompiledLevel& level) {
        const auto r = records<DiskTexture>(section_textures);
        for (size_t i = 0; i < r.size(); ++i) {
            check_index(section_textures, i, "image", r[i].image, level.images.size(), "images",
                        true);
            Texture t;
            t.image = r[i].image;
            t.sampler = {r[i].mag_filter, r[i].min_filter, r[i].wrap_s, r[i].wrap_t};
            level.textures.push_back(t);
        }
    }

    void load_materials(CompiledLevel& level) {
        const auto r = records<DiskMaterial>(section_materials);
        for (size_t i = 0; i < r.size(); ++i) {
            const DiskMaterial& d = r[i];
            Material m;
            m.name = string(d.name, section_materials, i, "name");
            check_finite(section_materials, i, d.base_color, 4, "base_color");
            check_finite(section_materials, i, &d.metallic, 1, "metallic");
            check_finite(section_materials, i, &d.roughness, 1, "roughness");
            check_finite(section_materials, i, d.albedo, 3, "albedo");
            check_finite(section_materials, i, d.specular_color, 3, "specular_color");
            check_finite(section_materials, i, &d.gloss, 1, "gloss");
            check_finite(section_materials, i, d.emissive, 3, "emissive");
            check_finite(section_materials, i, &d.alpha_cutoff, 1, "alpha_cutoff");
            check_finite(section_materials, i, &d.normal_scale, 1, "normal_scale");
            check_finite(section_materials, i, &d.occlusion_strength, 1, "occlusion_strength");
            const size_t textures = level.textures.size();
            check_index(section_materials, i, "base_color_texture", d.base_color_texture, textures,
                        "textures", true);
            check_index(section_materials, i, "metallic_roughness_texture",
                        d.metallic_roughness_texture, textures, "textures", true);
            check_index(section_materials, i, "normal_texture", d.normal_texture, textures,
                        "textures", true);
            check_index(section_materials, i, "occlusion_texture", d.occlusion_texture, textures,
                        "textures", true);
            check_index(section_materials, i, "emissive_texture", d.emissive_texture, textures,
                        "textures", true);
            if (d.alpha_mode > 2)
                fail(section_materials, i,
                     "alpha_mode " + std::to_string(d.alpha_mode) + "; expected 0..2");
            if (d.material_class > 3)
                fail(section_materials, i,
                     "material_class " + std::to_string(d.material_class) + "; expected 0..3");
            if (d.gloss < 0.0f || d.gloss > 1.0f)
                fail(section_materials, i,
                     "gloss " + std::to_string(d.gloss) + "; expected [0, 1]");
            for (int k = 0; k < 4; ++k) m.base_color[k] = d.base_color[k];
            m.metallic = d.metallic;
            m.roughness = d.roughness;
            m.albedo = vec3_of(d.albedo);
            m.specular_color = vec3_of(d.specular_color);
            m.gloss = d.gloss;
            m.emissive = vec3_of(d.emissive);
            m.alpha_cutoff = d.alpha_cutoff;
            m.normal_scale = d.normal_scale;
            m.occlusion_strength = d.occlusion_strength;
            m.base_color_texture = d.base_color_texture;
            m.metallic_roughness_texture = d.metallic_roughness_texture;
            m.normal_texture = d.normal_texture;
            m.occlusion_texture = d.occlusion_texture;
            m.emissive_texture = d.emissive_texture;
            m.alpha_mode = static_cast<AlphaMode>(d.alpha_mode);
            m.double_sided = d.double_sided != 0;
            m.material_class = static_cast<MaterialClass>(d.material_class);
            level.materials.push_back(std::move(m));
        }
    }

    void load_lights(CompiledLevel& level) {
        const auto r = records<DiskLight>(section_lights);
        for (size_t i = 0; i < r.size(); ++i) {
            const DiskLight& d = r[i];
            Light l;
            l.name = string(d.name, section_lights, i, "name");
            if (d.type > 2)
                fail(section_lights, i, "type " + std::to_string(d.type) + "; expected 0..2");
            if (d.role > 2)
                fail(section_lights, i, "role " + std::to_string(d.role) + "; expected 0..2");
            check_finite(section_lights, i, d.color, 3, "color");
            check_finite(section_lights, i, d.position, 3, "position");
            check_finite(section_lights, i, d.direction, 3, "direction");
            if (!(d.intensity >= 0.0f) || !std::isfinite(d.intensity))
                fail(section_lights, i,
                     "intensity " + std::to_string(d.intensity) + "; expected finite >= 0");
            if (!(d.range >= 0.0f) || !std::isfinite(d.range))
                fail(section_lights, i,
                     "range " + std::to_string(d.range) + "; expected finite >= 0");
            if (!(d.inner_cone >= 0.0f && d.inner_cone <= d.outer_cone && d.outer_cone <= 1.5708f))
                fail(section_lights, i, "cone angles; expected 0 <= inner <= outer <= pi/2");
            l.type = static_cast<LightType>(d.type);
            l.role = static_cast<LightRole>(d.role);
            l.color = vec3_of(d.color);
            l.intensity = d.intensity;
            l.range = d.range;
            l.inner_cone = d.inner_cone;
            l.outer_cone = d.outer_cone;
            l.position = vec3_of(d.position);
            l.direction = vec3_of(d.direction);
            level.lights.push_back(std::move(l));
        }
    }

    void load_cameras(CompiledLevel& level) {
        const auto r = records<DiskCamera>(section_cameras);
        for (size_t i = 0; i < r.size(); ++i) {
            const DiskCamera& d = r[i];
            Camera c;
            c.name = string(d.name, section_cameras, i, "name");
            check_finite(section_cameras, i, &d.yfov, 7, "projection");
            check_finite(section_cameras, i, d.position, 3, "position");
            check_finite(section_cameras, i, d.rotation, 4, "rotation");
            check_finite(section_cameras, i, &d.exposure_ev100, 1, "exposure");
            c.orthographic = d.orthographic != 0;
            c.yfov = d.yfov;
            c.aspect_ratio = d.aspect_ratio;
            c.znear = d.znear;
            c.zfar = d.zfar;
            c.xmag = d.xmag;
            c.ymag = d.ymag;
            c.position = vec3_of(d.position);
            c.rotation = quat_of(d.rotation);
            c.exposure_ev100 = d.exposure_ev100;
            c.has_exposure = d.has_exposure != 0;
            level.cameras.push_back(std::move(c));
        }
    }

    std::vector<Vertex> load_vertices(uint32_t id) const {
        const auto r = records<DiskVertex>(id);
        std::vector<Vertex> out(r.size());
        for (size_t i = 0; i < r.size(); ++i) {
            const DiskVertex& d = r[i];
            check_finite(id, i, d.position, 14, "vertex attribute");
            Vertex& v = out[i];
            v.position = vec3_of(d.position);
            v.normal = vec3_of(d.normal);
            v.tangent = glm::vec4(d.tangent[0], d.tangent[1], d.tangent[2], d.tangent[3]);
            v.uv0 = glm::vec2(d.uv0[0], d.uv0[1]);
            v.uv1 = glm::vec2(d.uv1[0], d.uv1[1]);
        }
        return out;
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

    void load_atlases(CompiledLevel& level) {
        const auto r = records<DiskAtlas>(section_atlases);
        for (size_t i = 0; i < r.size(); ++i) {
            if (r[i].width == 0 || r[i].height == 0 || r[i].width > 65536 || r[i].height > 65536)
                fail(section_atlases, i,
                     "size " + std::to_string(r[i].width) + "x" + std::to_string(r[i].height) +
                         "; expected 1..65536 texels per side");
            level.atlases.push_back({r[i].width, r[i].height});
        }
    }

    void load_charts(CompiledLevel& level) {
        const auto r = records<DiskChart>(section_charts);
        for (size_t i = 0; i < r.size(); ++i) {
            const DiskChart& d = r[i];
            check_index(section_charts, i, "atlas", d.atlas, level.atlases.size(), "atlases",
                        false);
            const Atlas& a = level.atlases[d.atlas];
            check_range(section_charts, i, "x", d.x, d.width, a.width, "texels of atlas width");
            check_range(section_charts, i, "y", d.y, d.height, a.height, "texels of atlas height");
            if (uint64_t(2) * d.padding >= d.width || uint64_t(2) * d.padding >= d.height)
                fail(section_charts, i,
                     "padding " + std::to_string(d.padding) + " leaves no room in the rectangle");
            check_finite(section_charts, i, &d.texels_per_metre, 1, "texels_per_metre");
            check_finite(section_charts, i, d.origin, 9, "projection");
            Chart c;
            c.atlas = d.atlas;
            c.x = d.x;
            c.y = d.y;
            c.width = d.width;
            c.height = d.height;
            c.padding = d.padding;
            c.texels_per_metre = d.texels_per_metre;
            c.authored = d.authored != 0;
            c.origin = vec3_of(d.origin);
            c.axis_u = vec3_of(d.axis_u);
            c.axis_v = vec3_of(d.axis_v);
            level.charts.push_back(c);
        }
    }

    void load_bsp(CompiledLevel& level) {
        const auto planes = records<DiskBspPlane>(section_bsp_planes);
        for (size_t i = 0; i < planes.size(); ++i) {
            const DiskBspPlane& d = planes[i];
            const glm::dvec3 n(d.normal[0], d.normal[1], d.normal[2]);
            const double length = glm::length(n);
            if (!std::isfinite(length) || !std::isfinite(d.distance) ||
                std::abs(length - 1.0) > 1e-6)
                fail(section_bsp_planes, i, "normal is not unit length or distance is not finite");
            level.bsp_planes.push_back({n, d.distance});
        }
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
            check_finite(section_bsp_nodes, i, d.bounds_min, 6, "bounds");
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
            BspNode n;
            n.plane = d.plane;
            n.front = d.front;
            n.back = d.back;
            n.bounds_min = vec3_of(d.bounds_min);
            n.bounds_max = vec3_of(d.bounds_max);
            level.bsp_nodes.push_back(n);
        }
        for (size_t i = 0; i < leaves.size(); ++i) {
            const DiskBspLeaf& d = leaves[i];
            check_range(section_bsp_leaves, i, "triangles", d.first_triangle, d.triangle_count,
                        triangles, "triangles");
            check_finite(section_bsp_leaves, i, d.bounds_min, 6, "bounds");
            if (!nodes.empty() && !leaf_used[i])
                fail(section_bsp_leaves, i, "no node refers to this leaf");
            BspLeaf l;
            l.first_triangle = d.first_triangle;
            l.triangle_count = d.triangle_count;
            l.first_surface = d.first_surface;
            l.surface_count = d.surface_count;
            l.bounds_min = vec3_of(d.bounds_min);
            l.bounds_max = vec3_of(d.bounds_max);
            level.bsp_leaves.push_back(l);
        }
    }

    void load_given_up(CompiledLevel& level) {
        level.given_up_lights = load_u32(section_given_up_lights);
        for (size_t i = 0; i < level.given_up_lights.size(); ++i)
            check_index(section_given_up_lights, i, "light", level.given_up_lights[i],
                        level.lights.size(), "lights", false);
    }

    void load_surfaces(CompiledLevel& level) {
        const auto r = records<DiskSurface>(section_surfaces);
        for (size_t i = 0; i < r.size(); ++i) {
            const DiskSurface& d = r[i];
            if (d.first_index % 3 != 0 || d.index_count % 3 != 0 || d.index_count == 0)
                fail(section_surfaces, i,
                     "index range [" + std::to_string(d.first_index) + ", +" +
                         std::to_string(d.index_count) + "); expected non-empty whole triangles");
            check_range(section_surfaces, i, "indices", d.first_index, d.index_count,
                        level.indices.size(), "indices");
            check_index(section_surfaces, i, "material", d.material, level.materials.size(),
                        "materials", false);
            check_index(section_surfaces, i, "primary_light", d.primary_light, level.lights.size(),
                        "lights", true);
            if (d.primary_light != kNoIndex &&
                level.lights[d.primary_light].role != LightRole::primary)
                fail(
                    section_surfaces, i,
                    "primary_light " + std::to_string(d.primary_light) + " is not a primary light");
            check_index(section_surfaces, i, "chart", d.chart, level.charts.size(), "charts",
                        false);
            if (d.atlas != level.charts[d.chart].atlas)
                fail(section_surfaces, i,
                     "atlas " + std::to_string(d.atlas) + " differs from its chart's atlas " +
                         std::to_string(level.charts[d.chart].atlas));
            check_range(section_surfaces, i, "given-up lights", d.first_given_up, d.given_up_count,
                        level.given_up_lights.size(), "given-up lights");
            check_index(section_surfaces, i, "leaf", d.leaf, level.bsp_leaves.size(), "leaves",
                        false);
            check_finite(section_surfaces, i, d.bounds_min, 6, "bounds");
            Surface s;
            s.first_index = d.first_index;
            s.index_count = d.index_count;
            s.material = d.material;
            s.primary_light = d.primary_light;
            s.chart = d.chart;
            s.atlas = d.atlas;
            s.lightmap_x = d.lightmap_x;
            s.lightmap_y = d.lightmap_y;
            s.lightmap_width = d.lightmap_width;
            s.lightmap_height = d.lightmap_height;
            s.first_given_up = d.first_given_up;
            s.given_up_count = d.given_up_count;
            s.leaf = d.leaf;
            s.bounds_min = vec3_of(d.bounds_min);
            s.bounds_max = vec3_of(d.bounds_max);
            level.surfaces.push_back(s);
        }
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

    void load_dynamic_meshes(CompiledLevel& level) {
        const auto r = records<DiskDynamicMesh>(section_dynamic_meshes);
        for (size_t i = 0; i < r.size(); ++i) {
            const DiskDynamicMesh& d = r[i];
            DynamicMesh m;
            m.name = string(d.name, section_dynamic_meshes, i, "name");
            check_index(section_dynamic_meshes, i, "material", d.material, level.materials.size(),
                        "materials", false);
            check_range(section_dynamic_meshes, i, "vertices", d.first_vertex, d.vertex_count,
                        level.dynamic_vertices.size(), "dynamic vertices");
            if (d.first_index % 3 != 0 || d.index_count % 3 != 0)
                fail(section_dynamic_meshes, i, "index range is not whole triangles");
            check_range(section_dynamic_meshes, i, "indices", d.first_index, d.index_count,
                        level.dynamic_indices.size(), "dynamic indices");
            for (uint32_t k = d.first_index; k < d.first_index + d.index_count; ++k)
                check_index(section_dynamic_meshes, i, "index", level.dynamic_indices[k],
                            d.vertex_count, "vertices in the mesh", false);
            m.material = d.material;
            m.first_vertex = d.first_vertex;
            m.vertex_count = d.vertex_count;
            m.first_index = d.first_index;
            m.index_count = d.index_count;
            level.dynamic_meshes.push_back(std::move(m));
        }
    }

    void load_entities(CompiledLevel& level) {
        const auto r = records<DiskEntity>(section_entities);
        for (size_t i = 0; i < r.size(); ++i) {
            const DiskEntity& d = r[i];
            Entity e;
            e.name = string(d.name, section_entities, i, "name");
            if (d.flags & ~uint32_t(0xF))
                fail(section_entities, i, "flags " + std::to_string(d.flags) + " has unknown bits");
            check_range(section_entities, i, "dynamic meshes", d.first_dynamic_mesh,
                        d.dynamic_mesh_count, level.dynamic_meshes.size(), "dynamic meshes");
            check_finite(section_entities, i, &d.mover_period, 1, "mover_period");
            check_finite(section_entities, i, d.position, 19, "transform");
            e.flags = d.flags;
            e.first_dynamic_mesh = d.first_dynamic_mesh;
            e.dynamic_mesh_count = d.dynamic_mesh_count;
            e.mover_period = d.mover_period;
            e.position = vec3_of(d.position);
            e.rotation = quat_of(d.rotation);
            e.scale = vec3_of(d.scale);
            e.mover_offset = vec3_of(d.mover_offset);
            e.probe_box_min = vec3_of(d.probe_box_min);
            e.probe_box_max = vec3_of(d.probe_box_max);
            level.entities.push_back(std::move(e));
        }
    }

    void load_features(CompiledLevel& level) {
        const auto r = records<DiskFeatures>(section_features);
        if (r.size() != 1)
            fail(std::string("section features: ") + std::to_string(r.size()) +
                 " records; expected 1");
        const DiskFeatures& d = r[0];
        check_finite(section_features, 0, d.grid_min, 6, "grid bounds");
        Features& f = level.features;
        f.flags = d.flags;
        f.material_classes = d.material_classes;
        f.primary_light_types = d.primary_light_types;
        f.baked_light_types = d.baked_light_types;
        f.primary_count = d.primary_count;
        f.baked_light_count = d.baked_light_count;
        f.effect_omni_count = d.effect_omni_count;
        f.effect_spot_count = d.effect_spot_count;
        f.probe_count = d.probe_count;
        f.grid_min = vec3_of(d.grid_min);
        f.grid_max = vec3_of(d.grid_max);
    }

    std::span<const uint8_t> bytes_;
    const std::string& name_;
    std::array<SectionEntry, core_section_count> entries_{};
    std::array<const SectionEntry*, core_section_count> core_{};
    std::array<bool, section_id_limit - section_lightmap_texels> baked_seen_{};
    std::string strings_;
};

}  // namespace

PackageReadResult parse_package(std::span<const uint8_t> bytes, const std::string& name) {
    PackageReadResult result;
    try {
        Reader(bytes, name).read(result);
    } catch (const Rejected& rejected) {
        result = PackageReadResult{};
        result.error = rejected.message;
    } catch (const std::bad_alloc&) {
        result = PackageReadResult{};
        result.error = name + ": out of memory while reading";
    }
    return result;
}

PackageReadResult read_package_file(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        PackageReadResult result;
        result.error = path + ": cannot open; expected a readable .olpak file";
        return result;
    }
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                                     std::istreambuf_iterator<char>());
    return parse_package(bytes, path);
}

}  // namespace onelight::package
