// Buffers and their memory: host-visible buffers, which the CPU writes and reads through a
// persistent mapping (per-frame data, readback, staging), and device-local buffers filled once
// through a staging buffer (geometry, materials, lights).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "vk/context.hpp"

namespace onelight::vk {

// A buffer with its own memory allocation. Destroy with destroyBuffer() before the context.
struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;        // owned
    VkDeviceMemory memory = VK_NULL_HANDLE;  // owned
    VkDeviceSize size = 0;                   // bytes, as requested
    void* mapped =
        nullptr;  // host pointer to the whole buffer while it lives; null if device-local

    Buffer() = default;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;
};

// The index of a memory type allowed by typeBits that has all of `flags`, or -1.
[[nodiscard]] int findMemoryType(const Context& ctx, uint32_t typeBits,
                                 VkMemoryPropertyFlags flags);

// A host-visible, host-coherent buffer of `size` bytes, mapped for its whole life (host-cached
// memory is preferred, for fast readback). Host writes before a submit need no flush; host reads
// after a fence wait need a barrier from the writing stage to VK_ACCESS_HOST_READ_BIT recorded
// after the writes (bufferBarrier in commands.hpp).
void createHostBuffer(const Context& ctx, Buffer& buffer, VkDeviceSize size,
                      VkBufferUsageFlags usage);

// A device-local buffer holding `bytes` (at least 16 bytes are allocated, so an empty array still
// binds), copied in through a staging buffer; waits for the copy. `usage` gains TRANSFER_DST.
void createDeviceBuffer(const Context& ctx, Buffer& buffer, std::span<const uint8_t> bytes,
                        VkBufferUsageFlags usage);

// The bytes of a contiguous array of plain records, for createDeviceBuffer.
template <class T>
[[nodiscard]] std::span<const uint8_t> bytesOf(std::span<const T> records) {
    return {reinterpret_cast<const uint8_t*>(records.data()), records.size_bytes()};
}

// Unmaps, destroys and frees. Safe on an empty Buffer.
void destroyBuffer(const Context& ctx, Buffer& buffer);

}  // namespace onelight::vk
