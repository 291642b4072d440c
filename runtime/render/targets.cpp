// The frame's render targets: the MSAA colour and depth, the resolved HDR image, the display
// image the tonemap writes, and the host buffers a readback copies into.
#include "render/targets.hpp"

#include <algorithm>
#include <cmath>

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

void createTargets(const vk::Context& ctx, RenderTargets& targets, uint32_t width, uint32_t height,
                   VkSampleCountFlagBits samples, bool fxaa) {
    targets.width = width;
    targets.height = height;
    targets.samples = samples;
    vk::ImageDesc desc;
    desc.width = width;
    desc.height = height;
    desc.format = kHdrFormat;
    desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                 VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    vk::createImage(ctx, targets.hdr, desc);
    desc.format = kDisplayFormat;
    desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    vk::createImage(ctx, targets.display, desc);
    if (fxaa) {
        desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
        vk::createImage(ctx, targets.tonemapped, desc);
    }
    desc.samples = samples;
    if (samples != VK_SAMPLE_COUNT_1_BIT) {
        desc.format = kHdrFormat;
        desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
        vk::createImage(ctx, targets.msaaColor, desc);
    }
    desc.format = kDepthFormat;
    desc.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    vk::createImage(ctx, targets.depth, desc);
}

void destroyTargets(const vk::Context& ctx, RenderTargets& targets) {
    vk::destroyImage(ctx, targets.depth);
    vk::destroyImage(ctx, targets.msaaColor);
    vk::destroyImage(ctx, targets.tonemapped);
    vk::destroyImage(ctx, targets.display);
    vk::destroyImage(ctx, targets.hdr);
}

void createReadback(const vk::Context& ctx, FrameReadback& readback, uint32_t width,
                    uint32_t height) {
    const VkDeviceSize pixels = VkDeviceSize(width) * height;
    vk::createHostBuffer(ctx, readback.hdr, pixels * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    vk::createHostBuffer(ctx, readback.display, pixels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
}

void destroyReadback(const vk::Context& ctx, FrameReadback& readback) {
    vk::destroyBuffer(ctx, readback.swapchain);
    vk::destroyBuffer(ctx, readback.display);
    vk::destroyBuffer(ctx, readback.hdr);
}

}  // namespace onelight::render
