// Recording a frame after its shadow passes: the forward pass (MSAA, HDR, resolved), the tonemap
// pass, the copies out (readback, swapchain), and the readback itself once the frame is done.
#include <algorithm>

#include <glm/gtc/packing.hpp>

#include "render/renderer_state.hpp"
#include "vk/commands.hpp"
#include "vk/rendering.hpp"

namespace onelight::render {

namespace {

constexpr VkPipelineStageFlags kColorStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkPipelineStageFlags kDepthStages =
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;

VkExtent2D extentOf(const RendererState& s) {
    return {s.width, s.height};
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
void prepareForwardTargets(const RendererState& s, VkCommandBuffer cmd) {
    vk::imageBarrier(
        cmd, s.hdr,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                          kColorStage, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT));
    if (s.msaaColor.image)
        vk::imageBarrier(
            cmd, s.msaaColor,
            vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                              kColorStage, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, kColorStage,
                              VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT));
    vk::imageBarrier(
        cmd, s.depth,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                          kDepthStages, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, kDepthStages,
                          VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                              VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT));
}

// Dynamic rendering into the HDR target (through the MSAA target when multisampled) over a clear
// to the level's uniform sky (pre-exposed radiance, as the pass writes; black under a sky image,
// which the sky pass draws), with depth.
void beginForwardRendering(const RendererState& s, VkCommandBuffer cmd, float exposure) {
    const glm::vec3 sky =
        s.skyImage ? glm::vec3(0.0f)
                   : glm::min(s.settings.skyRadiance * exposure, glm::vec3(glsl::HDR_MAX));
    const VkClearColorValue clear{{sky.r, sky.g, sky.b, 1.0f}};
    const VkRenderingAttachmentInfo color =
        s.samples != VK_SAMPLE_COUNT_1_BIT
            ? vk::resolvedColorAttachment(s.msaaColor.view, s.hdr.view, VK_ATTACHMENT_LOAD_OP_CLEAR,
                                          clear)
            : vk::colorAttachment(s.hdr.view, VK_ATTACHMENT_LOAD_OP_CLEAR,
                                  VK_ATTACHMENT_STORE_OP_STORE, clear);
    const VkRenderingAttachmentInfo depth = vk::depthAttachment(
        s.depth.view, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_DONT_CARE);
    vk::beginRendering(cmd, extentOf(s), &color, &depth);
}

DrawPush drawPushOf(const RendererState& s, const FrameView& view, const Draw& d) {
    DrawPush push{};
    push.model = d.entity == kNoIndex ? glm::mat4(1.0f) : view.entityTransforms[d.entity];
    push.material = d.material;
    push.primaryLight = d.primaryLight;
    push.lightmapAtlas = d.atlas;
    push.objectLighting = d.entity;
    push.lightmapScale = glm::vec4(1.0f);
    if (d.atlas < s.atlasUvScale.size())
        push.lightmapScale = glm::vec4(s.atlasUvScale[d.atlas], 0.0f, 0.0f);
    return push;
}

}  // namespace

void recordForwardPass(RendererState& s, VkCommandBuffer cmd, const FrameSlot& slot,
                       const FrameView& view, const DrawList& list, FrameStats& stats) {
    prepareForwardTargets(s, cmd);
    beginForwardRendering(s, cmd, view.exposure);
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &s.vertices.buffer, &zero);
    vkCmdBindIndexBuffer(cmd, s.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, s.forwardLayout.layout, 0, 1,
                            &slot.frameSet, 0, nullptr);
    if (s.depthPipelines[0] != VK_NULL_HANDLE) {
        int bound = -1;
        for (const Draw& d : list.draws) {
            if (keyAlphaMask(d.key)) continue;  // its coverage comes from the fragment shader
            const int doubleSided = keyDoubleSided(d.key) ? 1 : 0;
            if (doubleSided != bound) {
                vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                                  s.depthPipelines[doubleSided]);
                bound = doubleSided;
            }
            const DrawPush push = drawPushOf(s, view, d);
            vkCmdPushConstants(cmd, s.forwardLayout.layout,
                               VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                               sizeof(push), &push);
            vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, d.vertexOffset, 0);
        }
    }
    uint32_t boundKey = kNoIndex, boundMaterial = kNoIndex;
    for (const Draw& d : list.draws) {
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
        const DrawPush push = drawPushOf(s, view, d);
        vkCmdPushConstants(cmd, s.forwardLayout.layout,
                           VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof(push), &push);
        vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, d.vertexOffset, 0);
        stats.trianglesDrawn += d.indexCount / 3;
    }
    if (s.skyPipeline) {  // last: only the pixels the level left at the far plane run it
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, s.skyPipeline);
        vkCmdDraw(cmd, 3, 1, 0, 0);
    }
    vkCmdEndRendering(cmd);
}

void recordTonemapPass(RendererState& s, VkCommandBuffer cmd) {
    vk::imageBarrier(
        cmd, s.hdr,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kColorStage,
                          VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                          VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT));
    vk::imageBarrier(
        cmd, s.display,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, 0, kColorStage,
                          VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT));
    const VkRenderingAttachmentInfo color = vk::colorAttachment(
        s.display.view, VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_STORE);
    vk::beginRendering(cmd, extentOf(s), &color, nullptr);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, s.tonemapPipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, s.tonemapLayout.layout, 0, 1,
                            &s.tonemapSet, 0, nullptr);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

void recordOutputs(RendererState& s, VkCommandBuffer cmd, const FrameOutput& output) {
    const vk::Context& ctx = *s.ctx;
    vk::imageBarrier(
        cmd, s.display,
        vk::layoutBarrier(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kColorStage,
                          VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_READ_BIT));
    if (output.readback) {
        vk::imageBarrier(
            cmd, s.hdr,
            vk::layoutBarrier(VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                              VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0,
                              VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT));
        vk::copyImageToHost(cmd, s.hdr.image, s.width, s.height, s.readbackHdr);
        vk::copyImageToHost(cmd, s.display.image, s.width, s.height, s.readbackDisplay);
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
    if (width == s.width && height == s.height) {
        vk::copyImage(cmd, s.display.image, swapImage, VK_IMAGE_ASPECT_COLOR_BIT, width, height);
    } else {  // a render scale: the frame is smaller than the window
        vk::blitImage(cmd, s.display.image, s.width, s.height, swapImage, width, height);
    }
    VkImageLayout layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    if (output.readbackSwapchain) {
        const VkDeviceSize bytes = VkDeviceSize(width) * height * 4;
        if (s.readbackSwapchain.size != bytes) {
            vk::destroyBuffer(ctx, s.readbackSwapchain);
            vk::createHostBuffer(ctx, s.readbackSwapchain, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        }
        vk::imageBarrier(
            cmd, swapImage, VK_IMAGE_ASPECT_COLOR_BIT,
            vk::layoutBarrier(layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                              VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT));
        layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        vk::copyImageToHost(cmd, swapImage, width, height, s.readbackSwapchain);
    }
    vk::imageBarrier(
        cmd, swapImage, VK_IMAGE_ASPECT_COLOR_BIT,
        vk::layoutBarrier(layout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT,
                          VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0));
}

void readBackFrame(RendererState& s, const FrameOutput& output, float exposure) {
    CapturedFrame& c = s.captured;
    if (output.readback) {
        c.width = s.width;
        c.height = s.height;
        const size_t pixels = size_t(s.width) * s.height;
        bgraToRgba(static_cast<const uint8_t*>(s.readbackDisplay.mapped), pixels, c.rgba8);
        c.linearRgba.resize(pixels * 4);
        const auto* halves = static_cast<const uint16_t*>(s.readbackHdr.mapped);
        const float unexpose = 1.0f / exposure;
        for (size_t i = 0; i < pixels * 4; ++i)
            c.linearRgba[i] = (i % 4 == 3) ? 1.0f : glm::unpackHalf1x16(halves[i]) * unexpose;
    }
    if (output.swapchain && output.readbackSwapchain)
        bgraToRgba(static_cast<const uint8_t*>(s.readbackSwapchain.mapped),
                   size_t(s.readbackSwapchain.size / 4), c.swapchainRgba8);
}

}  // namespace onelight::render
