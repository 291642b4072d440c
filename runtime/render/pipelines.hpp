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

/// What the forward permutations are specialized for, besides the materials.
struct ForwardChoices {
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool fetchBakedLighting = false;  // baked lighting, or the placeholders sampled anyway
    int diffuseModel = 0;             // DIFFUSE_* (lighting.glsl): the level's
    bool probes = false;              // the package's probes are in use
    bool skyImage = false;            // the sky pass is needed
};

struct Pipelines {
    vk::PipelineLayout forwardLayout, shadowLayout, tonemapLayout;  // owned
    std::map<uint32_t, VkPipeline> forward;                         // owned, by permutationKey
    VkPipeline flat = VK_NULL_HANDLE;  // owned, only with RendererOptions::flatShading
    // The depth pre-pass: forward.vert alone, depth only, culling back faces or none (owned).
    VkPipeline depth[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    VkPipeline shadow = VK_NULL_HANDLE;     // owned
    VkPipeline tonemap = VK_NULL_HANDLE;    // owned
    VkPipeline sky = VK_NULL_HANDLE;        // owned, when the level's sky is an image
    std::vector<std::string> permutations;  // the forward pipelines built, by name
};

/// Pipeline layouts, the forward permutations `materials` use, the shadow, sky and tonemap
/// pipelines.
void createPipelines(const vk::Context& ctx, Pipelines& pipelines, const SceneMaterials& materials,
                     const RendererOptions& options, const ForwardChoices& choices);
void destroyPipelines(const vk::Context& ctx, Pipelines& pipelines);

/// The descriptor sets, from one pool: one frame set per frame slot, one per material, the
/// tonemap set. They borrow every buffer, image and sampler they point at.
struct DescriptorSets {
    VkDescriptorPool pool = VK_NULL_HANDLE;                // owned, frees the sets
    std::array<VkDescriptorSet, kFramesInFlight> frame{};  // set 0 of the forward pass, per slot
    std::vector<VkDescriptorSet> material;                 // set 1, per material
    VkDescriptorSet tonemap = VK_NULL_HANDLE;
};

void createDescriptorSets(const vk::Context& ctx, DescriptorSets& sets, const Pipelines& pipelines,
                          const FrameSlots& frames, const Scene& scene, const ShadowMaps& shadows,
                          const vk::Buffer& lightRecords, const RenderTargets& targets);
void destroyDescriptorSets(const vk::Context& ctx, DescriptorSets& sets);
/// Points the tonemap set at the current HDR target (after createTargets).
void writeTonemapSet(const vk::Context& ctx, const DescriptorSets& sets,
                     const RenderTargets& targets, const LookupTables& tables);

}  // namespace onelight::render
