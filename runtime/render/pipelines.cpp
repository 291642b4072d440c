// The renderer's pipelines and descriptor sets, laid out from the bindings of
// shaders/gpu_interface.glsl: the forward permutations a level's materials use, the shadow
// pipeline, the sky and tonemap pipelines, and the frame, material and tonemap sets.
#include <algorithm>
#include <string>
#include <vector>

#include "render/renderer_state.hpp"
#include "vk/descriptors.hpp"
#include "vk/vk_check.hpp"

#include "forward.frag.spv.h"
#include "forward.vert.spv.h"
#include "fullscreen.vert.spv.h"
#include "shadow.vert.spv.h"
#include "sky.frag.spv.h"
#include "sky.vert.spv.h"
#include "tonemap.frag.spv.h"

namespace onelight::render {

namespace {

const char* const kClassNames[4] = {"metal", "dielectric", "full", "lambert"};

constexpr VkShaderStageFlags kFragment = VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr VkShaderStageFlags kVertexFragment =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;

// Set 0 of the forward pass, binding by binding (gpu_interface.glsl).
const std::vector<VkDescriptorSetLayoutBinding>& frameBindings() {
    static const std::vector<VkDescriptorSetLayoutBinding> bindings = {
        vk::layoutBinding(glsl::BINDING_FRAME, kUniform, kVertexFragment),
        vk::layoutBinding(glsl::BINDING_LIGHTS, kStorage, kFragment),
        vk::layoutBinding(glsl::BINDING_SHADOW_VIEWS, kStorage, kFragment),
        vk::layoutBinding(glsl::BINDING_SHADOW_MAPS, kSampled, kFragment),
        vk::layoutBinding(glsl::BINDING_LIGHTMAP, kSampled, kFragment),
        vk::layoutBinding(glsl::BINDING_SHADOW_MASK, kSampled, kFragment),
        vk::layoutBinding(glsl::BINDING_OBJECT_LIGHTING, kStorage, kFragment),
        vk::layoutBinding(glsl::BINDING_PROBES, kSampled, kFragment),
        vk::layoutBinding(glsl::BINDING_MATERIALS, kStorage, kFragment),
        vk::layoutBinding(glsl::BINDING_ENV_BRDF, kSampled, kFragment),
        vk::layoutBinding(glsl::BINDING_PROBE_RECORDS, kStorage, kFragment),
        vk::layoutBinding(glsl::BINDING_SKY, kSampled, kFragment),
        vk::layoutBinding(glsl::BINDING_PROBE_CELLS, kStorage, kFragment)};
    static_assert(glsl::FRAME_BINDING_COUNT == 13, "one layout binding per frame binding");
    return bindings;
}

// Descriptors of `type` in `bindings`.
uint32_t countOf(const std::vector<VkDescriptorSetLayoutBinding>& bindings, VkDescriptorType type) {
    uint32_t n = 0;
    for (const VkDescriptorSetLayoutBinding& b : bindings)
        if (b.descriptorType == type) n += b.descriptorCount;
    return n;
}

std::vector<VkVertexInputAttributeDescription> vertexAttributes(bool positionOnly) {
    static_assert(sizeof(world::Vertex) == 56, "vertex layout of forward.vert");
    std::vector<VkVertexInputAttributeDescription> a = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                                                        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 12},
                                                        {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 24},
                                                        {3, 0, VK_FORMAT_R32G32_SFLOAT, 40},
                                                        {4, 0, VK_FORMAT_R32G32_SFLOAT, 48}};
    if (positionOnly) a.resize(1);
    return a;
}

void createLayouts(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    std::vector<VkDescriptorSetLayoutBinding> materialBindings;
    for (int slot = 0; slot < glsl::TEXTURE_SLOT_COUNT; ++slot)
        materialBindings.push_back(vk::layoutBinding(uint32_t(slot), kSampled, kFragment));
    const std::vector<std::vector<VkDescriptorSetLayoutBinding>> forwardSets = {frameBindings(),
                                                                                materialBindings};
    vk::createPipelineLayout(ctx, s.forwardLayout, forwardSets, sizeof(DrawPush), kVertexFragment);
    const std::vector<std::vector<VkDescriptorSetLayoutBinding>> noSets;
    vk::createPipelineLayout(ctx, s.shadowLayout, noSets, sizeof(glm::mat4),
                             VK_SHADER_STAGE_VERTEX_BIT);
    const std::vector<std::vector<VkDescriptorSetLayoutBinding>> tonemapSets = {
        {vk::layoutBinding(glsl::BINDING_TONEMAP_HDR, kSampled, kFragment),
         vk::layoutBinding(glsl::BINDING_TONEMAP_LUT, kSampled, kFragment)}};
    vk::createPipelineLayout(ctx, s.tonemapLayout, tonemapSets, 0, 0);
}

// Forward permutations: only those the level's materials use (and the flat one for benchmarks).
void createForwardPipelines(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    vk::GraphicsPipelineDesc forward;
    forward.vertexBindings = {{0, sizeof(world::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    forward.vertexAttributes = vertexAttributes(false);
    forward.samples = s.samples;
    forward.colorFormats = {kHdrFormat};
    forward.depthFormat = kDepthFormat;
    std::vector<uint32_t> keys;
    for (size_t m = 0; m < s.materialClasses.size(); ++m)
        keys.push_back(permutationKey(s.materialClasses[m], s.materialDoubleSided[m] != 0,
                                      s.materialAlphaMask[m] != 0));
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    const int bakedLighting = s.bakedLighting || s.options.samplePlaceholders ? 1 : 0;
    for (uint32_t key : keys) {
        const int materialClass = int(keyMaterialClass(key));
        const bool doubleSided = keyDoubleSided(key), alphaMask = keyAlphaMask(key);
        forward.cullMode = doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
        forward.stages = {{VK_SHADER_STAGE_VERTEX_BIT, kForwardVertSpirv, {}},
                          {VK_SHADER_STAGE_FRAGMENT_BIT,
                           kForwardFragSpirv,
                           {{glsl::SPEC_MATERIAL_CLASS, materialClass},
                            {glsl::SPEC_ALPHA_MASK, alphaMask ? 1 : 0},
                            {glsl::SPEC_FLAT_SHADING, 0},
                            {glsl::SPEC_BAKED_LIGHTING, bakedLighting},
                            {glsl::SPEC_DIFFUSE_MODEL, s.diffuseModel},
                            {glsl::SPEC_MATERIAL_PIPELINE, s.options.materialPipeline ? 1 : 0},
                            {glsl::SPEC_PROBES, s.info.probes > 0 ? 1 : 0}}}};
        s.forwardPipelines[key] = vk::createGraphicsPipeline(ctx, s.forwardLayout, forward);
        s.info.permutations.push_back(std::string(kClassNames[materialClass]) +
                                      (doubleSided ? "+double-sided" : "") +
                                      (alphaMask ? "+alpha-mask" : ""));
    }
    if (s.options.depthPrepass && !s.options.flatShading) {
        vk::GraphicsPipelineDesc depth = forward;
        depth.stages = {{VK_SHADER_STAGE_VERTEX_BIT, kForwardVertSpirv, {}}};
        depth.colorWrite = false;
        for (int doubleSided = 0; doubleSided < 2; ++doubleSided) {
            depth.cullMode = doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
            s.depthPipelines[doubleSided] = vk::createGraphicsPipeline(ctx, s.forwardLayout, depth);
        }
    }
    if (s.options.flatShading) {
        forward.cullMode = VK_CULL_MODE_BACK_BIT;
        forward.stages = {
            {VK_SHADER_STAGE_VERTEX_BIT, kForwardVertSpirv, {}},
            {VK_SHADER_STAGE_FRAGMENT_BIT, kForwardFragSpirv, {{glsl::SPEC_FLAT_SHADING, 1}}}};
        s.flatPipeline = vk::createGraphicsPipeline(ctx, s.forwardLayout, forward);
        s.info.permutations = {"flat"};
    }
}

void createShadowAndTonemapPipelines(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    vk::GraphicsPipelineDesc shadow;
    shadow.stages = {{VK_SHADER_STAGE_VERTEX_BIT, kShadowVertSpirv, {}}};
    shadow.vertexBindings = {{0, sizeof(world::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    shadow.vertexAttributes = vertexAttributes(true);
    shadow.cullMode = VK_CULL_MODE_NONE;
    shadow.dynamicDepthBias = true;
    shadow.depthFormat = kDepthFormat;
    s.shadowPipeline = vk::createGraphicsPipeline(ctx, s.shadowLayout, shadow);

    vk::GraphicsPipelineDesc tonemap;
    tonemap.stages = {{VK_SHADER_STAGE_VERTEX_BIT, kFullscreenVertSpirv, {}},
                      {VK_SHADER_STAGE_FRAGMENT_BIT, kTonemapFragSpirv, {}}};
    tonemap.cullMode = VK_CULL_MODE_NONE;
    tonemap.depthTest = tonemap.depthWrite = false;
    tonemap.colorFormats = {kDisplayFormat};
    s.tonemapPipeline = vk::createGraphicsPipeline(ctx, s.tonemapLayout, tonemap);
}

// The sky pass: the forward pass's layout and targets, no depth writes, behind everything.
void createSkyPipeline(RendererState& s) {
    if (!s.skyImage) return;
    vk::GraphicsPipelineDesc sky;
    sky.stages = {{VK_SHADER_STAGE_VERTEX_BIT, kSkyVertSpirv, {}},
                  {VK_SHADER_STAGE_FRAGMENT_BIT, kSkyFragSpirv, {}}};
    sky.cullMode = VK_CULL_MODE_NONE;
    sky.depthWrite = false;
    sky.samples = s.samples;
    sky.colorFormats = {kHdrFormat};
    sky.depthFormat = kDepthFormat;
    s.skyPipeline = vk::createGraphicsPipeline(*s.ctx, s.forwardLayout, sky);
}

// One frame set per frame slot, one material set per material, the tonemap set.
void createDescriptorSets(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    const uint32_t materials = uint32_t(s.materialTextures.size());
    const std::vector<VkDescriptorSetLayoutBinding>& frame = frameBindings();
    const VkDescriptorPoolSize sizes[] = {
        {kUniform, kFramesInFlight * countOf(frame, kUniform)},
        {kStorage, kFramesInFlight * countOf(frame, kStorage)},
        {kSampled, kFramesInFlight * countOf(frame, kSampled) +
                       materials * uint32_t(glsl::TEXTURE_SLOT_COUNT) + 2}};
    s.descriptorPool = vk::createDescriptorPool(ctx, kFramesInFlight + materials + 1, sizes);

    const vk::Image& shadowMaps = s.frameShadows.image ? s.frameShadows : s.staticShadows;
    for (FrameSlot& slot : s.frames) {
        slot.frameSet =
            vk::allocateDescriptorSet(ctx, s.descriptorPool, s.forwardLayout.setLayouts[0]);
        vk::DescriptorWriter w;
        w.set = slot.frameSet;
        w.buffer(glsl::BINDING_FRAME, kUniform, slot.uniforms.buffer);
        w.buffer(glsl::BINDING_LIGHTS, kStorage, s.lightBuffer.buffer);
        w.buffer(glsl::BINDING_SHADOW_VIEWS, kStorage, slot.shadowViews.buffer);
        w.image(glsl::BINDING_SHADOW_MAPS, shadowMaps.view, s.shadowSampler);
        w.image(glsl::BINDING_LIGHTMAP, s.lightmap.view, s.linearClamp);
        w.image(glsl::BINDING_SHADOW_MASK, s.shadowMask.view, s.linearClamp);
        w.buffer(glsl::BINDING_OBJECT_LIGHTING, kStorage, slot.objectLighting.buffer);
        w.image(glsl::BINDING_PROBES, s.probe.view, s.linearClamp);
        w.buffer(glsl::BINDING_MATERIALS, kStorage, s.materialBuffer.buffer);
        w.image(glsl::BINDING_ENV_BRDF, s.envBrdf.view, s.linearClamp);
        w.buffer(glsl::BINDING_PROBE_RECORDS, kStorage, s.probeBuffer.buffer);
        w.image(glsl::BINDING_SKY, s.sky.view, s.skySampler);
        w.buffer(glsl::BINDING_PROBE_CELLS, kStorage, s.probeCellBuffer.buffer);
        w.update(ctx);
    }
    for (const MaterialTextures& textures : s.materialTextures) {
        vk::DescriptorWriter m;
        m.set = vk::allocateDescriptorSet(ctx, s.descriptorPool, s.forwardLayout.setLayouts[1]);
        for (uint32_t t = 0; t < uint32_t(glsl::TEXTURE_SLOT_COUNT); ++t)
            m.image(t, textures[t].first, textures[t].second);
        m.update(ctx);
        s.materialSets.push_back(m.set);
    }
    s.tonemapSet = vk::allocateDescriptorSet(ctx, s.descriptorPool, s.tonemapLayout.setLayouts[0]);
    writeTonemapSet(s);
}

}  // namespace

void writeTonemapSet(RendererState& s) {
    vk::DescriptorWriter w;
    w.set = s.tonemapSet;
    w.image(glsl::BINDING_TONEMAP_HDR, s.hdr.view, s.nearestClamp);
    w.image(glsl::BINDING_TONEMAP_LUT, s.lut.view, s.linearClamp);
    w.update(*s.ctx);
}

void createPipelines(RendererState& s) {
    createLayouts(s);
    createForwardPipelines(s);
    createShadowAndTonemapPipelines(s);
    createSkyPipeline(s);
    createDescriptorSets(s);
}

void destroyPipelines(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    if (s.descriptorPool) vkDestroyDescriptorPool(ctx.device, s.descriptorPool, nullptr);
    s.descriptorPool = VK_NULL_HANDLE;
    s.materialSets.clear();
    s.tonemapSet = VK_NULL_HANDLE;
    for (FrameSlot& slot : s.frames) slot.frameSet = VK_NULL_HANDLE;
    for (VkPipeline* p : {&s.skyPipeline, &s.tonemapPipeline, &s.shadowPipeline, &s.flatPipeline,
                          &s.depthPipelines[0], &s.depthPipelines[1]}) {
        if (*p) vkDestroyPipeline(ctx.device, *p, nullptr);
        *p = VK_NULL_HANDLE;
    }
    for (auto& [key, pipeline] : s.forwardPipelines)
        vkDestroyPipeline(ctx.device, pipeline, nullptr);
    s.forwardPipelines.clear();
    vk::destroyPipelineLayout(ctx, s.tonemapLayout);
    vk::destroyPipelineLayout(ctx, s.shadowLayout);
    vk::destroyPipelineLayout(ctx, s.forwardLayout);
}

}  // namespace onelight::render
