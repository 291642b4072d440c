// Runtime shadow maps of the primary lights (shadows.cpp): their slots and views, their fitting
// to the camera and their passes.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render/camera.hpp"
#include "render/gpu_types.hpp"
#include "render/renderer.hpp"
#include "render/scene.hpp"
#include "vk/context.hpp"
#include "vk/graphics_pipeline.hpp"
#include "vk/image.hpp"

namespace onelight::render {

/// The sun's cascades (Zhang et al. 2006, "Parallel-Split Shadow Maps"): cascade k of n covers
/// view distances up to radius / kSunCascadeRatio^(n - 1 - k), each a map of the same size, so
/// that a texel spans about the same number of pixels at every cascade's far end (1.6 at
/// 1280x720 with a 90-degree view, a 1024 map and the 40 m radius: 1.1, 3.3 and 9.8 cm texels).
inline constexpr float kSunCascadeRatio = 3.0f;

/// The far view distance of each of `cascades` sun cascades within `shadowRadius` metres, the
/// last one the radius; fewer when a cascade already spans the level (`levelDiagonal` metres).
[[nodiscard]] std::vector<float> sunCascadeSplits(float shadowRadius, uint32_t cascades,
                                                  float levelDiagonal);

/// The half size (metres) of the sun map that covers view distances up to `split` around the
/// camera, snapped to its cell and never wider than the level.
[[nodiscard]] float sunCascadeExtent(float split, float levelDiagonal);

/// The shadow layers of one primary light: the sun's cascades, a spot's 1 or an omni's 6, views
/// first..first+count.
struct ShadowSlot {
    uint32_t light = 0;
    uint32_t firstView = 0, viewCount = 0;
};

struct ShadowView {
    glm::mat4 viewProj{1.0f};
    glm::vec4 params{0.0f};       // GpuShadowView::params
    float depthBiasClamp = 0.0f;  // depth units, the slope bias's limit; 0: none
    bool staticValid = false;     // its static casters are rendered and still fit
    glm::vec2 sunCell{1e30f};     // a sun cascade: the snapped camera cell it was fitted around
    float split = 0.0f;           // a sun cascade: the far view distance it covers (metres)
    VkImageView staticLayer = VK_NULL_HANDLE;  // owned, layer of staticShadows
    VkImageView frameLayer = VK_NULL_HANDLE;   // owned, layer of frameShadows (with dynamics)
};

/// The shadow maps: a static layer per view, cached, and with dynamic casters in the level a
/// frame layer per view (the static one copied, the dynamic casters drawn over it).
struct ShadowMaps {
    vk::Image staticShadows, frameShadows;  // owned, D32 2D arrays, one layer per view
    VkSampler sampler = VK_NULL_HANDLE;     // owned, compare
    std::vector<ShadowSlot> slots;
    std::vector<uint32_t> lightSlot;  // per light: into slots or kNoIndex
    std::vector<ShadowView> views;    // at least one
    uint32_t layers = 0;              // layers in use (views holds one more without any)
    uint32_t mapSize = 0;             // texels, every layer
};

/// Slots for every primary light while `options.maxShadowLayers` last (none with flat
/// shading), a sun's with its cascades (options.sunCascades, fewer in a level smaller than
/// them), their layers cleared to "unoccluded"; frame layers when `dynamicCasters`.
void createShadows(const vk::Context& ctx, ShadowMaps& shadows, const LevelData& level,
                   const RendererOptions& options, bool dynamicCasters);
void destroyShadows(const vk::Context& ctx, ShadowMaps& shadows);

/// The shadow views of every light, {kNoIndex, 0} for a light without a slot.
[[nodiscard]] std::vector<ShadowViewRange> lightShadowViews(const ShadowMaps& shadows);

/// The maps the forward pass samples: the frame layers when there are any, else the static ones.
[[nodiscard]] const vk::Image& sampledShadowMaps(const ShadowMaps& shadows);

/// Fits the views of the slots of `visibleLights` for this camera; marks slots to redraw.
void updateShadowViews(ShadowMaps& shadows, const LevelData& level, const Camera& camera,
                       const std::vector<uint32_t>& visibleLights);
/// Copies the shadow views fitted for this frame into `out` (GpuShadowView per view).
void writeShadowViews(const ShadowMaps& shadows, GpuShadowView* out);
/// What the shadow passes draw with: opaque casters depth only; alpha-masked ones (glTF MASK)
/// through their material's base colour alpha, so that their holes let the light through as in
/// the forward pass and the baked mask. Borrowed.
struct ShadowDraw {
    VkPipeline opaque = VK_NULL_HANDLE, masked = VK_NULL_HANDLE;
    VkPipelineLayout opaqueLayout = VK_NULL_HANDLE, maskedLayout = VK_NULL_HANDLE;
    const SceneMaterials* materials = nullptr;
    const std::vector<VkDescriptorSet>* materialSets = nullptr;  // per material
};

/// Records the shadow passes; returns how many static views were redrawn.
[[nodiscard]] uint32_t recordShadowPasses(ShadowMaps& shadows, VkCommandBuffer cmd,
                                          const ShadowDraw& draw, const SceneGeometry& geometry,
                                          const std::vector<uint32_t>& visibleLights,
                                          const std::vector<glm::mat4>& entityTransforms,
                                          const std::vector<uint8_t>& entityHidden);

}  // namespace onelight::render
