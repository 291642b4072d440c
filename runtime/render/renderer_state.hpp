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
#include "vk/graphics_pipeline.hpp"
#include "vk/image.hpp"
#include "world/baked_lighting.hpp"

namespace onelight::render {

inline constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
inline constexpr VkFormat kDisplayFormat = VK_FORMAT_B8G8R8A8_UNORM;  // as the swapchain
inline constexpr uint32_t kLutSize = 64;
inline constexpr uint32_t kEnvBrdfSize = 32;

/// A material's five texture slots (base, metallic-roughness, normal, occlusion, emissive).
using MaterialTextures = std::array<std::pair<VkImageView, VkSampler>, 5>;

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
    VkImageView staticLayer = VK_NULL_HANDLE;  // owned, layer of staticShadows
    VkImageView frameLayer = VK_NULL_HANDLE;   // owned, layer of frameShadows (with dynamics)
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
    std::vector<DrawSurface> surfaces;
    std::vector<DrawDynamicMesh> dynamicMeshes;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
    float ambientLux = 0.0f;
    std::vector<uint32_t> dynamicPrimary;  // per entity, with hysteresis

    // GPU scene.
    vk::Buffer vertices, indices, lightBuffer, shadowViewBuffer, materialBuffer, frameBuffer;
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
    vk::Buffer objectLightingBuffer;      // GpuObjectLighting per entity, written per frame
    vk::Buffer probeBuffer;               // GpuProbe records (render/probe_records.hpp)
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
    vk::Image envBrdf;  // EnvBRDF_Fit at kEnvBrdfSize^2 texel centres (NoV, gloss)

    // Targets.
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    uint32_t width = 0, height = 0;
    vk::Image msaaColor, depth, hdr, display;
    vk::Buffer readbackHdr, readbackDisplay, readbackSwapchain;
    CapturedFrame captured;

    // Pipelines and descriptors.
    vk::PipelineLayout forwardLayout, shadowLayout, tonemapLayout;
    std::map<uint32_t, VkPipeline> forwardPipelines;   // owned, by permutationKey
    VkPipeline flatPipeline = VK_NULL_HANDLE;          // owned
    VkPipeline shadowPipeline = VK_NULL_HANDLE;        // owned
    VkPipeline tonemapPipeline = VK_NULL_HANDLE;       // owned
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;  // owned, frees the sets
    VkDescriptorSet frameSet = VK_NULL_HANDLE, tonemapSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> materialSets;  // per material (one default when none)

    // Submission.
    VkCommandBuffer cmd = VK_NULL_HANDLE;  // from ctx->commandPool
    VkFence fence = VK_NULL_HANDLE;        // owned
    VkQueryPool queries = VK_NULL_HANDLE;  // owned, 4 timestamps
    bool timestamps = false;
};

/// Pipeline key of a forward permutation: material class, double-sided, alpha mask.
inline uint32_t permutationKey(uint32_t materialClass, bool doubleSided, bool alphaMask) {
    return materialClass | (doubleSided ? 4u : 0u) | (alphaMask ? 8u : 0u);
}

// scene.cpp
void uploadScene(RendererState& s, const assets::LoadedLevel& loaded);
void destroyScene(RendererState& s);

// shadows.cpp
void createShadows(RendererState& s);
void destroyShadows(RendererState& s);
/// Fits the views of the slots of `visibleLights` for this camera; marks slots to redraw.
void updateShadowViews(RendererState& s, const Camera& camera,
                       const std::vector<uint32_t>& visibleLights);
/// Records the shadow passes; returns how many static views were redrawn.
uint32_t recordShadowPasses(RendererState& s, VkCommandBuffer cmd,
                            const std::vector<uint32_t>& visibleLights,
                            const std::vector<glm::mat4>& entityTransforms);

}  // namespace onelight::render
