// The compiled level in memory: what the compiler produces, what the .olpak writer stores and
// what the reader gives back to the baker and the runtime. Plain data; the on-disk twin of each
// type lives in package/format.hpp and is a different type.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <glm/gtc/quaternion.hpp>
#include "world/no_index.hpp"

namespace onelight::world {

enum class LightType : uint8_t { directional = 0, point = 1, spot = 2 };
enum class LightRole : uint8_t { primary = 0, baked = 1, effect = 2 };

/// A KHR_lights_punctual light in its glTF units, placed in world space.
struct Light {
    std::string name;  // node name (light name when the node has none)
    LightType type = LightType::point;
    LightRole role = LightRole::primary;
    glm::vec3 color{1.0f};                   // linear RGB, multiplies intensity
    float intensity = 1.0f;                  // lux (directional) or candela (point, spot)
    float range = 0.0f;                      // metres; 0 = unlimited
    float inner_cone = 0.0f;                 // radians, spot only, 0 <= inner < outer
    float outer_cone = 0.785398163f;         // radians, spot only, <= pi/2
    glm::vec3 position{0.0f};                // metres, world space (unused for directional)
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit, world space, the way the light travels
};

/// Shader permutation a material needs (docs/lighting.md "Material classes").
enum class MaterialClass : uint8_t { metal = 0, dielectric = 1, full = 2, lambert = 3 };
enum class AlphaMode : uint8_t { opaque = 0, mask = 1, blend = 2 };

/// A glTF metallic-roughness material converted to the engine's parameters:
///   albedo         = baseColor.rgb * (1 - metallic)
///   specular_color = mix(0.04, baseColor.rgb, metallic)
///   gloss          = saturate(log2(2 / roughness^4 - 1) / 18)   (inverse of
///                    ggxAlpha_fromGloss with GGX alpha = roughness^2)
/// When textures are present these are the factors: the runtime applies the same formula per
/// texel to the glTF textures (shaders/material.glsl) and the baker shades with the factors
/// alone. Texture processing in the baker is planned, not built.
struct Material {
    std::string name;
    glm::vec4 base_color{1.0f};       // linear RGBA factor
    float metallic = 1.0f;            // glTF factor [0,1]
    float roughness = 1.0f;           // glTF perceptual roughness factor [0,1]
    glm::vec3 albedo{1.0f};           // diffuse reflectance, linear
    glm::vec3 specular_color{0.04f};  // F0, linear
    float gloss = 0.0f;               // [0,1], GGX alpha = sqrt(2 / (1 + 2^(18 gloss)))
    glm::vec3 emissive{0.0f};         // linear factor
    float alpha_cutoff = 0.5f;        // used when alpha_mode == mask
    AlphaMode alpha_mode = AlphaMode::opaque;
    bool double_sided = false;
    MaterialClass material_class = MaterialClass::full;
    uint32_t base_color_texture = kNoIndex;          // index into textures
    uint32_t metallic_roughness_texture = kNoIndex;  // index into textures
    uint32_t normal_texture = kNoIndex;              // index into textures
    uint32_t occlusion_texture = kNoIndex;           // index into textures
    uint32_t emissive_texture = kNoIndex;            // index into textures
    float normal_scale = 1.0f;
    float occlusion_strength = 1.0f;
};

/// glTF sampler, with glTF's GL enum values (0 = unspecified filter).
struct Sampler {
    uint16_t mag_filter = 0;
    uint16_t min_filter = 0;
    uint16_t wrap_s = 10497;  // REPEAT
    uint16_t wrap_t = 10497;
};

struct Texture {
    uint32_t image = kNoIndex;  // index into images
    Sampler sampler;
};

/// An image is a file reference (uri relative to the package's folder) or, when the glTF
/// embeds it, the encoded bytes (PNG/JPEG) as they were. Pixels are never decoded here.
struct Image {
    std::string name;
    std::string uri;        // empty when embedded
    std::string mime_type;  // may be empty for file references
    std::vector<uint8_t> encoded_bytes;
};

struct Camera {
    std::string name;  // node name: what --camera NAME matches
    bool orthographic = false;
    float yfov = 0.8f;               // radians (perspective)
    float aspect_ratio = 0.0f;       // 0 = use the window's
    float znear = 0.01f;             // metres
    float zfar = 0.0f;               // metres; 0 = infinite
    float xmag = 1.0f, ymag = 1.0f;  // metres (orthographic)
    glm::vec3 position{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // world from camera; the camera looks down -Z
    float exposure_ev100 = 0.0f;                 // valid when has_exposure
    bool has_exposure = false;
};

/// Engine-side vertex; static vertices are in world space, dynamic ones in their mesh's space.
struct Vertex {
    glm::vec3 position{0.0f};                   // metres
    glm::vec3 normal{0.0f, 0.0f, 1.0f};         // unit
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // xyz unit, w = bitangent sign (+-1)
    glm::vec2 uv0{0.0f};                        // material texture coordinates
    glm::vec2 uv1{0.0f};  // lightmap coordinates, normalised over the surface's atlas
};

/// A run of static triangles with one material, one primary light and one lightmap chart,
/// inside one BSP leaf. Lightmap placement lives here (chart rectangle copied from charts).
struct Surface {
    uint32_t first_index = 0;      // into indices, multiple of 3
    uint32_t index_count = 0;      // multiple of 3, > 0
    uint32_t material = kNoIndex;  // into materials
    uint32_t primary_light =
        kNoIndex;               // into lights (role primary); kNoIndex when the level has none
    uint32_t chart = kNoIndex;  // into charts
    uint32_t atlas = kNoIndex;  // into atlases (== charts[chart].atlas)
    uint32_t lightmap_x = 0, lightmap_y = 0;           // texels, chart rectangle in the atlas
    uint32_t lightmap_width = 0, lightmap_height = 0;  // texels, padding included
    uint32_t first_given_up = 0;                       // into given_up_lights
    uint32_t given_up_count = 0;  // primaries reaching this surface that it bakes as secondary
    uint32_t leaf = 0;            // into bsp_leaves
    glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};  // metres, world space
};

/// A lightmap chart: a rectangle of an atlas and, for generated charts, the planar projection
/// used to make its lightmap coordinates.
struct Chart {
    uint32_t atlas = 0;
    uint32_t x = 0, y = 0, width = 0, height = 0;  // texels, padding included
    uint32_t padding = 2;                          // texels on each side
    float texels_per_metre = 0.0f;  // density actually used (may be below the request)
    bool authored = false;          // true: coordinates came from TEXCOORD_1
    glm::vec3 origin{0.0f};         // world point of texel (x + padding, y + padding)
    glm::vec3 axis_u{1.0f, 0.0f, 0.0f}, axis_v{0.0f, 1.0f, 0.0f};  // unit, world space
};

struct Atlas {
    uint32_t width = 0, height = 0;  // texels
};

struct BspPlane {
    glm::dvec3 normal{0.0, 0.0, 1.0};  // unit
    double distance = 0.0;             // dot(normal, p) == distance on the plane, metres
};

/// child >= 0 is a node index; child < 0 is leaf index -(child + 1).
struct BspNode {
    uint32_t plane = 0;
    int32_t front = -1, back = -1;
    glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};  // of every triangle below, metres
};

struct BspLeaf {
    uint32_t first_triangle = 0, triangle_count = 0;  // triangles = index triples
    uint32_t first_surface = 0, surface_count = 0;    // into surfaces
    glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};
};

/// A dynamic mesh primitive in its own (node-local) space.
struct DynamicMesh {
    std::string name;
    uint32_t material = kNoIndex;
    uint32_t first_vertex = 0, vertex_count = 0;  // into dynamic_vertices
    uint32_t first_index = 0, index_count = 0;    // into dynamic_indices (relative to first_vertex)
};

enum EntityFlags : uint32_t {
    entity_dynamic = 1u << 0,  // owns dynamic meshes, lit by the grid
    entity_mover = 1u << 1,    // moves back and forth by mover_offset over mover_period
    entity_spawn = 1u << 2,    // a player spawn point
    entity_probe = 1u << 3,    // an environment probe position
};
inline constexpr uint32_t kAllEntityFlags =
    entity_dynamic | entity_mover | entity_spawn | entity_probe;

/// A node the game or the baker needs by name: dynamic meshes, movers, spawns, probes.
struct Entity {
    std::string name;
    uint32_t flags = 0;  // EntityFlags
    glm::vec3 position{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    uint32_t first_dynamic_mesh = 0, dynamic_mesh_count = 0;
    glm::vec3 mover_offset{0.0f};  // metres, world space
    float mover_period = 0.0f;     // seconds for a full back-and-forth; > 0 for movers
    glm::vec3 probe_box_min{0.0f}, probe_box_max{0.0f};  // world; empty box = no box projection
};

enum FeatureFlags : uint32_t {
    feature_lightmaps = 1u << 0,   // static surfaces exist
    feature_light_grid = 1u << 1,  // dynamic entities exist
    feature_probes = 1u << 2,      // some material has specular
    feature_normal_maps = 1u << 3,
    feature_alpha_mask = 1u << 4,
    feature_alpha_blend = 1u << 5,
    feature_emissive = 1u << 6,
    feature_double_sided = 1u << 7,
    feature_effect_omni = 1u << 8,   // gun-flash lights (<= 4 at a time)
    feature_effect_spot = 1u << 9,   // flashlight (<= 1)
    feature_auto_probes = 1u << 10,  // no probe given: the baker places them
    feature_authored_grid = 1u << 11,
};

/// What the level needs, so only that is built (docs/architecture.md "Principles", 3).
struct Features {
    uint32_t flags = 0;                // FeatureFlags
    uint32_t material_classes = 0;     // bit (1 << MaterialClass)
    uint32_t primary_light_types = 0;  // bit (1 << LightType) over primaries used by surfaces
    uint32_t baked_light_types = 0;    // bit (1 << LightType) over baked lights
    uint32_t primary_count = 0;        // primaries used by at least one surface
    uint32_t baked_light_count = 0;
    uint32_t effect_omni_count = 0;
    uint32_t effect_spot_count = 0;
    uint32_t probe_count = 0;                  // authored probes
    glm::vec3 grid_min{0.0f}, grid_max{0.0f};  // light grid extent, world metres
};

/// Level-wide settings and measures.
struct LevelSettings {
    float exposure_ev100 = 0.0f;  // default exposure (extras.onelight.exposure)
    bool has_exposure = false;
    float texels_per_metre = 0.0f;                 // requested lightmap density
    glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};  // static geometry, metres
    float probe_spacing = 0.0f;                    // metres between automatic probes; 0 = unset
    glm::vec3 sky_radiance{0.0f};                  // cd/m^2, RGB: the uniform sky, 0 = none
};

struct CompiledLevel {
    LevelSettings settings;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Image> images;
    std::vector<Light> lights;
    std::vector<Camera> cameras;
    std::vector<Vertex> vertices;   // static, world space
    std::vector<uint32_t> indices;  // static triangles, grouped by leaf then surface
    std::vector<Surface> surfaces;
    std::vector<uint32_t> given_up_lights;  // into lights
    std::vector<Chart> charts;
    std::vector<Atlas> atlases;
    std::vector<BspPlane> bsp_planes;
    std::vector<BspNode> bsp_nodes;   // root is node 0 when non-empty
    std::vector<BspLeaf> bsp_leaves;  // an empty level has one empty leaf and no node
    std::vector<Vertex> dynamic_vertices;
    std::vector<uint32_t> dynamic_indices;
    std::vector<DynamicMesh> dynamic_meshes;
    std::vector<Entity> entities;
    Features features;
};

}  // namespace onelight::world
