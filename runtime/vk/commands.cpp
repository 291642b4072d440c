#include "vk/commands.hpp"

#include "vk/vk_check.hpp"

namespace onelight::vk {

void submitOnce(const Context& ctx, const std::function<void(VkCommandBuffer)>& record,
                uint64_t timeoutNs) {
    VkCommandBufferAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    alloc.commandPool = ctx.commandPool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateCommandBuffers(ctx.device, &alloc, &cmd));

    VkFence fence = VK_NULL_HANDLE;
    try {
        VkCommandBufferBeginInfo begin{};
        begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
        record(cmd);
        VK_CHECK(vkEndCommandBuffer(cmd));

        VkFenceCreateInfo fenceInfo{};

        fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
        VK_CHECK(vkCreateFence(ctx.device, &fenceInfo, nullptr, &fence));
        VkSubmitInfo submit{};
        submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cmd;
        VK_CHECK(vkQueueSubmit(ctx.queue, 1, &submit, fence));
    } catch (...) {
        if (fence) vkDestroyFence(ctx.device, fence, nullptr);
        vkFreeCommandBuffers(ctx.device, ctx.commandPool, 1, &cmd);
        throw;
    }

    const VkResult waited = vkWaitForFences(ctx.device, 1, &fence, VK_TRUE, timeoutNs);
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

}  // namespace onelight::vk
