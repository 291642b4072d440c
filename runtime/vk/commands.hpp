// Command buffers: a one-shot submit, and barrier helpers.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>

#include "vk/buffer.hpp"
#include "vk/context.hpp"

namespace onelight::vk {

// Records a primary command buffer from ctx.commandPool with `record`, submits it to ctx.queue
// and waits for it to finish (throws on VK_TIMEOUT after timeoutNs). For uploads, readbacks and
// tests, not for frames.
void submitOnce(const Context& ctx, const std::function<void(VkCommandBuffer)>& record,
                uint64_t timeoutNs = 60'000'000'000ull);

// A barrier on the whole of one buffer: accesses `srcAccess` by `srcStage` happen before, and are
// visible to, accesses `dstAccess` by `dstStage`. E.g. compute-shader writes before host reads:
// (COMPUTE_SHADER, SHADER_WRITE) -> (HOST, HOST_READ).
void bufferBarrier(VkCommandBuffer cmd, const Buffer& buffer, VkPipelineStageFlags srcStage,
                   VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);

}  // namespace onelight::vk
