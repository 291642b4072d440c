// The renderer's pipelines and descriptor sets, laid out from the bindings of
// shaders/gpu_interface.glsl: the forward permutations a level's materials use, the shadow
// pipeline, the sky and tonemap pipelines, and the frame, material and tonemap sets.
#include "render/pipelines.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "vk/descriptors.hpp"
#include "vk/vk_check.hpp"

#include "forward.frag.spv.h"
#include "forward.vert.spv.h"
#include "forward_masked.frag.spv.h"
#include "fullscreen.vert.spv.h"
#include "fxaa.frag.spv.h"
#include "shadow.vert.spv.h"
#include "shadow_masked.frag.spv.h"
#include "shadow_masked.vert.spv.h"
#include "sky.frag.spv.h"
#include "sky.vert.spv.h"
#include "tonemap.frag.spv.h"

namespace onelight::render {

namespace {

const char* const kClassNames[4] = {"metal", "dielectric", "full", "lambert"};

// A permutation's name: its class, then what it adds or leaves out ("lambert+double-sided
// textures=base,emissive no-primary lightmap").
std::string permutationName(const PermutationKey& k) {
    static const char* const kSlots[7] = {"base",     "metal-rough", "normal", "occlusion",
                                          "emissive", "cavity",      "facets"};
    static const char* const kSecondary[4] = {"", " lightmap", " object", " constant"};
    std::string name = std::string(kClassNames[k.materialClass]) +
                       (k.doubleSided ? "+double-sided" : "") + (k.alphaMask ? "+alpha-mask" : "") +
                       (k.alphaBlend ? "+alpha-blend" : "");
    if (k.textures != uint32_t(glsl::ALL_TEXTURES)) {
        std::string slots;
        for (int t = 0; t < glsl::TEXTURE_SLOT_COUNT; ++t)
            if (k.textures & (1u << t)) slots += std::string(slots.empty() ? "" : ",") + kSlots[t];
        name += " textures=" + (slots.empty() ? std::string("none") : slots);
    }
    static const char* const kPrimary[5] = {" no-primary", "", " directional", " point", " spot"};
    name += kPrimary[std::min(k.primary, 4u)];
    const bool edges = k.directEdges && k.secondary == uint32_t(glsl::SECONDARY_LIGHTMAP);
    return name + (k.primaryShadow ? "" : " unoccluded") + kSecondary[k.secondary & 3u] +
           (edges ? " edges" : "") + (k.effectLights ? "" : " no-effects") +
           (k.primaryFade ? " fade" : "");
}

// The pipeline keys the level's draws use: each static surface's and each dynamic mesh's, for
// frames with effect lights and without.
std::vector<uint32_t> forwardKeys(const SceneGeometry& geometry, const SceneMaterials& materials,
                                  const RendererOptions& options) {
    const uint32_t materialCount = uint32_t(materials.classes.size());
    std::vector<uint32_t> keys;
    for (const bool effects : {false, true}) {
        for (const DrawSurface& s : geometry.surfaces)
            for (const bool shadow : {false, true}) {
                // An unoccluded surface's shadowed variant: while a dynamic caster may reach it.
                if (!shadow && !s.unoccluded) continue;
                if (shadow && s.unoccluded && !geometry.dynamicCasters) continue;
                keys.push_back(drawPipelineKey(
                    materials, options, std::min(s.material, materialCount - 1), s.primaryKind,
                    uint32_t(s.atlas != kNoIndex ? glsl::SECONDARY_LIGHTMAP
                                                 : glsl::SECONDARY_CONSTANT),
                    effects, shadow, false, s.directEdges));
            }
        for (const DrawDynamicMesh& d : geometry.dynamicMeshes)
            for (const uint32_t kind : geometry.dynamicPrimaryKinds)
                for (const bool fade : {false, true})  // while its primary switch cross-fades
                    keys.push_back(drawPipelineKey(
                        materials, options, std::min(d.material, materialCount - 1), kind,
                        uint32_t(glsl::SECONDARY_OBJECT), effects, true, fade));
        // A level with nothing to draw still gets a pipeline.
        if (geometry.surfaces.empty() && geometry.dynamicMeshes.empty())
            keys.push_back(drawPipelineKey(materials, options, 0, uint32_t(glsl::PRIMARY_ANY),
                                           uint32_t(glsl::SECONDARY_ANY), effects));
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    return keys;
}

constexpr VkShaderStageFlags kFragment = VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr VkShaderStageFlags kVertexFragment =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
constexpr VkDescriptorType kUniformDynamic = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;

// Set 0 of the forward pass, binding by binding (gpu_interface.glsl).
const std::vector<VkDescriptorSetLayoutBinding>& frameBindings() {
    static const std::vector<VkDescriptorSetLayoutBinding> bindings = {
        vk::layoutBinding(glsl::BINDING_FRAME, kUniform, kVertexFragment),
        vk::layoutBinding(glsl::BINDING_SHADOW_VIEWS, kUniform, kFragment),
        vk::layoutBinding(glsl::BINDING_SHADOW_MAPS, kSampled, kFragment),
        vk::layoutBinding(glsl::BINDING_LIGHTMAP, kSampled, kFragment),
        vk::layoutBinding(glsl::BINDING_SHADOW_MASK, kSampled, kFragment),
        vk::layoutBinding(glsl::BINDING_PROBES, kSampled, kFragment),
        vk::layoutBinding(glsl::BINDING_ENV_BRDF, kSampled, kFragment),
        vk::layoutBinding(glsl::BINDING_PROBE_RECORDS, kStorage, kFragment),
        vk::layoutBinding(glsl::BINDING_SKY, kSampled, kFragment),
        vk::layoutBinding(glsl::BINDING_PROBE_CELLS, kStorage, kFragment),
        vk::layoutBinding(glsl::BINDING_PRIMARY_LIGHTS, kUniform, kFragment),
        vk::layoutBinding(glsl::BINDING_OBJECT_LIGHTING, kStorage, kFragment),
        vk::layoutBinding(glsl::BINDING_MATERIAL_RECORDS, kUniformDynamic, kFragment)};
    static_assert(glsl::FRAME_BINDING_COUNT == 13, "one layout binding per frame binding");
    return bindings;
}

// Set 1: a material's textures, slot by slot.
const std::vector<VkDescriptorSetLayoutBinding>& materialBindings() {
    static const std::vector<VkDescriptorSetLayoutBinding> bindings = [] {
        std::vector<VkDescriptorSetLayoutBinding> b;
        for (int slot = 0; slot < glsl::TEXTURE_SLOT_COUNT; ++slot)
            b.push_back(vk::layoutBinding(uint32_t(slot), kSampled, kFragment));
        return b;
    }();
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

void createLayouts(const vk::Context& ctx, Pipelines& p) {
    const std::vector<std::vector<VkDescriptorSetLayoutBinding>> forwardSets = {frameBindings(),
                                                                                materialBindings()};
    vk::createPipelineLayout(ctx, p.forwardLayout, forwardSets, sizeof(DrawPush), kVertexFragment);
    const std::vector<std::vector<VkDescriptorSetLayoutBinding>> noSets;
    vk::createPipelineLayout(ctx, p.shadowLayout, noSets, sizeof(glm::mat4),
                             VK_SHADER_STAGE_VERTEX_BIT);
    const std::vector<std::vector<VkDescriptorSetLayoutBinding>> maskedSets = {materialBindings()};
    vk::createPipelineLayout(ctx, p.maskedShadowLayout, maskedSets, sizeof(MaskedShadowPush),
                             kVertexFragment);
    const std::vector<std::vector<VkDescriptorSetLayoutBinding>> tonemapSets = {
        {vk::layoutBinding(glsl::BINDING_TONEMAP_HDR, kSampled, kFragment),
         vk::layoutBinding(glsl::BINDING_TONEMAP_LUT, kSampled, kFragment)}};
    vk::createPipelineLayout(ctx, p.tonemapLayout, tonemapSets, 0, 0);
    const std::vector<std::vector<VkDescriptorSetLayoutBinding>> fxaaSets = {
        {vk::layoutBinding(glsl::BINDING_FXAA_INPUT, kSampled, kFragment)}};
    vk::createPipelineLayout(ctx, p.fxaaLayout, fxaaSets, 0, 0);
}

// Forward permutations: only those the level's draws use (and the flat one for benchmarks).
void createForwardPipelines(const vk::Context& ctx, Pipelines& p, const SceneGeometry& geometry,
                            const SceneMaterials& materials, const RendererOptions& options,
                            const ForwardChoices& choices) {
    vk::GraphicsPipelineDesc forward;
    forward.vertexBindings = {{0, sizeof(world::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    forward.vertexAttributes = vertexAttributes(false);
    forward.samples = choices.samples;
    forward.colorFormats = {kHdrFormat};
    forward.depthFormat = kDepthFormat;
    const std::vector<uint32_t> keys = forwardKeys(geometry, materials, options);
    const int bakedLighting = choices.fetchBakedLighting ? 1 : 0;
    for (uint32_t key : keys) {
        const PermutationKey k = unpackPermutationKey(key);
        const int materialClass = int(k.materialClass);
        forward.cullMode = k.doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
        forward.alphaBlend = k.alphaBlend;
        forward.depthWrite = !k.alphaBlend;
        forward.stages = {
            {VK_SHADER_STAGE_VERTEX_BIT, kForwardVertSpirv, {}},
            {VK_SHADER_STAGE_FRAGMENT_BIT,
             k.alphaMask && !k.alphaBlend ? std::span<const uint32_t>(kForwardMaskedFragSpirv)
                                          : std::span<const uint32_t>(kForwardFragSpirv),
             {{glsl::SPEC_MATERIAL_CLASS, materialClass},
              {glsl::SPEC_ALPHA_MODE, k.alphaBlend  ? glsl::ALPHA_MODE_BLEND
                                      : k.alphaMask ? glsl::ALPHA_MODE_MASK
                                                    : glsl::ALPHA_MODE_OPAQUE},
              {glsl::SPEC_FLAT_SHADING, 0},
              {glsl::SPEC_BAKED_LIGHTING, bakedLighting},
              {glsl::SPEC_DIFFUSE_MODEL, choices.diffuseModel},
              {glsl::SPEC_MATERIAL_PIPELINE, options.materialPipeline ? 1 : 0},
              {glsl::SPEC_PROBES, choices.probes ? 1 : 0},
              {glsl::SPEC_TEXTURES, int(k.textures)},
              {glsl::SPEC_PRIMARY, int(k.primary)},
              {glsl::SPEC_SECONDARY, int(k.secondary)},
              {glsl::SPEC_EFFECT_LIGHTS, k.effectLights ? 1 : 0},
              {glsl::SPEC_FEATURES_OFF, int(options.featuresOff)},
              {glsl::SPEC_PRIMARY_SHADOW, k.primaryShadow ? 1 : 0},
              {glsl::SPEC_PRIMARY_FADE, k.primaryFade ? 1 : 0},
              {glsl::SPEC_DIRECT_EDGES, k.directEdges ? 1 : 0}}}};
        p.forward[key] = vk::createGraphicsPipeline(ctx, p.forwardLayout, forward);
        p.permutations.push_back(permutationName(k));
    }
    forward.alphaBlend = false;
    forward.depthWrite = true;
    if (options.depthPrepass && !options.flatShading) {
        vk::GraphicsPipelineDesc depth = forward;
        depth.stages = {{VK_SHADER_STAGE_VERTEX_BIT, kForwardVertSpirv, {}}};
        depth.colorWrite = false;
        for (int doubleSided = 0; doubleSided < 2; ++doubleSided) {
            depth.cullMode = doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
            p.depth[doubleSided] = vk::createGraphicsPipeline(ctx, p.forwardLayout, depth);
        }
    }
    if (options.flatShading) {
        forward.cullMode = VK_CULL_MODE_BACK_BIT;
        forward.stages = {
            {VK_SHADER_STAGE_VERTEX_BIT, kForwardVertSpirv, {}},
            {VK_SHADER_STAGE_FRAGMENT_BIT, kForwardFragSpirv, {{glsl::SPEC_FLAT_SHADING, 1}}}};
        p.flat = vk::createGraphicsPipeline(ctx, p.forwardLayout, forward);
        p.permutations = {"flat"};
    }
}

void createShadowAndTonemapPipelines(const vk::Context& ctx, Pipelines& p, bool fxaa) {
    vk::GraphicsPipelineDesc shadow;
    shadow.stages = {{VK_SHADER_STAGE_VERTEX_BIT, kShadowVertSpirv, {}}};
    shadow.vertexBindings = {{0, sizeof(world::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    shadow.vertexAttributes = vertexAttributes(true);
    shadow.cullMode = VK_CULL_MODE_NONE;
    shadow.dynamicDepthBias = true;
    shadow.depthFormat = kDepthFormat;
    p.shadow = vk::createGraphicsPipeline(ctx, p.shadowLayout, shadow);
    shadow.stages = {{VK_SHADER_STAGE_VERTEX_BIT, kShadowMaskedVertSpirv, {}},
                     {VK_SHADER_STAGE_FRAGMENT_BIT, kShadowMaskedFragSpirv, {}}};
    shadow.vertexAttributes = vertexAttributes(false);
    p.maskedShadow = vk::createGraphicsPipeline(ctx, p.maskedShadowLayout, shadow);

    vk::GraphicsPipelineDesc tonemap;
    tonemap.stages = {{VK_SHADER_STAGE_VERTEX_BIT, kFullscreenVertSpirv, {}},
                      {VK_SHADER_STAGE_FRAGMENT_BIT, kTonemapFragSpirv, {}}};
    tonemap.cullMode = VK_CULL_MODE_NONE;
    tonemap.depthTest = tonemap.depthWrite = false;
    tonemap.colorFormats = {kDisplayFormat};
    p.tonemap = vk::createGraphicsPipeline(ctx, p.tonemapLayout, tonemap);
    if (fxaa) {
        tonemap.stages = {{VK_SHADER_STAGE_VERTEX_BIT, kFullscreenVertSpirv, {}},
                          {VK_SHADER_STAGE_FRAGMENT_BIT, kFxaaFragSpirv, {}}};
        p.fxaa = vk::createGraphicsPipeline(ctx, p.fxaaLayout, tonemap);
    }
}

// The sky pass: the forward pass's layout and targets, no depth writes, behind everything.
void createSkyPipeline(const vk::Context& ctx, Pipelines& p, const ForwardChoices& choices) {
    if (!choices.skyImage) return;
    vk::GraphicsPipelineDesc sky;
    sky.stages = {{VK_SHADER_STAGE_VERTEX_BIT, kSkyVertSpirv, {}},
                  {VK_SHADER_STAGE_FRAGMENT_BIT, kSkyFragSpirv, {}}};
    sky.cullMode = VK_CULL_MODE_NONE;
    sky.depthWrite = false;
    sky.samples = choices.samples;
    sky.colorFormats = {kHdrFormat};
    sky.depthFormat = kDepthFormat;
    p.sky = vk::createGraphicsPipeline(ctx, p.forwardLayout, sky);
}

}  // namespace

uint32_t drawPipelineKey(const SceneMaterials& materials, const RendererOptions& options,
                         uint32_t material, uint32_t primary, uint32_t secondary, bool effectLights,
                         bool primaryShadow, bool primaryFade, bool directEdges) {
    if (options.flatShading) return 0u;
    PermutationKey k;
    k.materialClass = materials.classes[material];
    k.doubleSided = materials.doubleSided[material] != 0;
    k.alphaMask = materials.alphaMode[material] == uint8_t(world::AlphaMode::kMask);
    k.alphaBlend = materials.alphaMode[material] == uint8_t(world::AlphaMode::kBlend);
    if (options.specializeDraws) {
        k.textures = materials.textureSlots[material];
        k.primary = primary;
        k.secondary = secondary;
        k.effectLights = effectLights;
        k.primaryShadow = primaryShadow;
        k.primaryFade = primaryFade;
        k.directEdges = directEdges;
    }
    return permutationKey(k);
}

void createPipelines(const vk::Context& ctx, Pipelines& pipelines, const SceneGeometry& geometry,
                     const SceneMaterials& materials, const RendererOptions& options,
                     const ForwardChoices& choices) {
    createLayouts(ctx, pipelines);
    createForwardPipelines(ctx, pipelines, geometry, materials, options, choices);
    createShadowAndTonemapPipelines(ctx, pipelines, options.fxaa);
    createSkyPipeline(ctx, pipelines, choices);
}

void destroyPipelines(const vk::Context& ctx, Pipelines& pipelines) {
    for (VkPipeline* p :
         {&pipelines.sky, &pipelines.tonemap, &pipelines.fxaa, &pipelines.shadow,
          &pipelines.maskedShadow, &pipelines.flat, &pipelines.depth[0], &pipelines.depth[1]}) {
        if (*p) vkDestroyPipeline(ctx.device, *p, nullptr);
        *p = VK_NULL_HANDLE;
    }
    for (auto& [key, pipeline] : pipelines.forward)
        vkDestroyPipeline(ctx.device, pipeline, nullptr);
    pipelines.forward.clear();
    vk::destroyPipelineLayout(ctx, pipelines.fxaaLayout);
    vk::destroyPipelineLayout(ctx, pipelines.tonemapLayout);
    vk::destroyPipelineLayout(ctx, pipelines.maskedShadowLayout);
    vk::destroyPipelineLayout(ctx, pipelines.shadowLayout);
    vk::destroyPipelineLayout(ctx, pipelines.forwardLayout);
}

// One frame set per frame slot, one material set per material, the tonemap set.
void createDescriptorSets(const vk::Context& ctx, DescriptorSets& sets, const Pipelines& pipelines,
                          const FrameSlots& frames, const Scene& scene, const ShadowMaps& shadows,
                          const vk::Buffer& primaryLights, const RenderTargets& targets) {
    const uint32_t materials = uint32_t(scene.materials.bound.size());
    const std::vector<VkDescriptorSetLayoutBinding>& frame = frameBindings();
    const std::vector<VkDescriptorSetLayoutBinding>& material = materialBindings();
    const VkDescriptorPoolSize sizes[] = {
        {kUniform, kFramesInFlight * countOf(frame, kUniform)},
        {kUniformDynamic, kFramesInFlight * countOf(frame, kUniformDynamic)},
        {kStorage, kFramesInFlight * countOf(frame, kStorage)},
        {kSampled,
         kFramesInFlight * countOf(frame, kSampled) + materials * countOf(material, kSampled) + 3}};
    sets.pool = vk::createDescriptorPool(ctx, kFramesInFlight + materials + 2, sizes);

    const LookupTables& tables = scene.tables;
    const vk::Image& shadowMaps = sampledShadowMaps(shadows);
    for (uint32_t i = 0; i < kFramesInFlight; ++i) {
        const FrameSlot& slot = frames.slots[i];
        sets.frame[i] =
            vk::allocateDescriptorSet(ctx, sets.pool, pipelines.forwardLayout.setLayouts[0]);
        vk::DescriptorWriter w;
        w.set = sets.frame[i];
        w.buffer(glsl::BINDING_FRAME, kUniform, slot.uniforms.buffer);
        w.buffer(glsl::BINDING_SHADOW_VIEWS, kUniform, slot.shadowViews.buffer);
        w.image(glsl::BINDING_SHADOW_MAPS, shadowMaps.view, shadows.sampler);
        w.image(glsl::BINDING_LIGHTMAP, scene.baked.lightmap.view, tables.linearClamp);
        w.image(glsl::BINDING_SHADOW_MASK, scene.baked.shadowMask.view, tables.linearClamp);
        w.image(glsl::BINDING_PROBES, scene.probes.cubes.view, tables.linearClamp);
        w.image(glsl::BINDING_ENV_BRDF, tables.envBrdf.view, tables.linearClamp);
        w.buffer(glsl::BINDING_PROBE_RECORDS, kStorage, scene.probes.records.buffer);
        w.image(glsl::BINDING_SKY, scene.sky.image.view, scene.sky.sampler);
        w.buffer(glsl::BINDING_PROBE_CELLS, kStorage, scene.probes.cells.buffer);
        w.buffer(glsl::BINDING_PRIMARY_LIGHTS, kUniform, primaryLights.buffer);
        w.buffer(glsl::BINDING_OBJECT_LIGHTING, kStorage, slot.objectLighting.buffer);
        w.buffer(glsl::BINDING_MATERIAL_RECORDS, kUniformDynamic, scene.materials.records.buffer, 0,
                 scene.materials.pageBytes);
        w.update(ctx);
    }
    for (size_t i = 0; i < scene.materials.bound.size(); ++i) {
        const MaterialTextures& textures = scene.materials.bound[i];
        vk::DescriptorWriter m;
        m.set = vk::allocateDescriptorSet(ctx, sets.pool, pipelines.forwardLayout.setLayouts[1]);
        for (uint32_t t = 0; t < uint32_t(glsl::TEXTURE_SLOT_COUNT); ++t)
            m.image(t, textures[t].first, textures[t].second);
        m.update(ctx);
        sets.material.push_back(m.set);
    }
    sets.tonemap = vk::allocateDescriptorSet(ctx, sets.pool, pipelines.tonemapLayout.setLayouts[0]);
    if (pipelines.fxaa)
        sets.fxaa = vk::allocateDescriptorSet(ctx, sets.pool, pipelines.fxaaLayout.setLayouts[0]);
    writeTonemapSet(ctx, sets, targets, tables);
}

void destroyDescriptorSets(const vk::Context& ctx, DescriptorSets& sets) {
    if (sets.pool) vkDestroyDescriptorPool(ctx.device, sets.pool, nullptr);
    sets.pool = VK_NULL_HANDLE;
    sets.material.clear();
    sets.tonemap = sets.fxaa = VK_NULL_HANDLE;
    sets.frame.fill(VK_NULL_HANDLE);
}

void writeTonemapSet(const vk::Context& ctx, const DescriptorSets& sets,
                     const RenderTargets& targets, const LookupTables& tables) {
    vk::DescriptorWriter w;
    w.set = sets.tonemap;
    w.image(glsl::BINDING_TONEMAP_HDR, targets.hdr.view, tables.nearestClamp);
    w.image(glsl::BINDING_TONEMAP_LUT, tables.lut.view, tables.linearClamp);
    w.update(ctx);
    if (sets.fxaa && targets.tonemapped.image) {
        vk::DescriptorWriter f;
        f.set = sets.fxaa;
        f.image(glsl::BINDING_FXAA_INPUT, targets.tonemapped.view, tables.linearClamp);
        f.update(ctx);
    }
}

}  // namespace onelight::render
