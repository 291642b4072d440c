#include "world/package/package_writer.hpp"

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "world/package/crc32.hpp"
#include "world/package/format.hpp"

namespace onelight::package {
namespace {

using namespace onelight::world;

template <typename T>
void append_record(std::vector<uint8_t>& out, const T& record) {
    const auto* p = reinterpret_cast<const uint8_t*>(&record);
    out.insert(out.end(), p, p + sizeof(T));
}

void put3(float* dst, const glm::vec3& v) {
    dst[0] = v.x;
    dst[1] = v.y;
    dst[2] = v.z;
}

void put_quat(float* dst, const glm::quat& q) {
    dst[0] = q.x;
    dst[1] = q.y;
    dst[2] = q.z;
    dst[3] = q.w;
}

DiskVertex disk_vertex(const Vertex& v) {
    DiskVertex d{};
    put3(d.position, v.position);
    put3(d.normal, v.normal);
    d.tangent[0] = v.tangent.x;
    d.tangent[1] = v.tangent.y;
    d.tangent[2] = v.tangent.z;
    d.tangent[3] = v.tangent.w;
    d.uv0[0] = v.uv0.x;
    d.uv0[1] = v.uv0.y;
    d.uv1[0] = v.uv1.x;
    d.uv1[1] = v.uv1.y;
    return d;
}

struct Section {
    uint32_t element_size = 1;
    uint32_t count = 0;
    std::vector<uint8_t> bytes;
};

class PackageBuilder {
public:
    std::array<Section, core_section_count> sections;

    StringRef string(const std::string& s) {
        Section& strings = sections[section_strings];
        const StringRef ref{static_cast<uint32_t>(strings.bytes.size()),
                            static_cast<uint32_t>(s.size())};
        strings.bytes.insert(strings.bytes.end(), s.begin(), s.end());
        strings.count = static_cast<uint32_t>(strings.bytes.size());
        return ref;
    }

    template <typename T>
    void add(SectionId id, const T& record) {
        Section& s = sections[id];
        s.element_size = sizeof(T);
        append_record(s.bytes, record);
        ++s.count;
    }

    template <typename T>
    void declare(SectionId id) {
        sections[id].element_size = sizeof(T);
    }
};

void build_sections(const CompiledLevel& level, PackageBuilder& b) {
    b.declare<char>(section_strings);
    b.declare<DiskLevel>(section_level);
    b.declare<DiskMaterial>(section_materials);
    b.declare<DiskTexture>(section_textures);
    b.declare<DiskImage>(section_images);
    b.declare<uint8_t>(section_image_bytes);
    b.declare<DiskLight>(section_lights);
    b.declare<DiskCamera>(section_cameras);
    b.declare<DiskVertex>(section_vertices);
    b.declare<uint32_t>(section_indices);
    b.declare<DiskSurface>(section_surfaces);
    b.declare<uint32_t>(section_given_up_lights);
    b.declare<DiskChart>(section_charts);
    b.declare<DiskAtlas>(section_atlases);
    b.declare<DiskBspPlane>(section_bsp_planes);
    b.declare<DiskBspNode>(section_bsp_nodes);
    b.declare<DiskBspLeaf>(section_bsp_leaves);
    b.declare<DiskVertex>(section_dynamic_vertices);
    b.declare<uint32_t>(section_dynamic_indices);
    b.declare<DiskDynamicMesh>(section_dynamic_meshes);
    b.declare<DiskEntity>(section_entities);
    b.declare<DiskFeatures>(section_features);

    DiskLevel dl{};
    dl.exposure_ev100 = level.settings.exposure_ev100;
    dl.has_exposure = level.settings.has_exposure ? 1 : 0;
    dl.texels_per_metre = level.settings.texels_per_metre;
    dl.probe_spacing = level.settings.probe_spacing;
    for (int c = 0; c < 3; ++c) dl.sky_radiance[c] = level.settings.sky_radiance[c];
    put3(dl.bounds_min, level.settings.bounds_min);
    put3(dl.bounds_max, level.settings.bounds_max);
    b.add(section_level, dl);

    for (const Material& m : level.materials) {
        DiskMaterial d{};
        d.name = b.string(m.name);
        for (int i = 0; i < 4; ++i) d.base_color[i] = m.base_color[i];
        d.metallic = m.metallic;
        d.roughness = m.roughness;
        put3(d.albedo, m.albedo);
        put3(d.specular_color, m.specular_color);
        d.gloss = m.gloss;
        put3(d.emissive, m.emissive);
        d.alpha_cutoff = m.alpha_cutoff;
        d.normal_scale = m.normal_scale;
        d.occlusion_strength = m.occlusion_strength;
        d.base_color_texture = m.base_color_texture;
        d.metallic_roughness_texture = m.metallic_roughness_texture;
        d.normal_texture = m.normal_texture;
        d.occlusion_texture = m.occlusion_texture;
        d.emissive_texture = m.emissive_texture;
        d.alpha_mode = static_cast<uint8_t>(m.alpha_mode);
        d.double_sided = m.double_sided ? 1 : 0;
        d.material_class = static_cast<uint8_t>(m.material_class);
        b.add(section_materials, d);
    }
    for (const Texture& t : level.textures) {
        DiskTexture d{};
        d.image = t.image;
        d.mag_filter = t.sampler.mag_filter;
        d.min_filter = t.sampler.min_filter;
        d.wrap_s = t.sampler.wrap_s;
        d.wrap_t = t.sampler.wrap_t;
        b.add(section_textures, d);
    }
    for (const Image& image : level.images) {
        DiskImage d{};
        d.name = b.string(image.name);
        d.uri = b.string(image.uri);
        d.mime_type = b.string(image.mime_type);
        Section& bytes = b.sections[section_image_bytes];
        d.first_byte = static_cast<uint32_t>(bytes.bytes.size());
        d.byte_count = static_cast<uint32_t>(image.encoded_bytes.size());
        bytes.bytes.insert(bytes.bytes.end(), image.encoded_bytes.begin(),
                           image.encoded_bytes.end());
        bytes.count = static_cast<uint32_t>(bytes.bytes.size());
        b.add(section_images, d);
    }
    for (const Light& l : level.lights) {
        DiskLight d{};
        d.name = b.string(l.name);
        d.type = static_cast<uint8_t>(l.type);
        d.role = static_cast<uint8_t>(l.role);
        put3(d.color, l.color);
        d.intensity = l.intensity;
        d.range = l.range;
        d.inner_cone = l.inner_cone;
        d.outer_cone = l.outer_cone;
        put3(d.position, l.position);
        put3(d.direction, l.direction);
        b.add(section_lights, d);
    }
    for (const Camera& c : level.cameras) {
        DiskCamera d{};
        d.name = b.string(c.name);
        d.orthographic = c.orthographic ? 1 : 0;
        d.yfov = c.yfov;
        d.aspect_ratio = c.aspect_ratio;
        d.znear = c.znear;
        d.zfar = c.zfar;
        d.xmag = c.xmag;
        d.ymag = c.ymag;
        put3(d.position, c.position);
        put_quat(d.rotation, c.rotation);
        d.exposure_ev100 = c.exposure_ev100;
        d.has_exposure = c.has_exposure ? 1 : 0;
        b.add(section_cameras, d);
    }
    for (const Vertex& v : level.vertices) b.add(section_vertices, disk_vertex(v));
    for (uint32_t i : level.indices) b.add(section_indices, i);
    for (const Surface& s : level.surfaces) {
        DiskSurface d{};
        d.first_index = s.first_index;
        d.index_count = s.index_count;
        d.material = s.material;
        d.primary_light = s.primary_light;
        d.chart = s.chart;
        d.atlas = s.atlas;
        d.lightmap_x = s.lightmap_x;
        d.lightmap_y = s.lightmap_y;
        d.lightmap_width = s.lightmap_width;
        d.lightmap_height = s.lightmap_height;
        d.first_given_up = s.first_given_up;
        d.given_up_count = s.given_up_count;
        d.leaf = s.leaf;
        put3(d.bounds_min, s.bounds_min);
        put3(d.bounds_max, s.bounds_max);
        b.add(section_surfaces, d);
    }
    for (uint32_t i : level.given_up_lights) b.add(section_given_up_lights, i);
    for (const Chart& c : level.charts) {
        DiskChart d{};
        d.atlas = c.atlas;
        d.x = c.x;
        d.y = c.y;
        d.width = c.width;
        d.height = c.height;
        d.padding = c.padding;
        d.texels_per_metre = c.texels_per_metre;
        d.authored = c.authored ? 1 : 0;
        put3(d.origin, c.origin);
        put3(d.axis_u, c.axis_u);
        put3(d.axis_v, c.axis_v);
        b.add(section_charts, d);
    }
    for (const Atlas& a : level.atlases) b.add(section_atlases, DiskAtlas{a.width, a.height});
    for (const BspPlane& p : level.bsp_planes) {
        DiskBspPlane d{};
        d.normal[0] = p.normal.x;
        d.normal[1] = p.normal.y;
        d.normal[2] = p.normal.z;
        d.distance = p.distance;
        b.add(section_bsp_planes, d);
    }
    for (const BspNode& n : level.bsp_nodes) {
        DiskBspNode d{};
        d.plane = n.plane;
        d.front = n.front;
        d.back = n.back;
        put3(d.bounds_min, n.bounds_min);
        put3(d.bounds_max, n.bounds_max);
        b.add(section_bsp_nodes, d);
    }
    for (const BspLeaf& l : level.bsp_leaves) {
        DiskBspLeaf d{};
        d.first_triangle = l.first_triangle;
        d.triangle_count = l.triangle_count;
        d.first_surface = l.first_surface;
        d.surface_count = l.surface_count;
        put3(d.bounds_min, l.bounds_min);
        put3(d.bounds_max, l.bounds_max);
        b.add(section_bsp_leaves, d);
    }
    for (const Vertex& v : level.dynamic_vertices) b.add(section_dynamic_vertices, disk_vertex(v));
    for (uint32_t i : level.dynamic_indices) b.add(section_dynamic_indices, i);
    for (const DynamicMesh& m : level.dynamic_meshes) {
        DiskDynamicMesh d{};
        d.name = b.string(m.name);
        d.material = m.material;
        d.first_vertex = m.first_vertex;
        d.vertex_count = m.vertex_count;
        d.first_index = m.first_index;
        d.index_count = m.index_count;
        b.add(section_dynamic_meshes, d);
    }
    for (const Entity& e : level.entities) {
        DiskEntity d{};
        d.name = b.string(e.name);
        d.flags = e.flags;
        d.first_dynamic_mesh = e.first_dynamic_mesh;
        d.dynamic_mesh_count = e.dynamic_mesh_count;
        d.mover_period = e.mover_period;
        put3(d.position, e.position);
        put_quat(d.rotation, e.rotation);
        put3(d.scale, e.scale);
        put3(d.mover_offset, e.mover_offset);
        put3(d.probe_box_min, e.probe_box_min);
        put3(d.probe_box_max, e.probe_box_max);
        b.add(section_entities, d);
    }
    const Features& f = level.features;
    DiskFeatures df{};
    df.flags = f.flags;
    df.material_classes = f.material_classes;
    df.primary_light_types = f.primary_light_types;
    df.baked_light_types = f.baked_light_types;
    df.primary_count = f.primary_count;
    df.baked_light_count = f.baked_light_count;
    df.effect_omni_count = f.effect_omni_count;
    df.effect_spot_count = f.effect_spot_count;
    df.probe_count = f.probe_count;
    put3(df.grid_min, f.grid_min);
    put3(df.grid_max, f.grid_max);
    b.add(section_features, df);
}

uint64_t align_up(uint64_t value) {
    return (value + kSectionAlignment - 1) / kSectionAlignment * kSectionAlignment;
}

}  // namespace

std::vector<uint8_t> serialize_package(const world::CompiledLevel& level,
                                       std::span<const RawSection> baked_sections) {
    PackageBuilder builder;
    build_sections(level, builder);
    struct Placed {
        uint32_t id;
        const Section* section;
        const RawSection* raw;
    };
    std::vector<Placed> order;
    for (uint32_t id = 0; id < core_section_count; ++id)
        order.push_back({id, &builder.sections[id], nullptr});
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

std::string write_file_atomically(const std::string& path, std::span<const uint8_t> bytes) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
        if (!file) return path + ": cannot create " + temporary;
        file.write(reinterpret_cast<const char*>(bytes.data()),
                   static_cast<std::streamsize>(bytes.size()));
        file.flush();
        if (!file) {
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            return path + ": writing " + temporary + " failed (disk full?)";
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        return path + ": cannot rename " + temporary + " into place";
    }
    return "";
}

}  // namespace onelight::package
