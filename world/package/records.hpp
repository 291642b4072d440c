// One to_disk / from_disk pair per .olpak record (format.hpp): the one place that maps each
// field between an in-memory type (compiled_level.hpp, baked_lighting.hpp) and its on-disk
// twin. The writers call to_disk; the readers check a record first (every index, range and
// float, with errors naming the field) and then call from_disk. from_disk never reads outside
// what it is given: a string or byte range that does not fit comes back empty.
#pragma once

#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "world/baked_lighting.hpp"
#include "world/compiled_level.hpp"
#include "world/package/format.hpp"

namespace onelight::package {

// The helpers and the pairs live in `records`; the pairs are brought into package below.
namespace records {

// Flags are stored as they are in memory.
static_assert(uint32_t(world::lightmap_texel_sampled) == uint32_t(lightmap_texel_sampled));
static_assert(uint32_t(world::lightmap_texel_dilated) == uint32_t(lightmap_texel_dilated));
static_assert(uint32_t(world::light_grid_cell_inside_solid) ==
              uint32_t(light_grid_cell_inside_solid));

/// Copies `v` into the array field `dst`.
inline void put(float (&dst)[2], const glm::vec2& v) {
    for (int i = 0; i < 2; ++i) dst[i] = v[i];
}
/// Copies `v` into the array field `dst`.
inline void put(float (&dst)[3], const glm::vec3& v) {
    for (int i = 0; i < 3; ++i) dst[i] = v[i];
}
/// Copies `v` into the array field `dst`.
inline void put(float (&dst)[4], const glm::vec4& v) {
    for (int i = 0; i < 4; ++i) dst[i] = v[i];
}
/// Copies `v` into the array field `dst`.
inline void put(double (&dst)[3], const glm::dvec3& v) {
    for (int i = 0; i < 3; ++i) dst[i] = v[i];
}
/// Copies `q` into the array field `dst` as x, y, z, w.
inline void put(float (&dst)[4], const glm::quat& q) {
    dst[0] = q.x;
    dst[1] = q.y;
    dst[2] = q.z;
    dst[3] = q.w;
}

/// The array field `v` as a vector.
inline glm::vec2 vec(const float (&v)[2]) {
    return glm::vec2(v[0], v[1]);
}
/// The array field `v` as a vector.
inline glm::vec3 vec(const float (&v)[3]) {
    return glm::vec3(v[0], v[1], v[2]);
}
/// The array field `v` as a vector.
inline glm::vec4 vec(const float (&v)[4]) {
    return glm::vec4(v[0], v[1], v[2], v[3]);
}
/// The array field `v` as a vector.
inline glm::dvec3 vec(const double (&v)[3]) {
    return glm::dvec3(v[0], v[1], v[2]);
}
/// The array field `v` (x, y, z, w) as a quaternion.
inline glm::quat quat(const float (&v)[4]) {
    return glm::quat(v[3], v[0], v[1], v[2]);
}

/// Bytes [first, first + count) of `bytes`, or none when they do not fit.
inline std::span<const uint8_t> slice(std::span<const uint8_t> bytes, uint64_t first,
                                      uint64_t count) {
    if (first > bytes.size() || count > bytes.size() - first) return {};
    return bytes.subspan(first, count);
}

}  // namespace records

/// The byte sections that records refer into (strings, image bytes), as a writer fills them.
struct BlobWriter {
    std::vector<uint8_t> strings;      // section_strings
    std::vector<uint8_t> image_bytes;  // section_image_bytes

    /// Appends `s` to the strings and returns its reference.
    StringRef add_string(const std::string& s) {
        const StringRef ref{static_cast<uint32_t>(strings.size()), static_cast<uint32_t>(s.size())};
        strings.insert(strings.end(), s.begin(), s.end());
        return ref;
    }
};

/// The same byte sections as a reader sees them.
struct BlobReader {
    std::span<const uint8_t> strings;      // section_strings
    std::span<const uint8_t> image_bytes;  // section_image_bytes

    /// The string `ref` refers to; "" when it runs outside the strings.
    std::string string(const StringRef& ref) const {
        const std::span<const uint8_t> s = records::slice(strings, ref.offset, ref.length);
        return std::string(s.begin(), s.end());
    }
};

namespace records {

/// Level settings -> DiskLevel (reserved 0).
inline DiskLevel to_disk(const world::LevelSettings& s) {
    DiskLevel d{};
    d.exposure_ev100 = s.exposure_ev100;
    d.has_exposure = s.has_exposure ? 1 : 0;
    d.texels_per_metre = s.texels_per_metre;
    put(d.bounds_min, s.bounds_min);
    put(d.bounds_max, s.bounds_max);
    d.probe_spacing = s.probe_spacing;
    put(d.sky_radiance, s.sky_radiance);
    return d;
}

/// DiskLevel -> level settings.
inline world::LevelSettings from_disk(const DiskLevel& d) {
    world::LevelSettings s;
    s.exposure_ev100 = d.exposure_ev100;
    s.has_exposure = d.has_exposure != 0;
    s.texels_per_metre = d.texels_per_metre;
    s.bounds_min = vec(d.bounds_min);
    s.bounds_max = vec(d.bounds_max);
    s.probe_spacing = d.probe_spacing;
    s.sky_radiance = vec(d.sky_radiance);
    return s;
}

/// Material -> DiskMaterial; appends the name to `blobs`.
inline DiskMaterial to_disk(const world::Material& m, BlobWriter& blobs) {
    DiskMaterial d{};
    d.name = blobs.add_string(m.name);
    put(d.base_color, m.base_color);
    d.metallic = m.metallic;
    d.roughness = m.roughness;
    put(d.albedo, m.albedo);
    put(d.specular_color, m.specular_color);
    d.gloss = m.gloss;
    put(d.emissive, m.emissive);
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
    return d;
}

/// DiskMaterial -> material, the name read from `blobs`.
inline world::Material from_disk(const DiskMaterial& d, const BlobReader& blobs) {
    world::Material m;
    m.name = blobs.string(d.name);
    m.base_color = vec(d.base_color);
    m.metallic = d.metallic;
    m.roughness = d.roughness;
    m.albedo = vec(d.albedo);
    m.specular_color = vec(d.specular_color);
    m.gloss = d.gloss;
    m.emissive = vec(d.emissive);
    m.alpha_cutoff = d.alpha_cutoff;
    m.normal_scale = d.normal_scale;
    m.occlusion_strength = d.occlusion_strength;
    m.base_color_texture = d.base_color_texture;
    m.metallic_roughness_texture = d.metallic_roughness_texture;
    m.normal_texture = d.normal_texture;
    m.occlusion_texture = d.occlusion_texture;
    m.emissive_texture = d.emissive_texture;
    m.alpha_mode = static_cast<world::AlphaMode>(d.alpha_mode);
    m.double_sided = d.double_sided != 0;
    m.material_class = static_cast<world::MaterialClass>(d.material_class);
    return m;
}

/// Texture -> DiskTexture.
inline DiskTexture to_disk(const world::Texture& t) {
    DiskTexture d{};
    d.image = t.image;
    d.mag_filter = t.sampler.mag_filter;
    d.min_filter = t.sampler.min_filter;
    d.wrap_s = t.sampler.wrap_s;
    d.wrap_t = t.sampler.wrap_t;
    return d;
}

/// DiskTexture -> texture.
inline world::Texture from_disk(const DiskTexture& d) {
    world::Texture t;
    t.image = d.image;
    t.sampler.mag_filter = d.mag_filter;
    t.sampler.min_filter = d.min_filter;
    t.sampler.wrap_s = d.wrap_s;
    t.sampler.wrap_t = d.wrap_t;
    return t;
}

/// Image -> DiskImage; appends the strings and the encoded bytes to `blobs`.
inline DiskImage to_disk(const world::Image& image, BlobWriter& blobs) {
    DiskImage d{};
    d.name = blobs.add_string(image.name);
    d.uri = blobs.add_string(image.uri);
    d.mime_type = blobs.add_string(image.mime_type);
    d.first_byte = static_cast<uint32_t>(blobs.image_bytes.size());
    d.byte_count = static_cast<uint32_t>(image.encoded_bytes.size());
    blobs.image_bytes.insert(blobs.image_bytes.end(), image.encoded_bytes.begin(),
                             image.encoded_bytes.end());
    return d;
}

/// DiskImage -> image, strings and encoded bytes read from `blobs`.
inline world::Image from_disk(const DiskImage& d, const BlobReader& blobs) {
    world::Image image;
    image.name = blobs.string(d.name);
    image.uri = blobs.string(d.uri);
    image.mime_type = blobs.string(d.mime_type);
    const std::span<const uint8_t> bytes = slice(blobs.image_bytes, d.first_byte, d.byte_count);
    image.encoded_bytes.assign(bytes.begin(), bytes.end());
    return image;
}

/// Light -> DiskLight; appends the name to `blobs`.
inline DiskLight to_disk(const world::Light& l, BlobWriter& blobs) {
    DiskLight d{};
    d.name = blobs.add_string(l.name);
    d.type = static_cast<uint8_t>(l.type);
    d.role = static_cast<uint8_t>(l.role);
    put(d.color, l.color);
    d.intensity = l.intensity;
    d.range = l.range;
    d.inner_cone = l.inner_cone;
    d.outer_cone = l.outer_cone;
    put(d.position, l.position);
    put(d.direction, l.direction);
    return d;
}

/// DiskLight -> light, the name read from `blobs`.
inline world::Light from_disk(const DiskLight& d, const BlobReader& blobs) {
    world::Light l;
    l.name = blobs.string(d.name);
    l.type = static_cast<world::LightType>(d.type);
    l.role = static_cast<world::LightRole>(d.role);
    l.color = vec(d.color);
    l.intensity = d.intensity;
    l.range = d.range;
    l.inner_cone = d.inner_cone;
    l.outer_cone = d.outer_cone;
    l.position = vec(d.position);
    l.direction = vec(d.direction);
    return l;
}

/// Camera -> DiskCamera; appends the name to `blobs`.
inline DiskCamera to_disk(const world::Camera& c, BlobWriter& blobs) {
    DiskCamera d{};
    d.name = blobs.add_string(c.name);
    d.orthographic = c.orthographic ? 1 : 0;
    d.yfov = c.yfov;
    d.aspect_ratio = c.aspect_ratio;
    d.znear = c.znear;
    d.zfar = c.zfar;
    d.xmag = c.xmag;
    d.ymag = c.ymag;
    put(d.position, c.position);
    put(d.rotation, c.rotation);
    d.exposure_ev100 = c.exposure_ev100;
    d.has_exposure = c.has_exposure ? 1 : 0;
    return d;
}

/// DiskCamera -> camera, the name read from `blobs`.
inline world::Camera from_disk(const DiskCamera& d, const BlobReader& blobs) {
    world::Camera c;
    c.name = blobs.string(d.name);
    c.orthographic = d.orthographic != 0;
    c.yfov = d.yfov;
    c.aspect_ratio = d.aspect_ratio;
    c.znear = d.znear;
    c.zfar = d.zfar;
    c.xmag = d.xmag;
    c.ymag = d.ymag;
    c.position = vec(d.position);
    c.rotation = quat(d.rotation);
    c.exposure_ev100 = d.exposure_ev100;
    c.has_exposure = d.has_exposure != 0;
    return c;
}

/// Vertex (static or dynamic) -> DiskVertex.
inline DiskVertex to_disk(const world::Vertex& v) {
    DiskVertex d{};
    put(d.position, v.position);
    put(d.normal, v.normal);
    put(d.tangent, v.tangent);
    put(d.uv0, v.uv0);
    put(d.uv1, v.uv1);
    return d;
}

/// DiskVertex -> vertex.
inline world::Vertex from_disk(const DiskVertex& d) {
    world::Vertex v;
    v.position = vec(d.position);
    v.normal = vec(d.normal);
    v.tangent = vec(d.tangent);
    v.uv0 = vec(d.uv0);
    v.uv1 = vec(d.uv1);
    return v;
}

/// Surface -> DiskSurface.
inline DiskSurface to_disk(const world::Surface& s) {
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
    put(d.bounds_min, s.bounds_min);
    put(d.bounds_max, s.bounds_max);
    return d;
}

/// DiskSurface -> surface.
inline world::Surface from_disk(const DiskSurface& d) {
    world::Surface s;
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
    s.bounds_min = vec(d.bounds_min);
    s.bounds_max = vec(d.bounds_max);
    return s;
}

/// Chart -> DiskChart.
inline DiskChart to_disk(const world::Chart& c) {
    DiskChart d{};
    d.atlas = c.atlas;
    d.x = c.x;
    d.y = c.y;
    d.width = c.width;
    d.height = c.height;
    d.padding = c.padding;
    d.texels_per_metre = c.texels_per_metre;
    d.authored = c.authored ? 1 : 0;
    put(d.origin, c.origin);
    put(d.axis_u, c.axis_u);
    put(d.axis_v, c.axis_v);
    return d;
}

/// DiskChart -> chart.
inline world::Chart from_disk(const DiskChart& d) {
    world::Chart c;
    c.atlas = d.atlas;
    c.x = d.x;
    c.y = d.y;
    c.width = d.width;
    c.height = d.height;
    c.padding = d.padding;
    c.texels_per_metre = d.texels_per_metre;
    c.authored = d.authored != 0;
    c.origin = vec(d.origin);
    c.axis_u = vec(d.axis_u);
    c.axis_v = vec(d.axis_v);
    return c;
}

/// Atlas -> DiskAtlas.
inline DiskAtlas to_disk(const world::Atlas& a) {
    return DiskAtlas{a.width, a.height};
}

/// DiskAtlas -> atlas.
inline world::Atlas from_disk(const DiskAtlas& d) {
    return world::Atlas{d.width, d.height};
}

/// BSP plane -> DiskBspPlane.
inline DiskBspPlane to_disk(const world::BspPlane& p) {
    DiskBspPlane d{};
    put(d.normal, p.normal);
    d.distance = p.distance;
    return d;
}

/// DiskBspPlane -> BSP plane.
inline world::BspPlane from_disk(const DiskBspPlane& d) {
    return world::BspPlane{vec(d.normal), d.distance};
}

/// BSP node -> DiskBspNode.
inline DiskBspNode to_disk(const world::BspNode& n) {
    DiskBspNode d{};
    d.plane = n.plane;
    d.front = n.front;
    d.back = n.back;
    put(d.bounds_min, n.bounds_min);
    put(d.bounds_max, n.bounds_max);
    return d;
}

/// DiskBspNode -> BSP node.
inline world::BspNode from_disk(const DiskBspNode& d) {
    world::BspNode n;
    n.plane = d.plane;
    n.front = d.front;
    n.back = d.back;
    n.bounds_min = vec(d.bounds_min);
    n.bounds_max = vec(d.bounds_max);
    return n;
}

/// BSP leaf -> DiskBspLeaf.
inline DiskBspLeaf to_disk(const world::BspLeaf& l) {
    DiskBspLeaf d{};
    d.first_triangle = l.first_triangle;
    d.triangle_count = l.triangle_count;
    d.first_surface = l.first_surface;
    d.surface_count = l.surface_count;
    put(d.bounds_min, l.bounds_min);
    put(d.bounds_max, l.bounds_max);
    return d;
}

/// DiskBspLeaf -> BSP leaf.
inline world::BspLeaf from_disk(const DiskBspLeaf& d) {
    world::BspLeaf l;
    l.first_triangle = d.first_triangle;
    l.triangle_count = d.triangle_count;
    l.first_surface = d.first_surface;
    l.surface_count = d.surface_count;
    l.bounds_min = vec(d.bounds_min);
    l.bounds_max = vec(d.bounds_max);
    return l;
}

/// Dynamic mesh -> DiskDynamicMesh; appends the name to `blobs`.
inline DiskDynamicMesh to_disk(const world::DynamicMesh& m, BlobWriter& blobs) {
    DiskDynamicMesh d{};
    d.name = blobs.add_string(m.name);
    d.material = m.material;
    d.first_vertex = m.first_vertex;
    d.vertex_count = m.vertex_count;
    d.first_index = m.first_index;
    d.index_count = m.index_count;
    return d;
}

/// DiskDynamicMesh -> dynamic mesh, the name read from `blobs`.
inline world::DynamicMesh from_disk(const DiskDynamicMesh& d, const BlobReader& blobs) {
    world::DynamicMesh m;
    m.name = blobs.string(d.name);
    m.material = d.material;
    m.first_vertex = d.first_vertex;
    m.vertex_count = d.vertex_count;
    m.first_index = d.first_index;
    m.index_count = d.index_count;
    return m;
}

/// Entity -> DiskEntity; appends the name to `blobs`.
inline DiskEntity to_disk(const world::Entity& e, BlobWriter& blobs) {
    DiskEntity d{};
    d.name = blobs.add_string(e.name);
    d.flags = e.flags;
    d.first_dynamic_mesh = e.first_dynamic_mesh;
    d.dynamic_mesh_count = e.dynamic_mesh_count;
    d.mover_period = e.mover_period;
    put(d.position, e.position);
    put(d.rotation, e.rotation);
    put(d.scale, e.scale);
    put(d.mover_offset, e.mover_offset);
    put(d.probe_box_min, e.probe_box_min);
    put(d.probe_box_max, e.probe_box_max);
    return d;
}

/// DiskEntity -> entity, the name read from `blobs`.
inline world::Entity from_disk(const DiskEntity& d, const BlobReader& blobs) {
    world::Entity e;
    e.name = blobs.string(d.name);
    e.flags = d.flags;
    e.first_dynamic_mesh = d.first_dynamic_mesh;
    e.dynamic_mesh_count = d.dynamic_mesh_count;
    e.mover_period = d.mover_period;
    e.position = vec(d.position);
    e.rotation = quat(d.rotation);
    e.scale = vec(d.scale);
    e.mover_offset = vec(d.mover_offset);
    e.probe_box_min = vec(d.probe_box_min);
    e.probe_box_max = vec(d.probe_box_max);
    return e;
}

/// Features -> DiskFeatures.
inline DiskFeatures to_disk(const world::Features& f) {
    DiskFeatures d{};
    d.flags = f.flags;
    d.material_classes = f.material_classes;
    d.primary_light_types = f.primary_light_types;
    d.baked_light_types = f.baked_light_types;
    d.primary_count = f.primary_count;
    d.baked_light_count = f.baked_light_count;
    d.effect_omni_count = f.effect_omni_count;
    d.effect_spot_count = f.effect_spot_count;
    d.probe_count = f.probe_count;
    put(d.grid_min, f.grid_min);
    put(d.grid_max, f.grid_max);
    return d;
}

/// DiskFeatures -> features.
inline world::Features from_disk(const DiskFeatures& d) {
    world::Features f;
    f.flags = d.flags;
    f.material_classes = d.material_classes;
    f.primary_light_types = d.primary_light_types;
    f.baked_light_types = d.baked_light_types;
    f.primary_count = d.primary_count;
    f.baked_light_count = d.baked_light_count;
    f.effect_omni_count = d.effect_omni_count;
    f.effect_spot_count = d.effect_spot_count;
    f.probe_count = d.probe_count;
    f.grid_min = vec(d.grid_min);
    f.grid_max = vec(d.grid_max);
    return f;
}

/// Lightmap texel -> DiskLightmapTexel.
inline DiskLightmapTexel to_disk(const world::LightmapTexel& t) {
    DiskLightmapTexel d{};
    put(d.irradiance, t.irradiance);
    put(d.direction, t.direction);
    d.normal_weight = t.normal_weight;
    d.flags = t.flags;
    return d;
}

/// DiskLightmapTexel -> lightmap texel.
inline world::LightmapTexel from_disk(const DiskLightmapTexel& d) {
    world::LightmapTexel t;
    t.irradiance = vec(d.irradiance);
    t.direction = vec(d.direction);
    t.normal_weight = d.normal_weight;
    t.flags = d.flags;
    return t;
}

/// The light grid's layout and the bake's shard -> DiskLightGridHeader (cell_count from the cells).
inline DiskLightGridHeader to_disk_grid_header(const world::BakedLighting& baked) {
    DiskLightGridHeader d{};
    put(d.origin, baked.grid.origin);
    put(d.cell_size, baked.grid.cell_size);
    for (int a = 0; a < 3; ++a) d.dims[a] = baked.grid.dims[a];
    d.cell_count = static_cast<uint32_t>(baked.grid.cells.size());
    d.shard_index = baked.shard_index;
    d.shard_count = baked.shard_count;
    d.samples = baked.grid.samples;
    return d;
}

/// DiskLightGridHeader -> the grid's origin, cell size, dims and samples and the shard in
/// `baked` (its cells untouched).
inline void from_disk_grid_header(const DiskLightGridHeader& d, world::BakedLighting& baked) {
    baked.grid.origin = vec(d.origin);
    baked.grid.cell_size = vec(d.cell_size);
    baked.grid.dims = glm::uvec3(d.dims[0], d.dims[1], d.dims[2]);
    baked.grid.samples = d.samples;
    baked.shard_index = d.shard_index;
    baked.shard_count = d.shard_count;
}

/// Light grid cell -> DiskLightGridCell.
inline DiskLightGridCell to_disk(const world::LightGridCell& c) {
    DiskLightGridCell d{};
    for (size_t f = 0; f < 6; ++f) put(d.ambient_cube[f], c.ambient_cube[f]);
    d.dominant_primary = c.dominant_primary == world::kNoIndex ? kNoIndex : c.dominant_primary;
    d.primary_visibility = c.primary_visibility;
    d.flags = c.flags;
    return d;
}

/// DiskLightGridCell -> light grid cell.
inline world::LightGridCell from_disk(const DiskLightGridCell& d) {
    world::LightGridCell c;
    for (size_t f = 0; f < 6; ++f) c.ambient_cube[f] = vec(d.ambient_cube[f]);
    c.dominant_primary = d.dominant_primary == kNoIndex ? world::kNoIndex : d.dominant_primary;
    c.primary_visibility = d.primary_visibility;
    c.flags = d.flags;
    return c;
}

/// Environment probe -> DiskProbe, its texels placed at `first_texel` of the section's texels.
inline DiskProbe to_disk(const world::EnvironmentProbe& p, uint32_t first_texel) {
    DiskProbe d{};
    put(d.position, p.position);
    put(d.box_min, p.box_min);
    put(d.box_max, p.box_max);
    put(d.irradiance_average, p.irradiance_average);
    d.face_size = p.face_size;
    d.mip_count = p.mip_count;
    d.first_texel = first_texel;
    d.texel_count = static_cast<uint32_t>(p.texels.size());
    d.entity = p.entity == world::kNoIndex ? kNoIndex : p.entity;
    return d;
}

/// DiskProbe -> environment probe, its texels copied from `texel_bytes` (all of the section's
/// texels, 4 bytes each).
inline world::EnvironmentProbe from_disk(const DiskProbe& d, std::span<const uint8_t> texel_bytes) {
    world::EnvironmentProbe p;
    p.position = vec(d.position);
    p.box_min = vec(d.box_min);
    p.box_max = vec(d.box_max);
    p.irradiance_average = vec(d.irradiance_average);
    p.face_size = d.face_size;
    p.mip_count = d.mip_count;
    p.entity = d.entity == kNoIndex ? world::kNoIndex : d.entity;
    const std::span<const uint8_t> bytes =
        slice(texel_bytes, uint64_t(d.first_texel) * 4, uint64_t(d.texel_count) * 4);
    p.texels.resize(bytes.size() / 4);
    if (!bytes.empty()) std::memcpy(p.texels.data(), bytes.data(), bytes.size());
    return p;
}

}  // namespace records

using records::from_disk;
using records::from_disk_grid_header;
using records::to_disk;
using records::to_disk_grid_header;

}  // namespace onelight::package
