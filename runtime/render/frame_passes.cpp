// Recording a frame after its shadow passes: the forward pass (MSAA, HDR, resolved), the tonemap
// pass, the copies out (readback, swapchain), and the readback itself once the frame is done.
#include "render/frame_passes.hpp"

#include <algorithm>

#include <glm/gtc/packing.hpp>

#include "vk/commands.hpp"
#include "vk/rendering.hpp"

namespace onelight::render {

namespace {

constexpr VkPipelineStageFlags kColorStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkPipelineStageFlags kDepthStages =
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;

VkExtent2D extentOf(const RenderTargets& targets) {
    return {targets.width, targets.height};
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

// The targets of the forward pass, whatever the previous frame left in them, ready to be drawn.
void prepareForwardTargets(const RenderTargets& targets, VkCommandBuffer cmd) {
    vk::imageBarrier(
        cmd, targets.hdr,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                          kColorStage, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT));
    if (targets.msaaColor.image)
        vk::imageBarrier(
            cmd, targets.msaaColor,
            vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                              kColorStage, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, kColorStage,
                              VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT));
    vk::imageBarrier(
        cmd, targets.depth,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                          kDepthStages, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, kDepthStages,
                          VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                              VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT));
}

// Dynamic rendering into the HDR target (through the MSAA target when multisampled) over a clear
// to the level's uniform sky (pre-exposed radiance, as the pass writes; black under a sky image,
// which the sky pass draws), with depth.
void beginForwardRendering(const Scene& scene, const RenderTargets& targets, VkCommandBuffer cmd,
                           float exposure) {
    const glm::vec3 sky = scene.sky.present ? glm::vec3(0.0f)
                                            : glm::min(scene.level.settings.skyRadiance * exposure,
                                                       glm::vec3(glsl::HDR_MAX));
    const VkClearColorValue clear{{sky.r, sky.g, sky.b, 1.0f}};
    const VkRenderingAttachmentInfo color =
        targets.samples != VK_SAMPLE_COUNT_1_BIT
            ? vk::resolvedColorAttachment(targets.msaaColor.view, targets.hdr.view,
                                          VK_ATTACHMENT_LOAD_OP_CLEAR, clear)
            : vk::colorAttachment(targets.hdr.view, VK_ATTACHMENT_LOAD_OP_CLEAR,
                                  VK_ATTACHMENT_STORE_OP_STORE, clear);
    const VkRenderingAttachmentInfo depth = vk::depthAttachment(
        targets.depth.view, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_DONT_CARE);
    vk::beginRendering(cmd, extentOf(targets), &color, &depth);
}

// A full-screen triangle of `pipeline` (with its one set) into `target`, whatever was in it.
void fullscreenPass(VkCommandBuffer cmd, const RenderTargets& targets, const vk::Image& target,
                    VkPipeline pipeline, VkPipelineLayout layout, VkDescriptorSet set) {
    vk::imageBarrier(
        cmd, target,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0,
                          kColorStage, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT));
    const VkRenderingAttachmentInfo color = vk::colorAttachment(
        target.view, VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_STORE);
    vk::beginRendering(cmd, extentOf(targets), &color, nullptr);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0, nullptr);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

// The sky pass, after the opaque draws: only the pixels they left at the far plane run it.
void recordSky(VkCommandBuffer cmd, const Pipelines& pipelines) {
    if (!pipelines.sky) return;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.sky);
    vkCmdDraw(cmd, 3, 1, 0, 0);
}

DrawPush drawPushOf(const std::vector<glm::vec2>& atlasUvScale,
                    const std::vector<uint32_t>& primaryRecord, const FrameView& view,
                    const Draw& d) {
    DrawPush push{};
    push.model = d.entity == kNoIndex ? glm::mat4(1.0f) : view.entityTransforms[d.entity];
    push.material = d.material % glsl::MAX_MATERIAL_RECORDS;  // in its page
    push.primaryLight =
        d.primaryLight < primaryRecord.size() ? primaryRecord[d.primaryLight] : kNoIndex;
    push.fadeLight = d.fadeLight < primaryRecord.size() ? primaryRecord[d.fadeLight] : kNoIndex;
    push.primaryWeight = push.fadeLight != kNoIndex ? d.primaryWeight : 1.0f;
    push.lightmapAtlas = d.atlas;
    push.objectLighting = d.entity;
    push.lightmapScale = glm::vec4(1.0f);
    if (d.atlas < atlasUvScale.size())
        push.lightmapScale = glm::vec4(atlasUvScale[d.atlas], 0.0f, 0.0f);
    return push;
}

}  // namespace

void recordForwardPass(VkCommandBuffer cmd, const Scene& scene, const RenderTargets& targets,
                       const Pipelines& pipelines, const DescriptorSets& sets, uint32_t slot,
                       const std::vector<uint32_t>& primaryRecord, const FrameView& view,
                       const DrawList& list, FrameStats& stats) {
    const std::vector<glm::vec2>& atlasUvScale = scene.baked.atlasUvScale;
    const VkPipelineLayout layout = pipelines.forwardLayout.layout;
    prepareForwardTargets(targets, cmd);
    beginForwardRendering(scene, targets, cmd, view.exposure);
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &scene.geometry.vertices.buffer, &zero);
    vkCmdBindIndexBuffer(cmd, scene.geometry.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    // Set 0 with the page of material records the draw's material is in (one page but for a
    // level of more than MAX_MATERIAL_RECORDS materials).
    uint32_t boundPage = kNoIndex;
    auto bindFrameSet = [&](uint32_t material) {
        const uint32_t page = material / glsl::MAX_MATERIAL_RECORDS;
        if (page == boundPage) return;
        const uint32_t offset = uint32_t(page * scene.materials.pageBytes);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1,
                                &sets.frame[slot], 1, &offset);
        stats.frameSetBinds += boundPage != kNoIndex ? 1 : 0;
        boundPage = page;
    };
    bindFrameSet(0);
    if (pipelines.depth[0] != VK_NULL_HANDLE) {
        int bound = -1;
        for (const Draw& d : list.draws) {
            // A masked draw's coverage comes from the fragment shader; a blended one hides nothing.
            if (keyAlphaMask(d.key) || keyAlphaBlend(d.key)) continue;
            const int doubleSided = keyDoubleSided(d.key) ? 1 : 0;
            if (doubleSided != bound) {
                vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                                  pipelines.depth[doubleSided]);
                bound = doubleSided;
            }
            const DrawPush push = drawPushOf(atlasUvScale, primaryRecord, view, d);
            vkCmdPushConstants(cmd, layout,
                               VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                               sizeof(push), &push);
            vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, d.vertexOffset, 0);
        }
    }
    uint32_t boundKey = kNoIndex, boundMaterial = kNoIndex;
    bool skyDrawn = false;
    for (const Draw& d : list.draws) {
        // The sky before the blended draws (the last, back to front), which go over it.
        if (!skyDrawn && keyAlphaBlend(d.key)) {
            recordSky(cmd, pipelines);
            skyDrawn = true;
            boundKey = kNoIndex;
        }
        if (d.key != boundKey) {
            // The flat pipeline exists only with flat shading, and then draws everything.
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                              pipelines.flat ? pipelines.flat : pipelines.forward.at(d.key));
            boundKey = d.key;
            ++stats.pipelineBinds;
        }
        if (d.material != boundMaterial) {
            bindFrameSet(d.material);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 1, 1,
                                    &sets.material[d.material], 0, nullptr);
            boundMaterial = d.material;
            ++stats.materialBinds;
        }
        const DrawPush push = drawPushOf(atlasUvScale, primaryRecord, view, d);
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                           0, sizeof(push), &push);
        vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, d.vertexOffset, 0);
        stats.trianglesDrawn += d.indexCount / 3;
    }
    if (!skyDrawn) recordSky(cmd, pipelines);
    vkCmdEndRendering(cmd);
}

void recordTonemapPass(VkCommandBuffer cmd, const RenderTargets& targets,
                       const Pipelines& pipelines, const DescriptorSets& sets) {
    vk::imageBarrier(
        cmd, targets.hdr,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kColorStage,
                          VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                          VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT));
    // With FXAA the tonemap writes its input, and the FXAA pass the display image.
    const bool fxaa = pipelines.fxaa && targets.tonemapped.image;
    fullscreenPass(cmd, targets, fxaa ? targets.tonemapped : targets.display, pipelines.tonemap,
                   pipelines.tonemapLayout.layout, sets.tonemap);
    if (!fxaa) return;
    vk::imageBarrier(
        cmd, targets.tonemapped,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kColorStage,
                          VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                          VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT));
    fullscreenPass(cmd, targets, targets.display, pipelines.fxaa, pipelines.fxaaLayout.layout,
                   sets.fxaa);
}

void recordOutputs(const vk::Context& ctx, VkCommandBuffer cmd, const RenderTargets& targets,
                   FrameReadback& readback, const FrameOutput& output) {
    vk::imageBarrier(
        cmd, targets.display,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kColorStage,
                          VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_READ_BIT));
    if (output.readback) {
        vk::imageBarrier(
            cmd, targets.hdr,
            vk::layoutBarrier(VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                              VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0,
                              VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT));
        vk::copyImageToHost(cmd, targets.hdr.image, targets.width, targets.height, readback.hdr);
        vk::copyImageToHost(cmd, targets.display.image, targets.width, targets.height,
                            readback.display);
    }
    if (!output.swapchain) return;
    const VkImage swapImage = output.swapchain->images.at(output.swapchainImage);
    const uint32_t width = output.swapchain->extent.width;
    const uint32_t height = output.swapchain->extent.height;
    vk::imageBarrier(
        cmd, swapImage, VK_IMAGE_ASPECT_COLOR_BIT,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_WRITE_BIT));
    if (width == targets.width && height == targets.height) {
        vk::copyImage(cmd, targets.display.image, swapImage, VK_IMAGE_ASPECT_COLOR_BIT, width,
                      height);
    } else {  // a render scale: the frame is smaller than the window
        vk::blitImage(cmd, targets.display.image, targets.width, targets.height, swapImage, width,
                      height);
    }
    VkImageLayout layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    if (output.readbackSwapchain) {
        const VkDeviceSize bytes = VkDeviceSize(width) * height * 4;
        if (readback.swapchain.size != bytes) {
            vk::destroyBuffer(ctx, readback.swapchain);
            vk::createHostBuffer(ctx, readback.swapchain, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        }
        vk::imageBarrier(
            cmd, swapImage, VK_IMAGE_ASPECT_COLOR_BIT,
            vk::layoutBarrier(layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                              VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT));
        layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        vk::copyImageToHost(cmd, swapImage, width, height, readback.swapchain);
    }
    vk::imageBarrier(
        cmd, swapImage, VK_IMAGE_ASPECT_COLOR_BIT,
        vk::layoutBarrier(layout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT,
                          VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0));
}

void readBackFrame(const RenderTargets& targets, FrameReadback& readback, const FrameOutput& output,
                   float exposure) {
    CapturedFrame& c = readback.captured;
    if (output.readback) {
        c.width = targets.width;
        c.height = targets.height;
        const size_t pixels = size_t(targets.width) * targets.height;
        bgraToRgba(static_cast<const uint8_t*>(readback.display.mapped), pixels, c.rgba8);
        c.linearRgba.resize(pixels * 4);
        const auto* halves = static_cast<const uint16_t*>(readback.hdr.mapped);
        const float unexpose = 1.0f / exposure;
        for (size_t i = 0; i < pixels * 4; ++i)
            c.linearRgba[i] = (i % 4 == 3) ? 1.0f : glm::unpackHalf1x16(halves[i]) * unexpose;
    }
    if (output.swapchain && output.readbackSwapchain)
        bgraToRgba(static_cast<const uint8_t*>(readback.swapchain.mapped),
                   size_t(readback.swapchain.size / 4), c.swapchainRgba8);
}

}  // namespace onelight::render
