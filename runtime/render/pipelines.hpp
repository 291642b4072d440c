// The renderer's pipelines and descriptor sets (pipelines.cpp), laid out from the bindings of
// shaders/gpu_interface.glsl.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "render/frame_slots.hpp"
#include "render/renderer.hpp"
#include "render/scene.hpp"
#include "render/shadows.hpp"
#include "render/targets.hpp"
#include "vk/buffer.hpp"
#include "vk/context.hpp"
#include "vk/graphics_pipeline.hpp"

namespace onelight::render {

/// What a forward pipeline is specialized for: its materials' class, sidedness, alpha mode and
/// texture slots, and its draws' primary light and source of secondary lighting
/// (forward_shading.glsl's SPEC_TEXTURES, SPEC_PRIMARY and SPEC_SECONDARY), and whether the frame
/// has effect lights (SPEC_EFFECT_LIGHTS).
struct PermutationKey {
    uint32_t materialClass = 0;
    bool doubleSided = false, alphaMask = false;
    uint32_t textures = uint32_t(glsl::ALL_TEXTURES);  // TEXTURE_* slots its materials may use
    uint32_t primary = uint32_t(glsl::PRIMARY_ANY);    // PRIMARY_*: its draws' primary's type
    uint32_t secondary = uint32_t(glsl::SECONDARY_ANY);
    bool effectLights = true;  // false: for frames without effect lights
    bool alphaBlend = false;   // glTF BLEND: blended over what is behind, drawn last, back to front
    bool primaryShadow = true;  // false: its draws' primary is unoccluded (DrawSurface::unoccluded)
    bool primaryFade = true;    // its draws may cross-fade a primary switch (SPEC_PRIMARY_FADE)
    bool directEdges = true;    // its draws' lightmaps may draw a baked shadow edge
};

/// The key packed into a pipeline's map key: class bits 0-1, double-sided 2, alpha mask 3,
/// texture slots 4-10, primary 11-13, secondary 14-15, effect lights 16, alpha blend 17 (so that
/// blended draws sort after every opaque one), no primary shadow 18, no primary fade 19, direct
/// edges 20.
inline constexpr uint32_t kKeyTextureBits = uint32_t(glsl::ALL_TEXTURES);
static_assert(kKeyTextureBits == 127u, "texture slots fill key bits 4-10");
[[nodiscard]] inline uint32_t permutationKey(const PermutationKey& k) {
    return k.materialClass | (k.doubleSided ? 4u : 0u) | (k.alphaMask ? 8u : 0u) |
           (k.textures & kKeyTextureBits) << 4 | (k.primary & 7u) << 11 | (k.secondary & 3u) << 14 |
           (k.effectLights ? 1u << 16 : 0u) | (k.alphaBlend ? 1u << 17 : 0u) |
           (k.primaryShadow ? 0u : 1u << 18) | (k.primaryFade ? 0u : 1u << 19) |
           (k.directEdges ? 1u << 20 : 0u);
}
[[nodiscard]] inline PermutationKey unpackPermutationKey(uint32_t key) {
    return {key & 3u,
            (key & 4u) != 0,
            (key & 8u) != 0,
            (key >> 4) & kKeyTextureBits,
            (key >> 11) & 7u,
            (key >> 14) & 3u,
            (key & (1u << 16)) != 0,
            (key & (1u << 17)) != 0,
            (key & (1u << 18)) == 0,
            (key & (1u << 19)) == 0,
            (key & (1u << 20)) != 0};
}
[[nodiscard]] inline bool keyDoubleSided(uint32_t key) {
    return (key & 4u) != 0;
}
[[nodiscard]] inline bool keyAlphaMask(uint32_t key) {
    return (key & 8u) != 0;
}
[[nodiscard]] inline bool keyAlphaBlend(uint32_t key) {
    return (key & (1u << 17)) != 0;
}

/// The pipeline key of a draw of `material` (0 with flat shading). A static surface: `primary`
/// PRIMARY_NONE or its primary's PRIMARY_<type>, `secondary` SECONDARY_LIGHTMAP or
/// SECONDARY_CONSTANT; a dynamic mesh: PRIMARY_ANY (the game picks it per frame) and
/// SECONDARY_OBJECT;
/// `effectLights` whether the frame has any; `primaryShadow` false for a static surface drawn
/// without its primary's shadow (DrawSurface::unoccluded); `directEdges` true for a static
/// surface whose lightmap draws a baked shadow edge (DrawSurface::directEdges). Without
/// options.specializeDraws every draw of a material shares the general pipeline.
[[nodiscard]] uint32_t drawPipelineKey(const SceneMaterials& materials,
                                       const RendererOptions& options, uint32_t material,
                                       uint32_t primary, uint32_t secondary, bool effectLights,
                                       bool primaryShadow = true, bool primaryFade = false,
                                       bool directEdges = false);

/// What the forward permutations are specialized for, besides the materials.
struct ForwardChoices {
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool fetchBakedLighting = false;  // baked lighting, or the placeholders sampled anyway
    int diffuseModel = 0;             // DIFFUSE_* (lighting.glsl): the level's
    bool probes = false;              // the package's probes are in use
    bool skyImage = false;            // the sky pass is needed
};

struct Pipelines {
    vk::PipelineLayout forwardLayout, shadowLayout, tonemapLayout, fxaaLayout;  // owned
    // Alpha-masked shadow casters: a material's set (set 1 of forwardLayout) as set 0.
    vk::PipelineLayout maskedShadowLayout;   // owned
    std::map<uint32_t, VkPipeline> forward;  // owned, by permutationKey
    VkPipeline flat = VK_NULL_HANDLE;        // owned, only with RendererOptions::flatShading
    // The depth pre-pass: forward.vert alone, depth only, culling back faces or none (owned).
    VkPipeline depth[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    VkPipeline shadow = VK_NULL_HANDLE;        // owned
    VkPipeline maskedShadow = VK_NULL_HANDLE;  // owned: alpha-masked casters' coverage test
    VkPipeline tonemap = VK_NULL_HANDLE;       // owned
    VkPipeline fxaa = VK_NULL_HANDLE;          // owned, with RendererOptions::fxaa
    VkPipeline sky = VK_NULL_HANDLE;           // owned, when the level's sky is an image
    std::vector<std::string> permutations;     // the forward pipelines built, by name
};

/// Pipeline layouts, the forward permutations the draws of `geometry` use, the shadow, sky and
/// tonemap pipelines.
void createPipelines(const vk::Context& ctx, Pipelines& pipelines, const SceneGeometry& geometry,
                     const SceneMaterials& materials, const RendererOptions& options,
                     const ForwardChoices& choices);
void destroyPipelines(const vk::Context& ctx, Pipelines& pipelines);

/// The descriptor sets, from one pool: one frame set per frame slot, one per material, the
/// tonemap set. They borrow every buffer, image and sampler they point at.
struct DescriptorSets {
    VkDescriptorPool pool = VK_NULL_HANDLE;                // owned, frees the sets
    std::array<VkDescriptorSet, kFramesInFlight> frame{};  // set 0 of the forward pass, per slot
    std::vector<VkDescriptorSet> material;                 // set 1, per material
    VkDescriptorSet tonemap = VK_NULL_HANDLE;
    VkDescriptorSet fxaa = VK_NULL_HANDLE;  // with RendererOptions::fxaa
};

void createDescriptorSets(const vk::Context& ctx, DescriptorSets& sets, const Pipelines& pipelines,
                          const FrameSlots& frames, const Scene& scene, const ShadowMaps& shadows,
                          const vk::Buffer& primaryLights, const RenderTargets& targets);
void destroyDescriptorSets(const vk::Context& ctx, DescriptorSets& sets);
/// Points the tonemap set at the current HDR target, and the FXAA set at the tonemapped one
/// (after createTargets).
void writeTonemapSet(const vk::Context& ctx, const DescriptorSets& sets,
                     const RenderTargets& targets, const LookupTables& tables);

}  // namespace onelight::render
