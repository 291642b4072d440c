// The renderer's life (create, resize, destroy) and its frame: kFramesInFlight frame slots used
// in turn, each frame worked out on the CPU (frame_view.cpp), recorded pass by pass (shadows.cpp,
// frame_passes.cpp) and submitted without waiting, unless its output must be read back.
#include "render/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <vector>

#include "render/frame_passes.hpp"
#include "render/frame_slots.hpp"
#include "render/frame_view.hpp"
#include "render/pipelines.hpp"
#include "render/scene.hpp"
#include "render/shadows.hpp"
#include "render/targets.hpp"
#include "vk/commands.hpp"
#include "vk/vk_check.hpp"

namespace onelight::render {

/// The renderer's parts, each owned here, created in the order of the fields (createRenderer)
/// and destroyed in reverse (destroyRenderer). Each file takes only the parts it uses.
struct RendererState {
    vk::Context* ctx = nullptr;  // borrowed
    RendererOptions options;
    RendererInfo info;
    Scene scene;                    // the level on the CPU and the GPU, uploaded once
    ShadowMaps shadows;             // the shadow slots, views and maps
    PrimaryRecords primaryRecords;  // the primary lights', with their shadow views
    RenderTargets targets;          // recreated by resizeRenderer
    FrameReadback readback;         // recreated by resizeRenderer (the captured frame kept)
    FrameSlots frames;              // the frames in flight
    Pipelines pipelines;
    DescriptorSets descriptors;          // borrow every part above
    std::vector<uint32_t> drawnPrimary;  // per entity: the primary its last drawn frame used
};

namespace {

void writeTimestamp(const FrameSlots& frames, VkCommandBuffer cmd, const FrameSlot& slot,
                    uint32_t index) {
    if (!frames.timestamps) return;
    if (index == 0) vkCmdResetQueryPool(cmd, slot.timestamps, 0, kTimestampCount);
    vkCmdWriteTimestamp(
        cmd, index == 0 ? VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT : VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
        slot.timestamps, index);
}

// Records the whole frame into the slot's command buffer.
void recordFrame(RendererState& s, uint32_t slotIndex, const FrameView& view, const DrawList& list,
                 const FrameOutput& output, FrameStats& stats) {
    const FrameSlot& slot = s.frames.slots[slotIndex];
    const VkCommandBuffer cmd = slot.cmd;
    vk::beginOneTimeCommands(cmd);
    writeTimestamp(s.frames, cmd, slot, 0);
    stats.shadowViewsRendered = recordShadowPasses(
        s.shadows, cmd,
        {s.pipelines.shadow, s.pipelines.maskedShadow, s.pipelines.shadowLayout.layout,
         s.pipelines.maskedShadowLayout.layout, &s.scene.materials, &s.descriptors.material},
        s.scene.geometry, list.visibleLights, view.entityTransforms, view.entityHidden);
    writeTimestamp(s.frames, cmd, slot, 1);
    recordForwardPass(cmd, s.scene, s.targets, s.pipelines, s.descriptors, slotIndex,
                      s.primaryRecords.recordOf, view, list, stats);
    writeTimestamp(s.frames, cmd, slot, 2);
    recordTonemapPass(cmd, s.targets, s.pipelines, s.descriptors);
    writeTimestamp(s.frames, cmd, slot, 3);
    recordOutputs(*s.ctx, cmd, s.targets, s.readback, output);
    VK_CHECK(vkEndCommandBuffer(cmd));
}

void submitFrame(const vk::Context& ctx, FrameSlots& frames, FrameSlot& slot,
                 const FrameOutput& output) {
    vk::SubmitSync sync;
    sync.fence = slot.done;
    if (output.swapchain) {
        sync.wait = output.swapchain->imageAcquired.at(output.swapchainImage);
        sync.waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
        sync.signal = output.swapchain->frameCopied.at(output.swapchainImage);
    }
    vk::submitCommands(ctx, slot.cmd, sync);
    slot.frame = frames.submitted++;
    slot.pending = true;
}

// Records and submits the frame of `view` drawing `list` into the next frame slot.
FrameStats drawList(RendererState& s, const FrameInputs& inputs, const FrameOutput& output,
                    const FrameView& view, const DrawList& list, FrameStats stats,
                    std::chrono::steady_clock::time_point cpuStart) {
    const vk::Context& ctx = *s.ctx;
    const Scene& scene = s.scene;
    const uint32_t slotIndex = uint32_t(s.frames.submitted % kFramesInFlight);
    FrameSlot& slot = s.frames.slots[slotIndex];
    writeObjectLighting(scene.level, scene.baked, scene.geometry, view, list,
                        static_cast<GpuObjectLighting*>(slot.objectLighting.mapped));
    const FrameUniforms uniforms = frameUniformsOf(scene, s.options, view, inputs.effects);
    std::memcpy(slot.uniforms.mapped, &uniforms, sizeof(uniforms));
    updateShadowViews(s.shadows, scene.level, view.camera, list.visibleLights);
    writeShadowViews(s.shadows, static_cast<GpuShadowView*>(slot.shadowViews.mapped));
    s.drawnPrimary.assign(scene.level.entities.size(), kNoIndex);
    for (const Draw& d : list.draws)
        if (d.entity != kNoIndex) s.drawnPrimary[d.entity] = d.primaryLight;

    recordFrame(s, slotIndex, view, list, output, stats);
    submitFrame(ctx, s.frames, slot, output);
    if (output.readback || output.wait || (output.swapchain && output.readbackSwapchain)) {
        finishFrame(ctx, slot, s.frames.timestamps, stats);
        readBackFrame(s.targets, s.readback, output, view.exposure);
    }
    stats.frame = slot.frame;
    stats.cpuMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpuStart)
            .count();
    return stats;
}

// Draws one hidden frame (warmUpDrawList): every pipeline the level uses, once with each
// material's textures bound, waited for. A driver that compiles its shader variants at first
// draw (llvmpipe keys them by the pipeline and by the formats and samplers bound) does so here,
// in createRenderer, and not in the first frame the player sees.
void warmUp(RendererState& s) {
    const Scene& scene = s.scene;
    const auto cpuStart = std::chrono::steady_clock::now();
    // The shadow pipeline once: a spot's or omni's static casters stay cached (a sun's are
    // fitted again around the first frame's camera).
    uint32_t shadowed = kNoIndex;
    for (uint32_t light = 0; light < s.shadows.lightSlot.size(); ++light) {
        if (s.shadows.lightSlot[light] == kNoIndex) continue;
        const bool sun = scene.level.lights[light].type == world::LightType::kDirectional;
        if (shadowed == kNoIndex || !sun) shadowed = light;
        if (!sun) break;
    }
    const FrameInputs inputs;
    const FrameView view =
        frameViewOf(scene.level, float(s.targets.width) / float(s.targets.height), inputs);
    const DrawList list = warmUpDrawList(scene.geometry, scene.materials, s.options,
                                         scene.level.entities.size(), shadowed);
    FrameOutput output;
    output.wait = true;
    (void)drawList(s, inputs, output, view, list, FrameStats{}, cpuStart);
    s.info.warmUpMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpuStart)
            .count();
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
    const VkSampleCountFlagBits samples = pickSamples(ctx, options.requestedMsaa);
    s.info.deviceName = ctx.properties.deviceName;
    s.info.msaaRequested = options.requestedMsaa;
    s.info.msaaInUse = uint32_t(samples);
    try {
        createScene(ctx, s.scene, level, options);
        const Scene& scene = s.scene;
        s.info.ambientLux = scene.level.ambientLux;
        s.info.autoEv100 = scene.level.autoEv100;
        s.info.bakedLighting = scene.baked.present;
        s.info.lightmapDecode = scene.baked.lightmapDecode;
        s.info.probes = scene.probes.baked;
        s.info.probeBytes = scene.probes.bytes;
        s.info.skyImage = scene.sky.present;
        for (size_t i = 0; i < scene.geometry.surfaces.size(); ++i) {
            if (level.level.surfaces[i].primaryLight == kNoIndex) continue;
            ++s.info.surfacesWithPrimary;
            s.info.surfacesUnoccluded += scene.geometry.surfaces[i].unoccluded ? 1u : 0u;
            s.info.surfacesInShadow +=
                scene.geometry.surfaces[i].primaryLight == kNoIndex ? 1u : 0u;
        }
        s.drawnPrimary.assign(scene.level.entities.size(), kNoIndex);

        createShadows(ctx, s.shadows, scene.level, options, scene.geometry.dynamicCasters);
        s.info.shadowLayers = s.shadows.layers;
        createPrimaryRecords(ctx, s.primaryRecords, scene.level.lights,
                             lightShadowViews(s.shadows));
        createTargets(ctx, s.targets, std::max(options.width, 1u), std::max(options.height, 1u),
                      samples, options.fxaa);
        createReadback(ctx, s.readback, s.targets.width, s.targets.height);
        createFrameSlots(ctx, s.frames, scene.level.entities.size());
        ForwardChoices choices;
        choices.samples = samples;
        choices.fetchBakedLighting = scene.baked.present || options.samplePlaceholders;
        choices.diffuseModel = int(scene.level.settings.diffuseModel);
        choices.probes = scene.probes.baked > 0;
        choices.skyImage = scene.sky.present;
        createPipelines(ctx, s.pipelines, scene.geometry, scene.materials, options, choices);
        s.info.permutations = s.pipelines.permutations;
        createDescriptorSets(ctx, s.descriptors, s.pipelines, s.frames, scene, s.shadows,
                             s.primaryRecords.buffer, s.targets);
        if (options.warmUp) warmUp(s);
    } catch (...) {
        destroyRenderer(renderer);
        throw;
    }
}

void destroyRenderer(Renderer& renderer) {
    if (!renderer.state) return;
    RendererState& s = *renderer.state;
    const vk::Context& ctx = *s.ctx;
    vkDeviceWaitIdle(ctx.device);
    destroyDescriptorSets(ctx, s.descriptors);
    destroyPipelines(ctx, s.pipelines);
    destroyFrameSlots(ctx, s.frames);
    destroyReadback(ctx, s.readback);
    destroyTargets(ctx, s.targets);
    vk::destroyBuffer(ctx, s.primaryRecords.buffer);
    destroyShadows(ctx, s.shadows);
    destroyScene(ctx, s.scene);
    renderer.state.reset();
}

const RendererInfo& rendererInfo(const Renderer& renderer) {
    return renderer.state->info;
}

const CapturedFrame& capturedFrame(const Renderer& renderer) {
    return renderer.state->readback.captured;
}

uint32_t drawnPrimary(const Renderer& renderer, uint32_t entity) {
    const RendererState& s = *renderer.state;
    return entity < s.drawnPrimary.size() ? s.drawnPrimary[entity] : kNoIndex;
}

void resizeRenderer(Renderer& renderer, uint32_t width, uint32_t height) {
    RendererState& s = *renderer.state;
    if (width == s.targets.width && height == s.targets.height) return;
    const vk::Context& ctx = *s.ctx;
    VK_CHECK(vkDeviceWaitIdle(ctx.device));
    const VkSampleCountFlagBits samples = s.targets.samples;
    destroyReadback(ctx, s.readback);
    destroyTargets(ctx, s.targets);
    createTargets(ctx, s.targets, std::max(width, 1u), std::max(height, 1u), samples,
                  s.options.fxaa);
    createReadback(ctx, s.readback, s.targets.width, s.targets.height);
    writeTonemapSet(ctx, s.descriptors, s.targets, s.scene.tables);
}

void waitForFrames(Renderer& renderer) {
    RendererState& s = *renderer.state;
    FrameStats ignored;
    for (FrameSlot& slot : s.frames.slots) finishFrame(*s.ctx, slot, s.frames.timestamps, ignored);
}

FrameStats drawFrame(Renderer& renderer, const FrameInputs& inputs, const FrameOutput& output) {
    RendererState& s = *renderer.state;
    const Scene& scene = s.scene;
    const auto cpuStart = std::chrono::steady_clock::now();
    FrameStats stats;
    const uint32_t slotIndex = uint32_t(s.frames.submitted % kFramesInFlight);
    // The frame kFramesInFlight ago: its buffers are free again.
    finishFrame(*s.ctx, s.frames.slots[slotIndex], s.frames.timestamps, stats);

    const FrameView view =
        frameViewOf(scene.level, float(s.targets.width) / float(s.targets.height), inputs);
    stats.ev100 = view.ev100;
    stats.exposure = view.exposure;
    const DrawList list = buildDrawList(scene, s.options, view, stats);
    return drawList(s, inputs, output, view, list, stats, cpuStart);
}

}  // namespace onelight::render
