// The frame's render targets and the host buffers a readback copies into (targets.cpp),
// recreated when the frame's size changes.
#pragma once

#include <cstdint>

#include "render/renderer.hpp"
#include "vk/buffer.hpp"
#include "vk/context.hpp"
#include "vk/image.hpp"

namespace onelight::render {

inline constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
inline constexpr VkFormat kDisplayFormat = VK_FORMAT_B8G8R8A8_UNORM;  // as the swapchain

/// The supported sample count nearest to `requested` (in powers of two; ties go up).
[[nodiscard]] VkSampleCountFlagBits pickSamples(const vk::Context& ctx, uint32_t requested);

/// The forward pass's targets (MSAA colour and depth, resolved into hdr) and the tonemap's.
struct RenderTargets {
    uint32_t width = 0, height = 0;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    vk::Image msaaColor;   // owned, only when samples > 1
    vk::Image depth;       // owned
    vk::Image hdr;         // owned, RGBA16F, the forward pass's output, the tonemap's input
    vk::Image display;     // owned, B8G8R8A8, the tonemap's output (with FXAA, the FXAA pass's)
    vk::Image tonemapped;  // owned, B8G8R8A8, with FXAA only: the tonemap's output, its input
};

/// The targets for `samples` per pixel, and the FXAA pass's input when `fxaa`.
void createTargets(const vk::Context& ctx, RenderTargets& targets, uint32_t width, uint32_t height,
                   VkSampleCountFlagBits samples, bool fxaa);
void destroyTargets(const vk::Context& ctx, RenderTargets& targets);

/// Host buffers the frame is copied into when read back, and the last frame read back.
struct FrameReadback {
    vk::Buffer hdr;        // owned, the targets' size, RGBA16F
    vk::Buffer display;    // owned, the targets' size, B8G8R8A8
    vk::Buffer swapchain;  // owned, created at the first swapchain readback, its image's size
    CapturedFrame captured;
};

void createReadback(const vk::Context& ctx, FrameReadback& readback, uint32_t width,
                    uint32_t height);
void destroyReadback(const vk::Context& ctx, FrameReadback& readback);

}  // namespace onelight::render
