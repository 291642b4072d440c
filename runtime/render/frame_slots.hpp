// The frames in flight (frame_slots.cpp): what each owns so that the CPU fills the next frame
// while the GPU still draws this one.
#pragma once

#include <array>
#include <cstdint>

#include "render/renderer.hpp"
#include "vk/buffer.hpp"
#include "vk/context.hpp"

namespace onelight::render {

inline constexpr uint32_t kFramesInFlight =
    2;  // the CPU records one frame while the GPU draws another
inline constexpr uint32_t kTimestampCount = 4;  // frame start, after shadows, forward, tonemap

/// What one frame in flight owns: its command buffer and fence, and every buffer the CPU writes
/// for it. Its descriptor set over these buffers is DescriptorSets::frame[slot].
struct FrameSlot {
    VkCommandBuffer cmd = VK_NULL_HANDLE;     // owned, from ctx.commandPool
    VkFence done = VK_NULL_HANDLE;            // owned, signalled when its last submit finished
    VkQueryPool timestamps = VK_NULL_HANDLE;  // owned, kTimestampCount (when supported)
    vk::Buffer uniforms;                      // owned, FrameUniforms
    vk::Buffer shadowViews;                   // owned, MAX_SHADOW_VIEWS GpuShadowView
    vk::Buffer objectLighting;                // owned, GpuObjectLighting per entity
    uint64_t frame = 0;                       // the frame it last submitted
    bool pending = false;                     // submitted and not waited for yet
};

/// kFramesInFlight slots used in turn: frame n records into slots[n % kFramesInFlight].
struct FrameSlots {
    std::array<FrameSlot, kFramesInFlight> slots;
    uint64_t submitted = 0;   // frames submitted so far
    bool timestamps = false;  // the device writes timestamps
};

/// Slots whose buffers hold the shadow views and `entities` entities (at least one).
void createFrameSlots(const vk::Context& ctx, FrameSlots& frames, size_t entities);
void destroyFrameSlots(const vk::Context& ctx, FrameSlots& frames);

/// Waits for the slot's last frame, if one is pending, and reports its GPU times in `stats`
/// (when the device writes `timestamps`).
void finishFrame(const vk::Context& ctx, FrameSlot& slot, bool timestamps, FrameStats& stats);

}  // namespace onelight::render
