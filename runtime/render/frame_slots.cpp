// The frames in flight: each slot's command buffer, fence, timestamp pool and per-frame buffers,
// and the wait for a slot's last frame with its GPU times.
#include "render/frame_slots.hpp"

#include <algorithm>
#include <cstring>
#include <vector>

#include "vk/commands.hpp"
#include "vk/timestamps.hpp"

namespace onelight::render {

void createFrameSlots(const vk::Context& ctx, FrameSlots& frames, size_t entities) {
    frames.timestamps = vk::timestampsSupported(ctx);
    entities = std::max<size_t>(entities, 1);
    for (FrameSlot& slot : frames.slots) {
        slot.cmd = vk::allocateCommandBuffer(ctx);
        slot.done = vk::createFence(ctx);
        if (frames.timestamps) slot.timestamps = vk::createTimestampPool(ctx, kTimestampCount);
        vk::createHostBuffer(ctx, slot.uniforms, sizeof(FrameUniforms),
                             VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        vk::createHostBuffer(ctx, slot.shadowViews, glsl::MAX_SHADOW_VIEWS * sizeof(GpuShadowView),
                             VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        vk::createHostBuffer(ctx, slot.objectLighting, entities * sizeof(GpuObjectLighting),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        std::memset(slot.shadowViews.mapped, 0, slot.shadowViews.size);
        std::memset(slot.objectLighting.mapped, 0, slot.objectLighting.size);
    }
}

void destroyFrameSlots(const vk::Context& ctx, FrameSlots& frames) {
    for (FrameSlot& slot : frames.slots) {
        vk::destroyBuffer(ctx, slot.objectLighting);
        vk::destroyBuffer(ctx, slot.shadowViews);
        vk::destroyBuffer(ctx, slot.uniforms);
        if (slot.timestamps) vkDestroyQueryPool(ctx.device, slot.timestamps, nullptr);
        if (slot.done) vkDestroyFence(ctx.device, slot.done, nullptr);
        if (slot.cmd) vkFreeCommandBuffers(ctx.device, ctx.commandPool, 1, &slot.cmd);
        slot.cmd = VK_NULL_HANDLE;
        slot.done = VK_NULL_HANDLE;
        slot.timestamps = VK_NULL_HANDLE;
        slot.pending = false;
    }
}

void finishFrame(const vk::Context& ctx, FrameSlot& slot, bool timestamps, FrameStats& stats) {
    if (!slot.pending) return;
    vk::waitForFence(ctx, slot.done, "drawFrame");
    slot.pending = false;
    if (!timestamps) return;
    const std::vector<double> t = vk::readTimestampsMs(ctx, slot.timestamps, kTimestampCount);
    stats.gpuTimestamps = true;
    stats.gpuFrame = slot.frame;
    stats.gpuShadowMs = t[1] - t[0];
    stats.gpuForwardMs = t[2] - t[1];
    stats.gpuTonemapMs = t[3] - t[2];
    stats.gpuMs = t[3];
}

}  // namespace onelight::render
