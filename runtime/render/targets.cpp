// The frame's render targets: the MSAA colour and depth, the resolved HDR image, the display
// image the tonemap writes, and the host buffers a readback copies into.
#include <algorithm>
#include <cmath>

#include "render/renderer_state.hpp"

namespace onelight::render {

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

}  // namespace onelight::render
