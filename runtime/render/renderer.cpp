// The renderer's life (create, resize, destroy) and its frame: kFramesInFlight frame slots used
// in turn, each frame worked out on the CPU (frame_view.cpp), recorded pass by pass (shadows.cpp,
// frame_passes.cpp) and submitted without waiting, unless its output must be read back.
#include "render/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <vector>

#include "render/renderer_state.hpp"
#include "vk/commands.hpp"
#include "vk/timestamps.hpp"
#include "vk/vk_check.hpp"

namespace onelight::render {

namespace {

void createFrameSlots(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    s.timestamps = vk::timestampsSupported(ctx);
    const size_t entities = std::max<size_t>(s.entities.size(), 1);
    for (FrameSlot& slot : s.frames) {
        slot.cmd = vk::allocateCommandBuffer(ctx);
        slot.done = vk::createFence(ctx);
        if (s.timestamps) slot.timestamps = vk::createTimestampPool(ctx, kTimestampCount);
        vk::createHostBuffer(ctx, slot.uniforms, sizeof(FrameUniforms),
                             VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        vk::createHostBuffer(ctx, slot.shadowViews, s.views.size() * sizeof(GpuShadowView),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        vk::createHostBuffer(ctx, slot.objectLighting, entities * sizeof(GpuObjectLighting),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        std::memset(slot.shadowViews.mapped, 0, slot.shadowViews.size);
        std::memset(slot.objectLighting.mapped, 0, slot.objectLighting.size);
    }
}

void destroyFrameSlots(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    for (FrameSlot& slot : s.frames) {
        vk::destroyBuffer(ctx, slot.objectLighting);
        vk::destroyBuffer(ctx, slot.shadowViews);
        vk::destroyBuffer(ctx, slot.uniforms);
        if (slot.timestamps) vkDestroyQueryPool(ctx.device, slot.timestamps, nullptr);
        if (slot.done) vkDestroyFence(ctx.device, slot.done, nullptr);
        if (slot.cmd) vkFreeCommandBuffers(ctx.device, ctx.commandPool, 1, &slot.cmd);
        slot.cmd = VK_NULL_HANDLE;
        slot.done = VK_NULL_HANDLE;
        slot.timestamps = VK_NULL_HANDLE;
        slot.pending = false;
    }
}

// Waits for the slot's last frame, if one is pending, and reports its GPU times in `stats`.
void finishFrame(RendererState& s, FrameSlot& slot, FrameStats& stats) {
    if (!slot.pending) return;
    vk::waitForFence(*s.ctx, slot.done, "drawFrame");
    slot.pending = false;
    if (!s.timestamps) return;
    const std::vector<double> t = vk::readTimestampsMs(*s.ctx, slot.timestamps, kTimestampCount);
    stats.gpuTimestamps = true;
    stats.gpuFrame = slot.frame;
    stats.gpuShadowMs = t[1] - t[0];
    stats.gpuForwardMs = t[2] - t[1];
    stats.gpuTonemapMs = t[3] - t[2];
    stats.gpuMs = t[3];
}

void writeTimestamp(const RendererState& s, VkCommandBuffer cmd, const FrameSlot& slot,
                    uint32_t index) {
    if (!s.timestamps) return;
    if (index == 0) vkCmdResetQueryPool(cmd, slot.timestamps, 0, kTimestampCount);
    vkCmdWriteTimestamp(
        cmd, index == 0 ? VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT : VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
        slot.timestamps, index);
}

// Records the whole frame into the slot's command buffer.
void recordFrame(RendererState& s, FrameSlot& slot, const FrameView& view, const DrawList& list,
                 const FrameOutput& output, FrameStats& stats) {
    const VkCommandBuffer cmd = slot.cmd;
    vk::beginOneTimeCommands(cmd);
    writeTimestamp(s, cmd, slot, 0);
    stats.shadowViewsRendered =
        recordShadowPasses(s, cmd, list.visibleLights, view.entityTransforms);
    writeTimestamp(s, cmd, slot, 1);
    recordForwardPass(s, cmd, slot, view, list, stats);
    writeTimestamp(s, cmd, slot, 2);
    recordTonemapPass(s, cmd);
    writeTimestamp(s, cmd, slot, 3);
    recordOutputs(s, cmd, output);
    VK_CHECK(vkEndCommandBuffer(cmd));
}

void submitFrame(RendererState& s, FrameSlot& slot, const FrameOutput& output) {
    vk::SubmitSync sync;
    sync.fence = slot.done;
    if (output.swapchain) {
        sync.wait = output.swapchain->imageAcquired.at(output.swapchainImage);
        sync.waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
        sync.signal = output.swapchain->frameCopied.at(output.swapchainImage);
    }
    vk::submitCommands(*s.ctx, slot.cmd, sync);
    slot.frame = s.framesSubmitted++;
    slot.pending = true;
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
    options.features.imageCubeArray = VK_TRUE;     // the probes' cube array
    options.features.depthBiasClamp = VK_TRUE;     // the sun shadow map's bias limit
    options.features.samplerAnisotropy = VK_TRUE;  // material textures at grazing view
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
        uploadScene(s, level);
        createShadows(s);
        uploadLights(s);
        createTargets(s);
        createFrameSlots(s);
        createPipelines(s);
    } catch (...) {
        destroyRenderer(renderer);
        throw;
    }
}

void destroyRenderer(Renderer& renderer) {
    if (!renderer.state) return;
    RendererState& s = *renderer.state;
    vkDeviceWaitIdle(s.ctx->device);
    destroyPipelines(s);
    destroyFrameSlots(s);
    destroyTargets(s);
    destroyShadows(s);
    destroyScene(s);
    renderer.state.reset();
}

const RendererInfo& rendererInfo(const Renderer& renderer) {
    return renderer.state->info;
}

const CapturedFrame& capturedFrame(const Renderer& renderer) {
    return renderer.state->captured;
}

uint32_t drawnPrimary(const Renderer& renderer, uint32_t entity) {
    const RendererState& s = *renderer.state;
    return entity < s.drawnPrimary.size() ? s.drawnPrimary[entity] : kNoIndex;
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

void waitForFrames(Renderer& renderer) {
    RendererState& s = *renderer.state;
    FrameStats ignored;
    for (FrameSlot& slot : s.frames) finishFrame(s, slot, ignored);
}

FrameStats drawFrame(Renderer& renderer, const FrameInputs& inputs, const FrameOutput& output) {
    RendererState& s = *renderer.state;
    const auto cpuStart = std::chrono::steady_clock::now();
    FrameStats stats;
    FrameSlot& slot = s.frames[s.framesSubmitted % kFramesInFlight];
    finishFrame(s, slot, stats);  // the frame kFramesInFlight ago: its buffers are free again

    const FrameView view = frameViewOf(s, inputs);
    stats.ev100 = view.ev100;
    stats.exposure = view.exposure;
    const DrawList list = buildDrawList(s, view, stats);
    writeObjectLighting(s, view, list, static_cast<GpuObjectLighting*>(slot.objectLighting.mapped));
    const FrameUniforms uniforms = frameUniformsOf(s, view, inputs.effects);
    std::memcpy(slot.uniforms.mapped, &uniforms, sizeof(uniforms));
    updateShadowViews(s, view.camera, list.visibleLights);
    writeShadowViews(s, static_cast<GpuShadowView*>(slot.shadowViews.mapped));
    s.drawnPrimary.assign(s.entities.size(), kNoIndex);
    for (const Draw& d : list.draws)
        if (d.entity != kNoIndex) s.drawnPrimary[d.entity] = d.primaryLight;

    recordFrame(s, slot, view, list, output, stats);
    submitFrame(s, slot, output);
    if (output.readback || output.wait || (output.swapchain && output.readbackSwapchain)) {
        finishFrame(s, slot, stats);
        readBackFrame(s, output, view.exposure);
    }
    stats.frame = slot.frame;
    stats.cpuMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpuStart)
            .count();
    return stats;
}

}  // namespace onelight::render
