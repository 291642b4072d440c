// The level as the renderer holds it, uploaded once at createRenderer: the CPU copy of what a
// frame reads (LevelData), and the GPU scene in owned parts, each with its create and destroy
// (scene.cpp), gathered in Scene and created in the order of its fields.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "assets/level_assets.hpp"
#include "render/gpu_types.hpp"
#include "render/renderer.hpp"
#include "vk/buffer.hpp"
#include "vk/context.hpp"
#include "vk/image.hpp"
#include "world/baked_lighting.hpp"

namespace onelight::render {

/// What a frame reads of the level on the CPU (copied from the package), and the exposure and
/// ambient worked out from it. No GPU objects.
struct LevelData {
    world::LevelSettings settings;
    std::vector<world::Light> lights;
    std::vector<world::Entity> entities;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // the level's, widened by the entities
    float ambientLux = 0.0f;  // the placeholder ambient (options, else 10% of the reference)
    float autoEv100 = 0.0f;   // exposure when neither camera nor level gives one
};

/// Samplers and lookup tables every pass may read.
struct LookupTables {
    VkSampler linearClamp = VK_NULL_HANDLE;   // owned: baked data, LUT, placeholders
    VkSampler nearestClamp = VK_NULL_HANDLE;  // owned: HDR in the tonemap
    vk::Image lut;                            // owned, the 64^3 filmic colour LUT
    vk::Image envBrdf;  // owned, the split-sum table (env_brdf_table.hpp), half floats
};

/// A static surface as the renderer draws it.
struct DrawSurface {
    uint32_t firstIndex = 0, indexCount = 0;
    uint32_t material = 0, primaryLight = kNoIndex, atlas = kNoIndex;
    uint32_t primaryKind = 0;  // PRIMARY_*: none, else its primary light's type
    // Its baked shadow mask is fully lit over all of it (world/surface_shadow.hpp): drawn
    // without its primary's shadow lookups while no dynamic caster's shadow may reach it. (A
    // surface the mask shadows whole is drawn without its primary: primaryKind PRIMARY_NONE.)
    bool unoccluded = false;
    // Some texel of its lightmap draws its baked direct light's shadow edge (world/
    // surface_shadow.hpp surfaceDirectEdges): the others are drawn without the edge's fetches.
    bool directEdges = false;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
};

/// A dynamic mesh with its object-space bounds.
struct DrawDynamicMesh {
    uint32_t entity = 0;
    uint32_t firstIndex = 0, indexCount = 0;  // into the shared index buffer
    int32_t vertexOffset = 0;                 // into the shared vertex buffer
    uint32_t material = 0;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // object space
    bool castsShadow = true;  // false for an item: Quake 3 draws items without shadows
};

/// The level's vertices and indices (static, then dynamic) and the draws into them.
struct SceneGeometry {
    vk::Buffer vertices, indices;  // owned, device-local
    std::vector<DrawSurface> surfaces;
    std::vector<DrawDynamicMesh> dynamicMeshes;
    bool dynamicCasters = false;  // some dynamic mesh casts a runtime shadow
    // The PRIMARY_* a dynamic mesh may be drawn with (the pipelines made for it): none, and the
    // types of the level's primary lights, sorted.
    std::vector<uint32_t> dynamicPrimaryKinds;
    // Per entity, object space: the bounds of its dynamic meshes (min > max without any).
    std::vector<glm::vec3> entityBoundsMin, entityBoundsMax;
};

/// A material's texture slots (TEXTURE_* of gpu_interface.glsl): view and sampler each.
using MaterialTextures =
    std::array<std::pair<VkImageView, VkSampler>, size_t(glsl::TEXTURE_SLOT_COUNT)>;

/// The materials: their GPU records, their decoded textures and samplers, and what picks their
/// forward permutation. At least one material (a default when the level has none).
struct SceneMaterials {
    // Owned: GpuMaterial per material, in pages of glsl::MAX_MATERIAL_RECORDS (frame set 0's
    // materialRecords[], bound a page at a time), the last page padded when there are several.
    vk::Buffer records;
    VkDeviceSize pageBytes = sizeof(GpuMaterial);  // a page's range: min(materials, a page)
    std::deque<vk::Image> textures;                // owned, decoded level images (never moved)
    std::map<uint64_t, uint32_t> textureIndex;     // (image << 1 | srgb) -> textures
    std::map<uint64_t, VkSampler> samplers;        // owned, by glTF sampler state
    vk::Image white, flatNormal;                   // owned, placeholders for missing textures
    std::vector<MaterialTextures> bound;           // per material: views and samplers, borrowed
    std::vector<uint8_t> classes;                  // per material, after forceMaterialClass
    std::vector<uint8_t> doubleSided;              // per material
    std::vector<uint8_t> alphaMode;                // per material: world::AlphaMode
    std::vector<uint8_t> castsShadows;             // per material: 0 if light passes it
    std::vector<glm::vec2> maskAlpha;   // per material: the base colour's alpha factor, the cutoff
    std::vector<uint8_t> textureSlots;  // per material: bit mask of TEXTURE_* filled
};

/// Baked lighting from the package, or neutral placeholders (see createBakedLighting).
struct BakedLightingMaps {
    bool present = false;                 // the level has it: the fetching permutation
    vk::Image lightmap;                   // owned, RGBA16F 2D array, 3 layers per atlas
    vk::Image shadowMask;                 // owned, RGBA8 2D array, a layer per atlas
    float lightmapDecode = 1.0f;          // lux per stored lightmap unit (a power of two)
    std::vector<glm::vec2> atlasUvScale;  // per atlas: uv1 to the lightmap array's uv
    world::LightGrid grid;                // empty without baked lighting
    world::Visibility visibility;         // the package's potentially visible set; may be empty
    // Each cluster's surfaces' bounds (world), for culling a dynamic object by the clusters
    // around it (frame_view.cpp); empty without visibility.
    std::vector<glm::vec3> clusterMin, clusterMax;
};

/// The environment probes' cube array and records, or one uniform placeholder cube.
struct EnvironmentProbes {
    vk::Image cubes;     // owned, one cube per record
    vk::Buffer records;  // owned, GpuProbe records (render/probe_records.hpp)
    vk::Buffer cells;    // owned, GpuProbeGrid and the cells' record lists
    uint32_t count = 1;  // records; the cube array holds as many cubes
    uint32_t mips = 1;
    uint32_t baked = 0;  // the package's probes in use (0: the placeholder)
    uint64_t bytes = 0;  // their cube array, every mip
};

/// The sky image (RGBA16F, the decoded .hdr unscaled), a black texel when the level has none.
struct SkyImage {
    vk::Image image;                     // owned
    VkSampler sampler = VK_NULL_HANDLE;  // owned: linear, repeating in u, clamped in v
    bool present = false;                // the level's sky is an image: the sky pass draws it
};

/// The whole scene, created field by field in this order and destroyed in reverse.
struct Scene {
    LevelData level;
    LookupTables tables;
    SceneGeometry geometry;
    SceneMaterials materials;  // borrows tables.linearClamp for its placeholders
    BakedLightingMaps baked;
    EnvironmentProbes probes;
    SkyImage sky;
};

void createScene(const vk::Context& ctx, Scene& scene, const assets::LoadedLevel& loaded,
                 const RendererOptions& options);
void destroyScene(const vk::Context& ctx, Scene& scene);

/// A light's shadow views as the forward pass finds them (GpuLight info.y and info.z): the
/// sun's cascades, a spot's one, an omni's six faces; {kNoIndex, 0} without a shadow.
struct ShadowViewRange {
    uint32_t first = kNoIndex, count = 0;
};

/// The primary lights' records: GpuLight, device-local, MAX_PRIMARY_RECORDS of them (read as a
/// uniform array at the draw's index), each with its shadow views, and each level light's record
/// (kNoIndex for a light that is not a primary).
struct PrimaryRecords {
    vk::Buffer buffer;               // owned
    std::vector<uint32_t> recordOf;  // per level light
};

/// A lightmap texel's baked shadow edge as the shadow mask's green, blue and alpha hold it, each
/// in [0, 1] before the unorm rounding (gpu_interface.glsl DIRECT_EDGE_RAMPS): the signed
/// distance in penumbra widths, and the edge's low and high levels (both the texel's visibility
/// where its sharpness is 0).
struct DirectEdgeMask {
    float ramps = 0.5f, low = 1.0f, high = 1.0f;
};
[[nodiscard]] DirectEdgeMask directEdgeMask(const world::LightmapTexel& t);

/// A draw's PRIMARY_* under primary light `primaryLight` (an index into `lights`): its type's, or
/// PRIMARY_NONE for kNoIndex.
[[nodiscard]] uint32_t primaryKindOf(const std::vector<world::Light>& lights,
                                     uint32_t primaryLight);

/// After createShadows has given the lights their views (`shadowViews` per light). Throws
/// std::runtime_error naming the counts when the level has more than MAX_PRIMARY_RECORDS
/// primaries or the device's uniform range cannot hold them.
void createPrimaryRecords(const vk::Context& ctx, PrimaryRecords& records,
                          const std::vector<world::Light>& lights,
                          const std::vector<ShadowViewRange>& shadowViews);

}  // namespace onelight::render
