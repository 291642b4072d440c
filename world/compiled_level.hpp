// The compiled level in memory: what the compiler produces, what the .olpak writer stores and
// what the reader gives back to the baker and the runtime. Plain data; the on-disk twin of each
// type lives in package/format.hpp and is a different type.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <glm/gtc/quaternion.hpp>
#include "world/collision.hpp"
#include "world/gloss_mip_method.hpp"
#include "world/movers.hpp"
#include "world/no_index.hpp"

namespace onelight::world {

enum class LightType : uint8_t { kDirectional = 0, kPoint = 1, kSpot = 2 };
enum class LightRole : uint8_t { kPrimary = 0, kBaked = 1, kEffect = 2 };

/// A KHR_lights_punctual light in its glTF units, placed in world space.
struct Light {
    std::string name;  // node name (light name when the node has none)
    LightType type = LightType::kPoint;
    LightRole role = LightRole::kPrimary;
    glm::vec3 color{1.0f};                   // linear RGB, multiplies intensity
    float intensity = 1.0f;                  // lux (directional) or candela (point, spot)
    float range = 0.0f;                      // metres; 0 = unlimited
    float innerCone = 0.0f;                  // radians, spot only, 0 <= inner < outer
    float outerCone = 0.785398163f;          // radians, spot only, <= pi/2
    glm::vec3 position{0.0f};                // metres, world space (unused for directional)
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit, world space, the way the light travels
};

/// Shader permutation a material needs (docs/lighting.md "Material classes").
enum class MaterialClass : uint8_t { kMetal = 0, kDielectric = 1, kFull = 2, kLambert = 3 };
enum class AlphaMode : uint8_t { kOpaque = 0, kMask = 1, kBlend = 2 };

/// A glTF metallic-roughness material converted to the engine's parameters:
///   albedo         = baseColor.rgb * (1 - metallic)
///   specularColor = mix(0.04, baseColor.rgb, metallic)
///   gloss          = saturate(log2(2 / roughness^4 - 1) / 18)   (inverse of
///                    ggxAlpha_fromGloss with GGX alpha = roughness^2)
/// When textures are present these are the factors: the runtime and the baker apply the same
/// formula per texel to the glTF textures (shaders/material.glsl; the baker at every ray hit,
/// bake/materials).
struct Material {
    std::string name;
    glm::vec4 baseColor{1.0f};       // linear RGBA factor
    float metallic = 1.0f;           // glTF factor [0,1]
    float roughness = 1.0f;          // glTF perceptual roughness factor [0,1]
    glm::vec3 albedo{1.0f};          // diffuse reflectance, linear
    glm::vec3 specularColor{0.04f};  // F0, linear
    float gloss = 0.0f;              // [0,1], GGX alpha = sqrt(2 / (1 + 2^(18 gloss)))
    glm::vec3 emissive{0.0f};        // cd/m^2: emissiveFactor x KHR_materials_emissive_strength
    float alphaCutoff = 0.5f;        // used when alphaMode == mask
    AlphaMode alphaMode = AlphaMode::kOpaque;
    bool doubleSided = false;
    // false: light passes the surface in the bake, the reference and the runtime's shadow maps
    // although it is drawn (a Quake 3 translucent surface, as q3map2 lights it: q3_import.hpp).
    bool castsShadows = true;
    MaterialClass materialClass = MaterialClass::kFull;
    uint32_t baseColorTexture = kNoIndex;          // index into textures
    uint32_t metallicRoughnessTexture = kNoIndex;  // index into textures
    uint32_t normalTexture = kNoIndex;             // index into textures
    uint32_t occlusionTexture = kNoIndex;          // index into textures
    uint32_t emissiveTexture = kNoIndex;           // index into textures
    float normalScale = 1.0f;
    float occlusionStrength = 1.0f;
};

/// glTF sampler, with glTF's GL enum values (0 = unspecified filter).
struct Sampler {
    uint16_t magFilter = 0;
    uint16_t minFilter = 0;
    uint16_t wrapS = 10497;  // REPEAT
    uint16_t wrapT = 10497;
};

struct Texture {
    uint32_t image = kNoIndex;  // index into images
    Sampler sampler;
};

/// An image is a file reference (uri relative to the package's folder) or, when the glTF
/// embeds it, the encoded bytes (PNG/JPEG) as they were. Pixels are never decoded here.
struct Image {
    std::string name;
    std::string uri;       // empty when embedded
    std::string mimeType;  // may be empty for file references
    std::vector<uint8_t> encodedBytes;
};

struct Camera {
    std::string name;  // node name: what --camera NAME matches
    bool orthographic = false;
    float yfov = 0.8f;               // radians (perspective)
    float aspectRatio = 0.0f;        // 0 = use the window's
    float znear = 0.01f;             // metres
    float zfar = 0.0f;               // metres; 0 = infinite
    float xmag = 1.0f, ymag = 1.0f;  // metres (orthographic)
    glm::vec3 position{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // world from camera; the camera looks down -Z
    float exposureEv100 = 0.0f;                  // valid when hasExposure
    bool hasExposure = false;
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
    uint32_t firstIndex = 0;       // into indices, multiple of 3
    uint32_t indexCount = 0;       // multiple of 3, > 0
    uint32_t material = kNoIndex;  // into materials
    uint32_t primaryLight =
        kNoIndex;               // into lights (role primary); kNoIndex when the level has none
    uint32_t chart = kNoIndex;  // into charts
    uint32_t atlas = kNoIndex;  // into atlases (== charts[chart].atlas)
    uint32_t lightmapX = 0, lightmapY = 0;           // texels, chart rectangle in the atlas
    uint32_t lightmapWidth = 0, lightmapHeight = 0;  // texels, padding included
    uint32_t firstGivenUp = 0;                       // into given_up_lights
    uint32_t givenUpCount = 0;  // primaries reaching this surface that it bakes as secondary
    uint32_t leaf = 0;          // into bsp_leaves
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // metres, world space
};

/// A lightmap chart: a rectangle of an atlas and, for generated charts, the planar projection
/// used to make its lightmap coordinates.
struct Chart {
    uint32_t atlas = 0;
    uint32_t x = 0, y = 0, width = 0, height = 0;  // texels, padding included
    uint32_t padding = 2;                          // texels on each side
    float texelsPerMetre = 0.0f;  // density actually used (may be below the request)
    bool authored = false;        // true: coordinates came from TEXCOORD_1
    glm::vec3 origin{0.0f};       // world point of texel (x + padding, y + padding)
    glm::vec3 axisU{1.0f, 0.0f, 0.0f}, axisV{0.0f, 1.0f, 0.0f};  // unit, world space
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
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // of every triangle below, metres
};

struct BspLeaf {
    uint32_t firstTriangle = 0, triangleCount = 0;  // triangles = index triples
    uint32_t firstSurface = 0, surfaceCount = 0;    // into surfaces
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
};

/// A dynamic mesh primitive in its own (node-local) space.
struct DynamicMesh {
    std::string name;
    uint32_t material = kNoIndex;
    uint32_t firstVertex = 0, vertexCount = 0;  // into dynamic_vertices
    uint32_t firstIndex = 0, indexCount = 0;    // into dynamic_indices (relative to firstVertex)
};

enum EntityFlags : uint32_t {
    kEntityDynamic = 1u << 0,    // owns dynamic meshes, lit by the grid
    kEntityMover = 1u << 1,      // moved by a mover (world/movers.hpp)
    kEntitySpawn = 1u << 2,      // a player spawn point
    kEntityProbe = 1u << 3,      // an environment probe position
    kEntityItem = 1u << 4,       // a pickup: spins and bobs, taken on touch, back after itemRespawn
    kEntitySuspended = 1u << 5,  // an item that hangs where placed (else it drops to the floor)
};
inline constexpr uint32_t kAllEntityFlags =
    kEntityDynamic | kEntityMover | kEntitySpawn | kEntityProbe | kEntityItem | kEntitySuspended;

/// A node the game or the baker needs by name: dynamic meshes, movers, spawns, probes.
struct Entity {
    std::string name;
    uint32_t flags = 0;  // EntityFlags
    glm::vec3 position{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    uint32_t firstDynamicMesh = 0, dynamicMeshCount = 0;
    glm::vec3 probeBoxMin{0.0f}, probeBoxMax{0.0f};  // world; empty box = no box projection
    float itemRespawn = 0.0f;  // items: seconds taken before it comes back; < 0 never
};

enum FeatureFlags : uint32_t {
    kFeatureLightmaps = 1u << 0,  // static surfaces exist
    kFeatureLightGrid = 1u << 1,  // dynamic entities exist
    kFeatureProbes = 1u << 2,     // some material has specular
    kFeatureNormalMaps = 1u << 3,
    kFeatureAlphaMask = 1u << 4,
    kFeatureAlphaBlend = 1u << 5,
    kFeatureEmissive = 1u << 6,
    kFeatureDoubleSided = 1u << 7,
    kFeatureEffectOmni = 1u << 8,   // gun-flash lights (<= 4 at a time)
    kFeatureEffectSpot = 1u << 9,   // flashlight (<= 1)
    kFeatureAutoProbes = 1u << 10,  // no probe given: the baker places them
    kFeatureAuthoredGrid = 1u << 11,
};

/// What the level needs, so only that is built (docs/architecture.md "Principles", 3).
struct Features {
    uint32_t flags = 0;              // FeatureFlags
    uint32_t materialClasses = 0;    // bit (1 << MaterialClass)
    uint32_t primaryLightTypes = 0;  // bit (1 << LightType) over primaries used by surfaces
    uint32_t bakedLightTypes = 0;    // bit (1 << LightType) over baked lights
    uint32_t primaryCount = 0;       // primaries used by at least one surface
    uint32_t bakedLightCount = 0;
    uint32_t effectOmniCount = 0;
    uint32_t effectSpotCount = 0;
    uint32_t probeCount = 0;                 // authored probes
    glm::vec3 gridMin{0.0f}, gridMax{0.0f};  // light grid extent, world metres
};

/// Level-wide settings and measures.
/// The diffuse BRDF of a level (shaders/lighting.glsl DIFFUSE_*): Lambert, or Lambertian
/// microfacets with multiple scattering (Chan 2018, sec. 5).
enum class DiffuseModel : uint8_t { kLambert = 0, kMultiscatter = 1 };

struct LevelSettings {
    float exposureEv100 = 0.0f;  // default exposure (extras.onelight.exposure)
    bool hasExposure = false;
    float texelsPerMetre = 0.0f;                 // requested lightmap density
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // static geometry, metres
    float probeSpacing = 0.0f;                   // metres between automatic probes; 0 = unset
    glm::vec3 skyRadiance{0.0f};   // cd/m^2, RGB: the uniform sky (0 = none), or skyImage's scale
    uint32_t skyImage = kNoIndex;  // into images: an equirectangular HDR sky (shaders/sky.glsl)
    DiffuseModel diffuseModel = DiffuseModel::kLambert;  // extras.onelight.diffuse
    // extras.onelight.gloss_mips: by default the method of lower error (docs/materials.md)
    GlossMipMethod glossMips = GlossMipMethod::kClean;
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
    std::vector<uint32_t> givenUpLights;  // into lights
    std::vector<Chart> charts;
    std::vector<Atlas> atlases;
    std::vector<BspPlane> bspPlanes;
    std::vector<BspNode> bspNodes;   // root is node 0 when non-empty
    std::vector<BspLeaf> bspLeaves;  // an empty level has one empty leaf and no node
    std::vector<Vertex> dynamicVertices;
    std::vector<uint32_t> dynamicIndices;
    std::vector<DynamicMesh> dynamicMeshes;
    std::vector<Entity> entities;
    Features features;
    LevelCollision collision;  // a Quake 3 map's brushes and triggers; empty for glTF levels
    LevelMovers movers;        // what moves the movers' entities (kEntityMover)
};

}  // namespace onelight::world
