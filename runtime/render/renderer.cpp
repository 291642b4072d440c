// The renderer's frame: culling, primary selection for dynamic objects, shadow passes, the
// forward pass (MSAA, HDR), the tonemap pass and the outputs.
#include "render/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <glm/gtc/packing.hpp>
#include <glm/gtc/quaternion.hpp>

#include "render/renderer_state.hpp"
#include "shading.hpp"
#include "vk/commands.hpp"
#include "vk/descriptors.hpp"
#include "vk/vk_check.hpp"
#include "world/light_grid_sample.hpp"

#include "forward.frag.spv.h"
#include "forward.vert.spv.h"
#include "fullscreen.vert.spv.h"
#include "shadow.vert.spv.h"
#include "tonemap.frag.spv.h"

namespace onelight::render {

namespace {

namespace glsl = onelight::glsl;

constexpr float kPrimaryHysteresis =
    1.25f;  // a dynamic object's new primary must be this much brighter

const char* const kClassNames[4] = {"metal", "dielectric", "full", "lambert"};

// The supported sample count nearest to `requested` (in powers of two; ties go up).
VkSampleCountFlagBits pickSamples(const vk::Context& ctx, uint32_t requested) {
    const VkSampleCountFlags supported = ctx.properties.limits.framebufferColorSampleCounts &
                                         ctx.properties.limits.framebufferDepthSampleCounts;
    const int want = int(std::round(std::log2(double(std::max(requested, 1u)))));
    int best = 0, bestDistance = 1 << 20;
    for (int bit = 0; bit <= 6; ++bit) {
        if (!(supported & (1u << bit))) continue;
        const int distance = std::abs(bit - want);
        if (distance < bestDistance || (distance == bestDistance && bit > best)) {
            best = bit;
            bestDistance = distance;
        }
    }
    return VkSampleCountFlagBits(1u << best);
}

std::vector<VkVertexInputAttributeDescription> vertexAttributes(bool positionOnly) {
    std::vector<VkVertexInputAttributeDescription> a = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                                                        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 12},
                                                        {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 24},
                                                        {3, 0, VK_FORMAT_R32G32_SFLOAT, 40},
                                                        {4, 0, VK_FORMAT_R32G32_SFLOAT, 48}};
    if (positionOnly) a.resize(1);
    return a;
}

void createTargets(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    vk::ImageDesc desc;
    desc.width = s.width;
    desc.height = s.height;
    desc.format = kHdrFormat;
    desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                 VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    vk::createImage(ctx, s.hdr, desc);
    desc.format = kDisplayFormat;
    desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    vk::createImage(ctx, s.display, desc);
    desc.samples = s.samples;
    if (s.samples != VK_SAMPLE_COUNT_1_BIT) {
        desc.format = kHdrFormat;
        desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
        vk::createImage(ctx, s.msaaColor, desc);
    }
    desc.format = kDepthFormat;
    desc.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    vk::createImage(ctx, s.depth, desc);
    const VkDeviceSize pixels = VkDeviceSize(s.width) * s.height;
    vk::createHostBuffer(ctx, s.readbackHdr, pixels * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    vk::createHostBuffer(ctx, s.readbackDisplay, pixels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
}

void destroyTargets(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    vk::destroyBuffer(ctx, s.readbackSwapchain);
    vk::destroyBuffer(ctx, s.readbackDisplay);
    vk::destroyBuffer(ctx, s.readbackHdr);
    vk::destroyImage(ctx, s.depth);
    vk::destroyImage(ctx, s.msaaColor);
    vk::destroyImage(ctx, s.display);
    vk::destroyImage(ctx, s.hdr);
}

void writeTonemapSet(RendererState& s) {
    vk::DescriptorWriter w;
    w.set = s.tonemapSet;
    w.image(0, s.hdr.view, s.nearestClamp);
    w.image(1, s.lut.view, s.linearClamp);
    w.update(*s.ctx);
}

void createPipelines(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    const VkShaderStageFlags fs = VK_SHADER_STAGE_FRAGMENT_BIT;
    const VkShaderStageFlags vfs = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const std::vector<std::vector<VkDescriptorSetLayoutBinding>> forwardSets = {
        {vk::layoutBinding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vfs),
         vk::layoutBinding(1, storage, fs), vk::layoutBinding(2, storage, fs),
         vk::layoutBinding(3, sampled, fs), vk::layoutBinding(4, sampled, fs),
         vk::layoutBinding(5, sampled, fs), vk::layoutBinding(6, storage, fs),
         vk::layoutBinding(7, sampled, fs), vk::layoutBinding(8, storage, fs),
         vk::layoutBinding(9, sampled, fs), vk::layoutBinding(10, storage, fs)},
        {vk::layoutBinding(0, sampled, fs), vk::layoutBinding(1, sampled, fs),
         vk::layoutBinding(2, sampled, fs), vk::layoutBinding(3, sampled, fs),
         vk::layoutBinding(4, sampled, fs)}};
    vk::createPipelineLayout(ctx, s.forwardLayout, forwardSets, sizeof(DrawPush), vfs);
    const std::vector<std::vector<VkDescriptorSetLayoutBinding>> noSets;
    vk::createPipelineLayout(ctx, s.shadowLayout, noSets, sizeof(glm::mat4),
                             VK_SHADER_STAGE_VERTEX_BIT);
    const std::vector<std::vector<VkDescriptorSetLayoutBinding>> tonemapSets = {
        {vk::layoutBinding(0, sampled, fs), vk::layoutBinding(1, sampled, fs)}};
    vk::createPipelineLayout(ctx, s.tonemapLayout, tonemapSets, 0, 0);

    // Forward permutations: only those the level's materials use.
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
    for (uint32_t key : keys) {
        const int materialClass = int(key & 3u);
        const bool doubleSided = (key & 4u) != 0, alphaMask = (key & 8u) != 0;
        forward.cullMode = doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
        forward.stages = {{VK_SHADER_STAGE_VERTEX_BIT, forward_vert_spv, {}},
                          {VK_SHADER_STAGE_FRAGMENT_BIT,
                           forward_frag_spv,
                           {{0, materialClass},
                            {1, alphaMask ? 1 : 0},
                            {2, 0},
                            {3, s.bakedLighting || s.options.samplePlaceholders ? 1 : 0}}}};
        s.forwardPipelines[key] = vk::createGraphicsPipeline(ctx, s.forwardLayout, forward);
        s.info.permutations.push_back(std::string(kClassNames[materialClass]) +
                                      (doubleSided ? "+double-sided" : "") +
                                      (alphaMask ? "+alpha-mask" : ""));
    }
    if (s.options.flatShading) {
        forward.cullMode = VK_CULL_MODE_BACK_BIT;
        forward.stages = {{VK_SHADER_STAGE_VERTEX_BIT, forward_vert_spv, {}},
                          {VK_SHADER_STAGE_FRAGMENT_BIT, forward_frag_spv, {{2, 1}}}};
        s.flatPipeline = vk::createGraphicsPipeline(ctx, s.forwardLayout, forward);
        s.info.permutations = {"flat"};
    }

    vk::GraphicsPipelineDesc shadow;
    shadow.stages = {{VK_SHADER_STAGE_VERTEX_BIT, shadow_vert_spv, {}}};
    shadow.vertexBindings = forward.vertexBindings;
    shadow.vertexAttributes = vertexAttributes(true);
    shadow.cullMode = VK_CULL_MODE_NONE;
    shadow.dynamicDepthBias = true;
    shadow.depthFormat = kDepthFormat;
    s.shadowPipeline = vk::createGraphicsPipeline(ctx, s.shadowLayout, shadow);

    vk::GraphicsPipelineDesc tonemap;
    tonemap.stages = {{VK_SHADER_STAGE_VERTEX_BIT, fullscreen_vert_spv, {}},
                      {VK_SHADER_STAGE_FRAGMENT_BIT, tonemap_frag_spv, {}}};
    tonemap.cullMode = VK_CULL_MODE_NONE;
    tonemap.depthTest = tonemap.depthWrite = false;
    tonemap.colorFormats = {kDisplayFormat};
    s.tonemapPipeline = vk::createGraphicsPipeline(ctx, s.tonemapLayout, tonemap);

    // Descriptors: the frame set, one set per material, the tonemap set.
    const uint32_t materialCount = uint32_t(s.materialTextures.size());
    const VkDescriptorPoolSize sizes[] = {
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}, {storage, 5}, {sampled, 6 + 5 * materialCount + 2}};
    s.descriptorPool = vk::createDescriptorPool(ctx, 2 + materialCount, sizes);
    s.frameSet = vk::allocateDescriptorSet(ctx, s.descriptorPool, s.forwardLayout.setLayouts[0]);
    vk::DescriptorWriter w;
    w.set = s.frameSet;
    w.buffer(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, s.frameBuffer.buffer);
    w.buffer(1, storage, s.lightBuffer.buffer);
    w.buffer(2, storage, s.shadowViewBuffer.buffer);
    w.image(3, s.frameShadows.image ? s.frameShadows.view : s.staticShadows.view, s.shadowSampler);
    w.image(4, s.lightmap.view, s.linearClamp);
    w.image(5, s.shadowMask.view, s.linearClamp);
    w.buffer(6, storage, s.objectLightingBuffer.buffer);
    w.image(7, s.probe.view, s.linearClamp);
    w.buffer(8, storage, s.materialBuffer.buffer);
    w.image(9, s.envBrdf.view, s.linearClamp);
    w.buffer(10, storage, s.probeBuffer.buffer);
    w.update(ctx);
    for (const MaterialTextures& textures : s.materialTextures) {
        vk::DescriptorWriter m;
        m.set = vk::allocateDescriptorSet(ctx, s.descriptorPool, s.forwardLayout.setLayouts[1]);
        for (uint32_t t = 0; t < 5; ++t) m.image(t, textures[t].first, textures[t].second);
        m.update(ctx);
        s.materialSets.push_back(m.set);
    }
    s.tonemapSet = vk::allocateDescriptorSet(ctx, s.descriptorPool, s.tonemapLayout.setLayouts[0]);
    writeTonemapSet(s);
}

void destroyPipelines(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    if (s.descriptorPool) vkDestroyDescriptorPool(ctx.device, s.descriptorPool, nullptr);
    s.descriptorPool = VK_NULL_HANDLE;
    s.materialSets.clear();
    for (VkPipeline* p : {&s.tonemapPipeline, &s.shadowPipeline, &s.flatPipeline}) {
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

void createSubmission(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    VkCommandBufferAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    alloc.commandPool = ctx.commandPool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(ctx.device, &alloc, &s.cmd));
    VkFenceCreateInfo fence{};
    fence.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    VK_CHECK(vkCreateFence(ctx.device, &fence, nullptr, &s.fence));

    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &count, families.data());
    s.timestamps = families[ctx.queueFamily].timestampValidBits > 0 &&
                   ctx.properties.limits.timestampPeriod > 0.0f;
    if (s.timestamps) {
        VkQueryPoolCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
        info.queryType = VK_QUERY_TYPE_TIMESTAMP;
        info.queryCount = 4;
        VK_CHECK(vkCreateQueryPool(ctx.device, &info, nullptr, &s.queries));
    }
}

void destroySubmission(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    if (s.queries) vkDestroyQueryPool(ctx.device, s.queries, nullptr);
    s.queries = VK_NULL_HANDLE;
    if (s.fence) vkDestroyFence(ctx.device, s.fence, nullptr);
    s.fence = VK_NULL_HANDLE;
    if (s.cmd) vkFreeCommandBuffers(ctx.device, ctx.commandPool, 1, &s.cmd);
    s.cmd = VK_NULL_HANDLE;
}

glm::mat4 entityMatrix(const world::Entity& e) {
    glm::mat4 m = glm::mat4_cast(glm::normalize(e.rotation));
    m[0] *= e.scale.x;
    m[1] *= e.scale.y;
    m[2] *= e.scale.z;
    m[3] = glm::vec4(e.position, 1.0f);
    return m;
}

float luminance(glm::vec3 c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

// Unshadowed illuminance (luminance, lux) of primary light `i` at p, by the shared light model.
float primaryIlluminance(const RendererState& s, uint32_t i, glm::vec3 p) {
    const world::Light& l = s.lights[i];
    const glsl::LightSample sample = glsl::evaluatePunctualLight(
        int(l.type), l.color, l.intensity, l.range, l.position, glm::normalize(l.direction),
        std::cos(l.inner_cone), std::cos(l.outer_cone), p);
    return luminance(sample.illuminance);
}

// The primary of a dynamic object at its lighting origin, with hysteresis against flicker: a new
// primary must score kPrimaryHysteresis times the current one. With a light grid the candidates
// are the dominant primaries of the grid cells around the origin, scored by their illuminance
// there times their baked visibility (world::dominantVisibility), so an object in a primary's
// shadow does not pick it; a current primary that dominates none of those cells any more is
// dropped. Without a grid every primary candidate is scored by its unshadowed illuminance.
uint32_t pickDynamicPrimary(RendererState& s, uint32_t entity, glm::vec3 origin,
                            const world::LightGridSample* grid) {
    uint32_t current = s.dynamicPrimary[entity];
    auto score = [&](uint32_t i) {
        const float e = primaryIlluminance(s, i, origin);
        return grid ? e * world::dominantVisibility(s.grid, *grid, i) : e;
    };
    float currentScore = current != kNoIndex ? score(current) : 0.0f;
    if (grid && !(currentScore > 0.0f)) {
        current = kNoIndex;
        currentScore = 0.0f;
    }
    for (uint32_t i = 0; i < s.lights.size(); ++i) {
        if (s.lights[i].role != world::LightRole::primary || i == current) continue;
        const float e = score(i);
        if (e > 0.0f && e > currentScore * kPrimaryHysteresis) {
            current = i;
            currentScore = e;
        }
    }
    s.dynamicPrimary[entity] = current;
    return current;
}

// A dynamic object's baked lighting for the forward pass: the grid's ambient cube at its origin
// and the baked visibility of its primary; neutral values (the placeholder ambient, visible) for
// the placeholder textures of a level without a grid.
GpuObjectLighting objectLightingOf(const RendererState& s, const world::LightGridSample* grid,
                                   uint32_t primary) {
    GpuObjectLighting o{};
    for (int f = 0; f < 6; ++f)
        o.ambientCube[f] = grid ? glm::vec4(grid->ambientCube[size_t(f)], 0.0f)
                                : glm::vec4(glm::vec3(s.ambientLux), 0.0f);
    o.ambientCube[0].w =
        grid && primary != kNoIndex ? world::bakedVisibility(s.grid, *grid, primary) : 1.0f;
    return o;
}

void worldBounds(const glm::mat4& m, glm::vec3 lo, glm::vec3 hi, glm::vec3& outMin,
                 glm::vec3& outMax) {
    outMin = glm::vec3(1e30f);
    outMax = glm::vec3(-1e30f);
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
        const glm::vec3 w = glm::vec3(m * glm::vec4(corner, 1.0f));
        outMin = glm::min(outMin, w);
        outMax = glm::max(outMax, w);
    }
}

struct Draw {
    uint32_t key;
    uint32_t material;
    uint32_t firstIndex, indexCount;
    int32_t vertexOffset;
    uint32_t primaryLight, atlas;
    uint32_t entity;  // kNoIndex for static; a dynamic object's record in objectLighting
    float distance2;  // squared metres from the camera: front to back within a permutation
};

// Dynamic rendering over the whole frame into `color` (and `depth` when given), with the
// viewport and scissor set to it.
void beginFrameRendering(VkCommandBuffer cmd, const RendererState& s,
                         const VkRenderingAttachmentInfo& color,
                         const VkRenderingAttachmentInfo* depth) {
    VkRenderingInfo info{};
    info.sType = VK_STRUCTURE_TYPE_RENDERING_INFO;
    info.renderArea = {{0, 0}, {s.width, s.height}};
    info.layerCount = 1;
    info.colorAttachmentCount = 1;
    info.pColorAttachments = &color;
    info.pDepthAttachment = depth;
    vkCmdBeginRendering(cmd, &info);
    const VkViewport viewport{0.0f, 0.0f, float(s.width), float(s.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {s.width, s.height}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

// The forward pass over a clear to the level's sky (pre-exposed radiance, as the pass writes).
void beginColorRendering(VkCommandBuffer cmd, const RendererState& s, float exposure) {
    VkRenderingAttachmentInfo color{};
    color.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    const glm::vec3 sky = glm::min(s.settings.sky_radiance * exposure, glm::vec3(kHdrMax));
    color.clearValue.color = {{sky.r, sky.g, sky.b, 1.0f}};
    if (s.samples != VK_SAMPLE_COUNT_1_BIT) {
        color.imageView = s.msaaColor.view;
        color.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        color.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        color.resolveImageView = s.hdr.view;
        color.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    } else {
        color.imageView = s.hdr.view;
        color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    }
    VkRenderingAttachmentInfo depth{};
    depth.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
    depth.imageView = s.depth.view;
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth.clearValue.depthStencil = {1.0f, 0};
    beginFrameRendering(cmd, s, color, &depth);
}

void copyImageToBuffer(VkCommandBuffer cmd, VkImage image, uint32_t width, uint32_t height,
                       const vk::Buffer& buffer) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {width, height, 1};
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.buffer, 1,
                           &copy);
    vk::bufferBarrier(cmd, buffer, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
}

void bgraToRgba(const uint8_t* bgra, size_t pixels, std::vector<uint8_t>& rgba) {
    rgba.resize(pixels * 4);
    for (size_t i = 0; i < pixels; ++i) {
        rgba[4 * i + 0] = bgra[4 * i + 2];
        rgba[4 * i + 1] = bgra[4 * i + 1];
        rgba[4 * i + 2] = bgra[4 * i + 0];
        rgba[4 * i + 3] = bgra[4 * i + 3];
    }
}

}  // namespace

Renderer::Renderer() = default;
Renderer::~Renderer() = default;

vk::ContextOptions renderContextOptions(RenderDeviceFeatures& features,
                                        const std::vector<const char*>& windowExtensions) {
    vk::ContextOptions options;
    options.apiVersion = VK_API_VERSION_1_3;
    options.instanceExtensions = windowExtensions;
    if (!windowExtensions.empty())
        options.deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    features.vulkan13 = {};
    features.vulkan13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
    features.vulkan13.dynamicRendering = VK_TRUE;
    options.features.imageCubeArray = VK_TRUE;  // the probes' cube array
    options.featureChain = &features.vulkan13;
    return options;
}

void createRenderer(Renderer& renderer, vk::Context& ctx, const assets::LoadedLevel& level,
                    const RendererOptions& options) {
    renderer.state = std::make_unique<RendererState>();
    RendererState& s = *renderer.state;
    s.ctx = &ctx;
    s.options = options;
    s.width = std::max(options.width, 1u);
    s.height = std::max(options.height, 1u);
    s.samples = pickSamples(ctx, options.requestedMsaa);
    s.info.deviceName = ctx.properties.deviceName;
    s.info.msaaRequested = options.requestedMsaa;
    s.info.msaaInUse = uint32_t(s.samples);
    try {
        vk::createHostBuffer(ctx, s.frameBuffer, sizeof(FrameUniforms),
                             VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        uploadScene(s, level);
        createShadows(s);
        createTargets(s);
        createPipelines(s);
        createSubmission(s);
    } catch (...) {
        destroyRenderer(renderer);
        throw;
    }
}

void destroyRenderer(Renderer& renderer) {
    if (!renderer.state) return;
    RendererState& s = *renderer.state;
    vkDeviceWaitIdle(s.ctx->device);
    destroySubmission(s);
    destroyPipelines(s);
    destroyTargets(s);
    destroyShadows(s);
    destroyScene(s);
    vk::destroyBuffer(*s.ctx, s.frameBuffer);
    renderer.state.reset();
}

const RendererInfo& rendererInfo(const Renderer& renderer) {
    return renderer.state->info;
}

const CapturedFrame& capturedFrame(const Renderer& renderer) {
    return renderer.state->captured;
}

uint32_t dynamicPrimary(const Renderer& renderer, uint32_t entity) {
    const RendererState& s = *renderer.state;
    return entity < s.dynamicPrimary.size() ? s.dynamicPrimary[entity] : kNoIndex;
}

void resizeRenderer(Renderer& renderer, uint32_t width, uint32_t height) {
    RendererState& s = *renderer.state;
    if (width == s.width && height == s.height) return;
    VK_CHECK(vkDeviceWaitIdle(s.ctx->device));
    destroyTargets(s);
    s.width = std::max(width, 1u);
    s.height = std::max(height, 1u);
    createTargets(s);
    writeTonemapSet(s);
}

FrameStats drawFrame(Renderer& renderer, const FrameInputs& inputs, const FrameOutput& output) {
    RendererState& s = *renderer.state;
    const vk::Context& ctx = *s.ctx;
    const auto cpuStart = std::chrono::steady_clock::now();
    FrameStats stats;

    // Camera and exposure.
    const Camera& camera = inputs.camera;
    const float diagonal = std::max(glm::length(s.boundsMax - s.boundsMin), 1.0f);
    const float zfar =
        camera.zfar > 0.0f
            ? camera.zfar
            : glm::length(camera.position - 0.5f * (s.boundsMin + s.boundsMax)) + diagonal;
    const glm::mat4 viewProj =
        projectionMatrix(camera, float(s.width) / float(s.height), zfar) * viewMatrix(camera);
    stats.ev100 = camera.hasExposure        ? camera.ev100
                  : s.settings.has_exposure ? s.settings.exposure_ev100
                                            : s.info.autoEv100;
    stats.exposure = glsl::exposure_fromEV100(stats.ev100);

    // Dynamic objects: transforms, then their primary.
    std::vector<glm::mat4> entityTransforms(s.entities.size());
    std::vector<uint32_t> givenPrimary(s.entities.size(), kNoIndex);
    for (size_t e = 0; e < s.entities.size(); ++e)
        entityTransforms[e] = entityMatrix(s.entities[e]);
    for (const DynamicTransform& t : inputs.dynamicTransforms) {
        if (t.entity >= entityTransforms.size()) continue;
        entityTransforms[t.entity] = t.worldFromObject;
        if (t.primary < s.lights.size()) givenPrimary[t.entity] = t.primary;
    }

    // Culling and the draw list.
    const Frustum frustum = frustumOf(viewProj);
    std::vector<Draw> draws;
    std::vector<uint32_t> visibleLights;
    auto keyOf = [&](uint32_t material) {
        return s.options.flatShading ? 0u
                                     : permutationKey(s.materialClasses[material],
                                                      s.materialDoubleSided[material] != 0,
                                                      s.materialAlphaMask[material] != 0);
    };
    const uint32_t materialCount = uint32_t(s.materialClasses.size());
    for (const DrawSurface& surface : s.surfaces) {
        if (!intersects(frustum, surface.boundsMin, surface.boundsMax)) {
            ++stats.surfacesCulled;
            continue;
        }
        const uint32_t material = std::min(surface.material, materialCount - 1);
        const glm::vec3 toCentre = 0.5f * (surface.boundsMin + surface.boundsMax) - camera.position;
        draws.push_back({keyOf(material), material, surface.firstIndex, surface.indexCount, 0,
                         surface.primaryLight, surface.atlas, kNoIndex,
                         glm::dot(toCentre, toCentre)});
        if (surface.primaryLight != kNoIndex) visibleLights.push_back(surface.primaryLight);
        ++stats.surfacesDrawn;
    }
    // Dynamic objects: the primary and the grid's lighting once per visible entity.
    std::vector<uint8_t> entityVisible(s.entities.size(), 0);
    std::vector<uint32_t> entityPrimary(s.entities.size(), kNoIndex);
    for (const DrawDynamicMesh& mesh : s.dynamicMeshes) {
        glm::vec3 lo, hi;
        worldBounds(entityTransforms[mesh.entity], mesh.boundsMin, mesh.boundsMax, lo, hi);
        if (intersects(frustum, lo, hi)) entityVisible[mesh.entity] = 1;
    }
    auto* records = static_cast<GpuObjectLighting*>(s.objectLightingBuffer.mapped);
    const bool useGrid = s.bakedLighting && !s.grid.cells.empty();
    for (uint32_t e = 0; e < s.entities.size(); ++e) {
        if (!entityVisible[e]) continue;
        const glm::vec3 origin(entityTransforms[e][3]);
        world::LightGridSample sample;
        if (useGrid) sample = world::sampleLightGrid(s.grid, origin);
        // The game's pick when it made one (it runs on the fixed tick, so replays expect what
        // is drawn); otherwise the renderer's own.
        entityPrimary[e] = givenPrimary[e] != kNoIndex
                               ? (s.dynamicPrimary[e] = givenPrimary[e])
                               : pickDynamicPrimary(s, e, origin, useGrid ? &sample : nullptr);
        records[e] = objectLightingOf(s, useGrid ? &sample : nullptr, entityPrimary[e]);
    }
    for (const DrawDynamicMesh& mesh : s.dynamicMeshes) {
        if (!entityVisible[mesh.entity]) continue;
        glm::vec3 lo, hi;
        worldBounds(entityTransforms[mesh.entity], mesh.boundsMin, mesh.boundsMax, lo, hi);
        const uint32_t primary = entityPrimary[mesh.entity];
        const uint32_t material = std::min(mesh.material, materialCount - 1);
        const glm::vec3 toCentre = 0.5f * (lo + hi) - camera.position;
        draws.push_back({keyOf(material), material, mesh.firstIndex, mesh.indexCount,
                         mesh.vertexOffset, primary, kNoIndex, mesh.entity,
                         glm::dot(toCentre, toCentre)});
        if (primary != kNoIndex) visibleLights.push_back(primary);
        ++stats.dynamicMeshesDrawn;
    }
    std::sort(visibleLights.begin(), visibleLights.end());
    visibleLights.erase(std::unique(visibleLights.begin(), visibleLights.end()),
                        visibleLights.end());
    std::stable_sort(draws.begin(), draws.end(), [](const Draw& a, const Draw& b) {
        return a.key != b.key ? a.key < b.key : a.distance2 < b.distance2;
    });
    if (s.options.flatShading) visibleLights.clear();

    // Frame uniforms.
    FrameUniforms u{};
    u.viewProj = viewProj;
    u.cameraPosition = glm::vec4(camera.position, stats.exposure);
    u.shadowParams = glm::vec4(s.options.shadowRadius, s.options.shadowBand,
                               1.0f / float(s.options.shadowMapSize), 0.0f);
    u.baked = glm::vec4(s.ambientLux, s.lightmapDecode, 0.0f, 0.0f);
    u.probeParams = glm::vec4(float(s.probeMips), 0.0f, 0.0f, 0.0f);
    const EffectLights& fx = inputs.effects;
    u.counts =
        glm::uvec4(std::min(fx.omniCount, kMaxEffectOmnis), fx.spotOn ? 1u : 0u, s.probeCount, 0u);
    for (uint32_t i = 0; i < u.counts.x; ++i) {
        u.omniPositionRange[i] = glm::vec4(fx.omni[i].position, fx.omni[i].range);
        u.omniColor[i] = glm::vec4(fx.omni[i].color * fx.omni[i].intensity, 0.0f);
    }
    u.spotPositionRange = glm::vec4(fx.spot.position, fx.spot.range);
    u.spotDirection = glm::vec4(glm::normalize(fx.spot.direction), 0.0f);
    u.spotColor = glm::vec4(fx.spot.color * fx.spot.intensity, 0.0f);
    u.spotCones = glm::vec4(std::cos(fx.spot.innerCone), std::cos(fx.spot.outerCone), 0.0f, 0.0f);
    std::memcpy(s.frameBuffer.mapped, &u, sizeof(u));
    updateShadowViews(s, camera, visibleLights);

    // Record.
    VkCommandBuffer cmd = s.cmd;
    VK_CHECK(vkResetCommandBuffer(cmd, 0));
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
    if (s.timestamps) {
        vkCmdResetQueryPool(cmd, s.queries, 0, 4);
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, s.queries, 0);
    }
    stats.shadowViewsRendered = recordShadowPasses(s, cmd, visibleLights, entityTransforms);
    if (s.timestamps) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, s.queries, 1);

    // Forward pass.
    const VkPipelineStageFlags colorStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    const VkPipelineStageFlags depthStages =
        VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    vk::imageBarrier(
        cmd, s.hdr,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                          colorStage, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT));
    if (s.msaaColor.image)
        vk::imageBarrier(
            cmd, s.msaaColor,
            vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                              colorStage, 0, colorStage, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT));
    vk::imageBarrier(
        cmd, s.depth,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                          depthStages, 0, depthStages,
                          VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                              VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT));
    beginColorRendering(cmd, s, stats.exposure);
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &s.vertices.buffer, &zero);
    vkCmdBindIndexBuffer(cmd, s.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, s.forwardLayout.layout, 0, 1,
                            &s.frameSet, 0, nullptr);
    uint32_t boundKey = kNoIndex, boundMaterial = kNoIndex;
    for (const Draw& d : draws) {
        if (d.key != boundKey) {
            vkCmdBindPipeline(
                cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                s.options.flatShading ? s.flatPipeline : s.forwardPipelines.at(d.key));
            boundKey = d.key;
        }
        if (d.material != boundMaterial) {
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, s.forwardLayout.layout, 1,
                                    1, &s.materialSets[d.material], 0, nullptr);
            boundMaterial = d.material;
        }
        DrawPush push{};
        push.model = d.entity == kNoIndex ? glm::mat4(1.0f) : entityTransforms[d.entity];
        push.material = d.material;
        push.primaryLight = d.primaryLight;
        push.lightmapAtlas = d.atlas;
        push.objectLighting = d.entity;
        push.lightmapScale = glm::vec4(1.0f);
        if (d.atlas < s.atlasUvScale.size())
            push.lightmapScale = glm::vec4(s.atlasUvScale[d.atlas], 0.0f, 0.0f);
        vkCmdPushConstants(cmd, s.forwardLayout.layout,
                           VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof(push), &push);
        vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, d.vertexOffset, 0);
        stats.trianglesDrawn += d.indexCount / 3;
    }
    vkCmdEndRendering(cmd);
    if (s.timestamps) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, s.queries, 2);

    // Tonemap pass.
    vk::imageBarrier(
        cmd, s.hdr,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, colorStage,
                          VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                          VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT));
    vk::imageBarrier(
        cmd, s.display,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, 0, colorStage,
                          VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT));
    {
        VkRenderingAttachmentInfo color{};
        color.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
        color.imageView = s.display.view;
        color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        beginFrameRendering(cmd, s, color, nullptr);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, s.tonemapPipeline);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, s.tonemapLayout.layout, 0, 1,
                                &s.tonemapSet, 0, nullptr);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
    }
    if (s.timestamps) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, s.queries, 3);

    // Outputs.
    vk::imageBarrier(
        cmd, s.display,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, colorStage,
                          VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_READ_BIT));
    if (output.readback) {
        vk::imageBarrier(
            cmd, s.hdr,
            vk::layoutBarrier(VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                              VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0,
                              VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT));
        copyImageToBuffer(cmd, s.hdr.image, s.width, s.height, s.readbackHdr);
        copyImageToBuffer(cmd, s.display.image, s.width, s.height, s.readbackDisplay);
    }
    VkImage swapImage = VK_NULL_HANDLE;
    uint32_t swapWidth = 0, swapHeight = 0;
    if (output.swapchain) {
        swapImage = output.swapchain->images.at(output.swapchainImage);
        swapWidth = std::min(output.swapchain->extent.width, s.width);
        swapHeight = std::min(output.swapchain->extent.height, s.height);
        vk::imageBarrier(
            cmd, swapImage, VK_IMAGE_ASPECT_COLOR_BIT,
            vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                              VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                              VK_ACCESS_TRANSFER_WRITE_BIT));
        VkImageCopy copy{};
        copy.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.dstSubresource = copy.srcSubresource;
        copy.extent = {swapWidth, swapHeight, 1};
        vkCmdCopyImage(cmd, s.display.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, swapImage,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
        VkImageLayout layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        if (output.readbackSwapchain) {
            const VkDeviceSize bytes = VkDeviceSize(swapWidth) * swapHeight * 4;
            if (s.readbackSwapchain.size != bytes) {
                vk::destroyBuffer(ctx, s.readbackSwapchain);
                vk::createHostBuffer(ctx, s.readbackSwapchain, bytes,
                                     VK_BUFFER_USAGE_TRANSFER_DST_BIT);
            }
            vk::imageBarrier(
                cmd, swapImage, VK_IMAGE_ASPECT_COLOR_BIT,
                vk::layoutBarrier(layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                  VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                                  VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT));
            layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
            copyImageToBuffer(cmd, swapImage, swapWidth, swapHeight, s.readbackSwapchain);
        }
        vk::imageBarrier(
            cmd, swapImage, VK_IMAGE_ASPECT_COLOR_BIT,
            vk::layoutBarrier(layout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                              VK_PIPELINE_STAGE_TRANSFER_BIT,
                              VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT,
                              VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0));
    }
    VK_CHECK(vkEndCommandBuffer(cmd));

    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    if (output.swapchain) {
        submit.waitSemaphoreCount = 1;
        submit.pWaitSemaphores = &output.swapchain->imageAcquired;
        submit.pWaitDstStageMask = &waitStage;
        submit.signalSemaphoreCount = 1;
        submit.pSignalSemaphores = &output.swapchain->frameCopied;
    }
    VK_CHECK(vkResetFences(ctx.device, 1, &s.fence));
    VK_CHECK(vkQueueSubmit(ctx.queue, 1, &submit, s.fence));
    VK_CHECK(vkWaitForFences(ctx.device, 1, &s.fence, VK_TRUE, 120'000'000'000ull));

    if (s.timestamps) {
        uint64_t t[4] = {};
        VK_CHECK(vkGetQueryPoolResults(ctx.device, s.queries, 0, 4, sizeof(t), t, sizeof(uint64_t),
                                       VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
        const double toMs = double(ctx.properties.limits.timestampPeriod) * 1e-6;
        stats.gpuTimestamps = true;
        stats.gpuShadowMs = double(t[1] - t[0]) * toMs;
        stats.gpuForwardMs = double(t[2] - t[1]) * toMs;
        stats.gpuTonemapMs = double(t[3] - t[2]) * toMs;
        stats.gpuMs = double(t[3] - t[0]) * toMs;
    }
    if (output.readback) {
        CapturedFrame& c = s.captured;
        c.width = s.width;
        c.height = s.height;
        const size_t pixels = size_t(s.width) * s.height;
        bgraToRgba(static_cast<const uint8_t*>(s.readbackDisplay.mapped), pixels, c.rgba8);
        c.linearRgba.resize(pixels * 4);
        const auto* halves = static_cast<const uint16_t*>(s.readbackHdr.mapped);
        const float unexpose = 1.0f / stats.exposure;
        for (size_t i = 0; i < pixels * 4; ++i)
            c.linearRgba[i] = (i % 4 == 3) ? 1.0f : glm::unpackHalf1x16(halves[i]) * unexpose;
    }
    if (output.swapchain && output.readbackSwapchain)
        bgraToRgba(static_cast<const uint8_t*>(s.readbackSwapchain.mapped),
                   size_t(swapWidth) * swapHeight, s.captured.swapchainRgba8);
    stats.cpuMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpuStart)
            .count();
    return stats;
}

}  // namespace onelight::render
