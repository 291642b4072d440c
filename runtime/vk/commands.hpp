// Command buffers, fences and semaphores: create-info helpers, a one-shot submit, a frame submit,
// and barrier and copy helpers.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>

#include "vk/buffer.hpp"
#include "vk/context.hpp"

namespace onelight::vk {

// A primary command buffer from ctx.commandPool (freed with the pool, or by vkFreeCommandBuffers).
[[nodiscard]] VkCommandBuffer allocateCommandBuffer(const Context& ctx);

// A fence, signalled from the start when `signalled`. The caller destroys it with vkDestroyFence.
[[nodiscard]] VkFence createFence(const Context& ctx, bool signalled = false);

// A binary semaphore. The caller destroys it with vkDestroySemaphore.
[[nodiscard]] VkSemaphore createSemaphore(const Context& ctx);

// Resets `cmd` and begins recording it for one submit.
void beginOneTimeCommands(VkCommandBuffer cmd);

// Calls `wait` (a vkWaitForFences with the timeout it is given) and, when that times out, once
// more. A wait that the process's suspension interrupts (a SIGSTOP, the machine asleep) finds its
// wall-clock deadline passed on resume while the GPU's work only goes on then, and the second
// wait sees it finish; a hung device times out twice.
[[nodiscard]] VkResult waitSurvivingSuspend(const std::function<VkResult(uint64_t)>& wait,
                                            uint64_t timeoutNs);

// Waits for `fence` (throws "... timed out" on VK_TIMEOUT after timeoutNs, naming `what`).
void waitForFence(const Context& ctx, VkFence fence, const char* what,
                  uint64_t timeoutNs = 120'000'000'000ull);

// What a submit of one command buffer waits for and signals (all optional).
struct SubmitSync {
    VkSemaphore wait = VK_NULL_HANDLE;  // waited at waitStage
    VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
    VkSemaphore signal = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;  // signalled when the work is done (reset by submit)
};

// Submits `cmd` (ended) to ctx.queue with `sync`; resets sync.fence first.
void submitCommands(const Context& ctx, VkCommandBuffer cmd, const SubmitSync& sync);

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

// Copies mip 0, layer 0 of a colour image in TRANSFER_SRC_OPTIMAL into `buffer` (tightly packed
// rows), then makes the copy visible to host reads after the submit's fence.
void copyImageToHost(VkCommandBuffer cmd, VkImage image, uint32_t width, uint32_t height,
                     const Buffer& buffer);

// Copies layers [firstLayer, firstLayer + layerCount) of mip 0 of `src` (TRANSFER_SRC_OPTIMAL)
// into the same layers of `dst` (TRANSFER_DST_OPTIMAL), width x height texels of `aspect`.
void copyImage(VkCommandBuffer cmd, VkImage src, VkImage dst, VkImageAspectFlags aspect,
               uint32_t width, uint32_t height, uint32_t firstLayer = 0, uint32_t layerCount = 1);

// Scales mip 0, layer 0 of the colour image `src` (TRANSFER_SRC_OPTIMAL, srcWidth x srcHeight)
// onto the whole of `dst` (TRANSFER_DST_OPTIMAL, dstWidth x dstHeight) with a linear filter. Both
// formats need VK_FORMAT_FEATURE_BLIT_SRC_BIT, BLIT_DST_BIT and SAMPLED_IMAGE_FILTER_LINEAR_BIT.
void blitImage(VkCommandBuffer cmd, VkImage src, uint32_t srcWidth, uint32_t srcHeight, VkImage dst,
               uint32_t dstWidth, uint32_t dstHeight);

}  // namespace onelight::vk
