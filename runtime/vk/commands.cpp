#include "vk/commands.hpp"

#include <stdexcept>
#include <string>

#include "vk/vk_check.hpp"

namespace onelight::vk {

VkCommandBuffer allocateCommandBuffer(const Context& ctx) {
    VkCommandBufferAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    alloc.commandPool = ctx.commandPool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateCommandBuffers(ctx.device, &alloc, &cmd));
    return cmd;
}

VkFence createFence(const Context& ctx, bool signalled) {
    VkFenceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    info.flags = signalled ? VK_FENCE_CREATE_SIGNALED_BIT : 0;
    VkFence fence = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFence(ctx.device, &info, nullptr, &fence));
    return fence;
}

VkSemaphore createSemaphore(const Context& ctx) {
    VkSemaphoreCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
    VkSemaphore semaphore = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSemaphore(ctx.device, &info, nullptr, &semaphore));
    return semaphore;
}

void beginOneTimeCommands(VkCommandBuffer cmd) {
    VK_CHECK(vkResetCommandBuffer(cmd, 0));
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
}

VkResult waitSurvivingSuspend(const std::function<VkResult(uint64_t)>& wait, uint64_t timeoutNs) {
    const VkResult first = wait(timeoutNs);
    return first == VK_TIMEOUT ? wait(timeoutNs) : first;
}

void waitForFence(const Context& ctx, VkFence fence, const char* what, uint64_t timeoutNs) {
    const VkResult waited = waitSurvivingSuspend(
        [&](uint64_t t) { return vkWaitForFences(ctx.device, 1, &fence, VK_TRUE, t); }, timeoutNs);
    if (waited == VK_TIMEOUT)
        throw std::runtime_error(std::string(what) + ": the GPU did not finish within " +
                                 std::to_string(timeoutNs / 1'000'000'000ull) + " s");
    check(waited, "vkWaitForFences", __FILE__, __LINE__);
}

void submitCommands(const Context& ctx, VkCommandBuffer cmd, const SubmitSync& sync) {
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    if (sync.wait) {
        submit.waitSemaphoreCount = 1;
        submit.pWaitSemaphores = &sync.wait;
        submit.pWaitDstStageMask = &sync.waitStage;
    }
    if (sync.signal) {
        submit.signalSemaphoreCount = 1;
        submit.pSignalSemaphores = &sync.signal;
    }
    if (sync.fence) VK_CHECK(vkResetFences(ctx.device, 1, &sync.fence));
    VK_CHECK(vkQueueSubmit(ctx.queue, 1, &submit, sync.fence));
}

void submitOnce(const Context& ctx, const std::function<void(VkCommandBuffer)>& record,
                uint64_t timeoutNs) {
    VkCommandBuffer cmd = allocateCommandBuffer(ctx);
    VkFence fence = VK_NULL_HANDLE;
    try {
        beginOneTimeCommands(cmd);
        record(cmd);
        VK_CHECK(vkEndCommandBuffer(cmd));
        fence = createFence(ctx);
        SubmitSync sync;
        sync.fence = fence;
        submitCommands(ctx, cmd, sync);
    } catch (...) {
        if (fence) vkDestroyFence(ctx.device, fence, nullptr);
        vkFreeCommandBuffers(ctx.device, ctx.commandPool, 1, &cmd);
        throw;
    }

    const VkResult waited = waitSurvivingSuspend(
        [&](uint64_t t) { return vkWaitForFences(ctx.device, 1, &fence, VK_TRUE, t); }, timeoutNs);
    if (waited == VK_SUCCESS) {
        vkDestroyFence(ctx.device, fence, nullptr);
        vkFreeCommandBuffers(ctx.device, ctx.commandPool, 1, &cmd);
    }  // else the work may still be pending: the device is lost or hung, leave both alone
    check(waited, "vkWaitForFences(submitOnce)", __FILE__, __LINE__);
}

void bufferBarrier(VkCommandBuffer cmd, const Buffer& buffer, VkPipelineStageFlags srcStage,
                   VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                   VkAccessFlags dstAccess) {
    VkBufferMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
    barrier.srcAccessMask = srcAccess;
    barrier.dstAccessMask = dstAccess;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.buffer = buffer.buffer;
    barrier.offset = 0;
    barrier.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 1, &barrier, 0, nullptr);
}

void copyImageToHost(VkCommandBuffer cmd, VkImage image, uint32_t width, uint32_t height,
                     const Buffer& buffer) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {width, height, 1};
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.buffer, 1,
                           &copy);
    bufferBarrier(cmd, buffer, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
}

void copyImage(VkCommandBuffer cmd, VkImage src, VkImage dst, VkImageAspectFlags aspect,
               uint32_t width, uint32_t height, uint32_t firstLayer, uint32_t layerCount) {
    VkImageCopy copy{};
    copy.srcSubresource = {aspect, 0, firstLayer, layerCount};
    copy.dstSubresource = copy.srcSubresource;
    copy.extent = {width, height, 1};
    vkCmdCopyImage(cmd, src, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
}

void blitImage(VkCommandBuffer cmd, VkImage src, uint32_t srcWidth, uint32_t srcHeight, VkImage dst,
               uint32_t dstWidth, uint32_t dstHeight) {
    VkImageBlit blit{};
    blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.srcOffsets[1] = {int32_t(srcWidth), int32_t(srcHeight), 1};
    blit.dstSubresource = blit.srcSubresource;
    blit.dstOffsets[1] = {int32_t(dstWidth), int32_t(dstHeight), 1};
    vkCmdBlitImage(cmd, src, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
}

}  // namespace onelight::vk
