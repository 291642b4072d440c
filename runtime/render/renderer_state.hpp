// The renderer's internals, shared by its source files (not part of the API).
#pragma once

#include <array>
#include <deque>
#include <map>
#include <utility>
#include <vector>

#include "render/camera.hpp"
#include "render/gpu_types.hpp"
#include "render/renderer.hpp"
#include "vk/buffer.hpp"
#include "vk/context.hpp"
#include "vk/graphics_pipeline.hpp"
#include "vk/image.hpp"
#include "world/baked_lighting.hpp"

namespace onelight::render {

inline constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
inline constexpr VkFormat kDisplayFormat = VK_FORMAT_B8G8R8A8_UNORM;  // as the swapchain
inline constexpr uint32_t kLutSize = 64;
inline constexpr uint32_t kFramesInFlight =
    2;  // the CPU records one frame while the GPU draws another
inline constexpr uint32_t kTimestampCount = 4;  // frame start, after shadows, forward, tonemap

/// A material's texture slots (TEXTURE_* of gpu_interface.glsl): view and sampler each.
using MaterialTextures =
    std::array<std::pair<VkImageView, VkSampler>, size_t(glsl::TEXTURE_SLOT_COUNT)>;

/// A static surface as the renderer draws it.
struct DrawSurface {
    uint32_t firstIndex = 0, indexCount = 0;
    uint32_t material = 0, primaryLight = kNoIndex, atlas = kNoIndex;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
};

/// A dynamic mesh with its object-space bounds.
struct DrawDynamicMesh {
    uint32_t entity = 0;
    uint32_t firstIndex = 0, indexCount = 0;  // into the shared index buffer
    int32_t vertexOffset = 0;                 // into the shared vertex buffer
    uint32_t material = 0;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // object space
};

/// The shadow layers of one primary light: 1 (sun, spot) or 6 (omni), views first..first+count.
struct ShadowSlot {
    uint32_t light = 0;
    uint32_t firstView = 0, viewCount = 0;
    bool staticValid = false;  // its static casters are rendered and still fit
    glm::vec2 sunCell{1e30f};  // the snapped camera cell the sun map was fitted around
};

struct ShadowView {
    glm::mat4 viewProj{1.0f};
    glm::vec4 params{0.0f};
    float depthBiasClamp = 0.0f;               // depth units, the slope bias's limit; 0: none
    VkImageView staticLayer = VK_NULL_HANDLE;  // owned, layer of staticShadows
    VkImageView frameLayer = VK_NULL_HANDLE;   // owned, layer of frameShadows (with dynamics)
};

/// What one frame in flight owns: its command buffer and fence, and every buffer the CPU writes
/// for it, so that the CPU fills the next frame while the GPU still reads this one.
struct FrameSlot {
    VkCommandBuffer cmd = VK_NULL_HANDLE;       // from ctx->commandPool
    VkFence done = VK_NULL_HANDLE;              // owned, signalled when its last submit finished
    VkQueryPool timestamps = VK_NULL_HANDLE;    // owned, kTimestampCount (when supported)
    vk::Buffer uniforms;                        // FrameUniforms
    vk::Buffer shadowViews;                     // GpuShadowView per shadow view
    vk::Buffer objectLighting;                  // GpuObjectLighting per entity
    VkDescriptorSet frameSet = VK_NULL_HANDLE;  // set 0 over these buffers, from the pool
    uint64_t frame = 0;                         // the frame it last submitted
    bool pending = false;                       // submitted and not waited for yet
};

struct RendererState {
    vk::Context* ctx = nullptr;  // borrowed
    RendererOptions options;
    RendererInfo info;

    // Level data the frame needs (copied from the package).
    world::LevelSettings settings;
    std::vector<world::Light> lights;
    std::vector<world::Entity> entities;
    std::vector<uint8_t> materialClasses;  // per material, after forceMaterialClass
    std::vector<uint8_t> materialDoubleSided, materialAlphaMask;
    int diffuseModel = 0;  // DIFFUSE_* (lighting.glsl): the level's, a specialization constant
    std::vector<DrawSurface> surfaces;
    std::vector<DrawDynamicMesh> dynamicMeshes;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
    float ambientLux = 0.0f;
    std::vector<uint32_t> drawnPrimary;  // per entity: the primary its last drawn frame used

    // GPU scene.
    vk::Buffer vertices, indices, lightBuffer, materialBuffer;  // device-local
    std::deque<vk::Image> textures;                  // owned, decoded level images (never moved)
    std::map<uint64_t, uint32_t> textureIndex;       // (image << 1 | srgb) -> textures
    std::map<uint64_t, VkSampler> samplers;          // owned, by glTF sampler state
    vk::Image white, flatNormal;                     // placeholders for missing textures
    std::vector<MaterialTextures> materialTextures;  // per material: views and samplers, borrowed
    VkSampler linearClamp = VK_NULL_HANDLE;          // owned: baked data, LUT
    VkSampler nearestClamp = VK_NULL_HANDLE;         // owned: HDR in the tonemap

    // Baked lighting from the package, or neutral placeholders (see uploadBakedLighting).
    bool bakedLighting = false;  // the level has it: the fetching permutation
    vk::Image lightmap, shadowMask, probe;
    float lightmapDecode = 1.0f;          // lux per stored lightmap unit (a power of two)
    std::vector<glm::vec2> atlasUvScale;  // per atlas: uv1 to the lightmap array's uv
    world::LightGrid grid;                // empty without baked lighting
    world::Visibility visibility;         // the package's potentially visible set; may be empty
    vk::Buffer probeBuffer;               // GpuProbe records (render/probe_records.hpp)
    vk::Buffer probeCellBuffer;           // GpuProbeGrid and the cells' record lists
    uint32_t probeCount = 1;              // records; the cube array holds as many cubes
    uint32_t probeMips = 1;

    // Shadows.
    vk::Image staticShadows, frameShadows;     // D32 2D arrays, one layer per view
    VkSampler shadowSampler = VK_NULL_HANDLE;  // owned, compare
    std::vector<ShadowSlot> slots;
    std::vector<uint32_t> lightSlot;  // per light: into slots or kNoIndex
    std::vector<ShadowView> views;

    // Colour.
    vk::Image lut;
    vk::Image envBrdf;  // the split-sum table (env_brdf_table.hpp), half floats

    // The sky image (RGBA16F, the decoded .hdr unscaled), a black texel when the level has none.
    vk::Image sky;
    VkSampler skySampler = VK_NULL_HANDLE;  // owned: linear, repeating in u, clamped in v
    bool skyImage = false;                  // the level's sky is an image: the sky pass draws it

    // Targets.
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    uint32_t width = 0, height = 0;
    vk::Image msaaColor, depth, hdr, display;
    vk::Buffer readbackHdr, readbackDisplay, readbackSwapchain;
    CapturedFrame captured;

    // Pipelines and descriptors.
    vk::PipelineLayout forwardLayout, shadowLayout, tonemapLayout;
    std::map<uint32_t, VkPipeline> forwardPipelines;  // owned, by permutationKey
    VkPipeline flatPipeline = VK_NULL_HANDLE;         // owned
    // The depth pre-pass: forward.vert alone, depth only, culling back faces or none (owned).
    VkPipeline depthPipelines[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    VkPipeline shadowPipeline = VK_NULL_HANDLE;        // owned
    VkPipeline tonemapPipeline = VK_NULL_HANDLE;       // owned
    VkPipeline skyPipeline = VK_NULL_HANDLE;           // owned, when skyImage
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;  // owned, frees the sets
    VkDescriptorSet tonemapSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> materialSets;  // per material (one default when none)

    // Submission: kFramesInFlight slots used in turn; frame n records into frames[n % count].
    std::array<FrameSlot, kFramesInFlight> frames;
    uint64_t framesSubmitted = 0;
    bool timestamps = false;  // the device writes timestamps
};

/// Pipeline key of a forward permutation: material class, double-sided, alpha mask.
[[nodiscard]] inline uint32_t permutationKey(uint32_t materialClass, bool doubleSided,
                                             bool alphaMask) {
    return materialClass | (doubleSided ? 4u : 0u) | (alphaMask ? 8u : 0u);
}
[[nodiscard]] inline uint32_t keyMaterialClass(uint32_t key) {
    return key & 3u;
}
[[nodiscard]] inline bool keyDoubleSided(uint32_t key) {
    return (key & 4u) != 0;
}
[[nodiscard]] inline bool keyAlphaMask(uint32_t key) {
    return (key & 8u) != 0;
}

// scene.cpp
void uploadScene(RendererState& s, const assets::LoadedLevel& loaded);
/// The level's lights with their first shadow views: after createShadows has given them slots.
void uploadLights(RendererState& s);
void destroyScene(RendererState& s);

// targets.cpp
/// The supported sample count nearest to `requested` (in powers of two; ties go up).
[[nodiscard]] VkSampleCountFlagBits pickSamples(const vk::Context& ctx, uint32_t requested);
void createTargets(RendererState& s);
void destroyTargets(RendererState& s);

// pipelines.cpp
/// Pipeline layouts, the forward permutations the level uses, shadow and tonemap pipelines, and
/// the descriptor sets (one frame set per frame slot, one per material, the tonemap set).
void createPipelines(RendererState& s);
void destroyPipelines(RendererState& s);
/// Points the tonemap set at the current HDR target (after createTargets).
void writeTonemapSet(RendererState& s);

// shadows.cpp
void createShadows(RendererState& s);
void destroyShadows(RendererState& s);
/// Fits the views of the slots of `visibleLights` for this camera; marks slots to redraw.
void updateShadowViews(RendererState& s, const Camera& camera,
                       const std::vector<uint32_t>& visibleLights);
/// Copies the shadow views fitted for this frame into `out` (GpuShadowView per view).
void writeShadowViews(const RendererState& s, GpuShadowView* out);
/// Records the shadow passes; returns how many static views were redrawn.
[[nodiscard]] uint32_t recordShadowPasses(RendererState& s, VkCommandBuffer cmd,
                                          const std::vector<uint32_t>& visibleLights,
                                          const std::vector<glm::mat4>& entityTransforms);

// frame_view.cpp: what a frame sees and draws, on the CPU.
/// Light records (gpu_interface.glsl GpuLight): a level light with its first shadow view, and
/// the effect lights (no shadow).
[[nodiscard]] GpuLight gpuLightOf(const world::Light& light, uint32_t firstShadowView);
[[nodiscard]] GpuLight gpuLightOf(const EffectOmni& omni);
[[nodiscard]] GpuLight gpuLightOf(const EffectSpot& spot);

/// One draw of the forward pass.
struct Draw {
    uint32_t key = 0;  // permutationKey of the material (0 with flat shading)
    uint32_t material = 0;
    uint32_t firstIndex = 0, indexCount = 0;
    int32_t vertexOffset = 0;
    uint32_t primaryLight = kNoIndex, atlas = kNoIndex;
    uint32_t entity = kNoIndex;  // kNoIndex for static; a dynamic object's record in objectLighting
    float distance2 = 0.0f;      // squared metres from the camera: dynamic draws front to back
};

/// The camera, the exposure and the dynamic objects' transforms and primaries of one frame.
struct FrameView {
    Camera camera;
    glm::mat4 projection{1.0f}, viewProj{1.0f};
    float ev100 = 0.0f, exposure = 1.0f;
    std::vector<glm::mat4> entityTransforms;  // per entity: given, else its placement
    std::vector<uint32_t> entityPrimary;      // per entity: the game's pick, or kNoIndex
};
[[nodiscard]] FrameView frameViewOf(const RendererState& s, const FrameInputs& inputs);

/// Orders the culled draws for recording and merges each run of static draws that bind and push
/// the same state (pipeline, material, primary, lightmap atlas) over adjacent index ranges into
/// one draw; dynamic meshes stay one draw each, front to back. With geometryOnly every adjacent
/// range merges whatever it binds (the raster floor, RendererOptions::rasterFloor).
void batchDraws(std::vector<Draw>& draws, bool geometryOnly);

/// The frame's draws, sorted by pipeline then front to back, and the primaries they use.
struct DrawList {
    std::vector<Draw> draws;
    std::vector<uint32_t> visibleLights;  // sorted, unique
    std::vector<uint8_t> entityVisible;   // per entity
};
/// Culls static surfaces and dynamic meshes against the view; counts them in `stats`.
[[nodiscard]] DrawList buildDrawList(const RendererState& s, const FrameView& view,
                                     FrameStats& stats);

/// The grid's lighting of every visible dynamic object, into `out` (one record per entity).
void writeObjectLighting(const RendererState& s, const FrameView& view, const DrawList& list,
                         GpuObjectLighting* out);

/// The frame's uniforms: camera, exposure, shadow and baked parameters, effect lights.
[[nodiscard]] FrameUniforms frameUniformsOf(const RendererState& s, const FrameView& view,
                                            const EffectLights& effects);

// frame_passes.cpp: recording the frame after the shadow passes.
/// The forward pass into the HDR target (resolved from MSAA); counts triangles in `stats`.
void recordForwardPass(RendererState& s, VkCommandBuffer cmd, const FrameSlot& slot,
                       const FrameView& view, const DrawList& list, FrameStats& stats);
/// The tonemap pass from the HDR target into the display target.
void recordTonemapPass(RendererState& s, VkCommandBuffer cmd);
/// Copies to the host (readback) and into the swapchain image, as `output` asks.
void recordOutputs(RendererState& s, VkCommandBuffer cmd, const FrameOutput& output);
/// Fills s.captured from the readback buffers of a finished frame.
void readBackFrame(RendererState& s, const FrameOutput& output, float exposure);

}  // namespace onelight::render
