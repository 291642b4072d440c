#include "vk/buffer.hpp"

#include <algorithm>
#include <cstring>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include "vk/commands.hpp"
#include "vk/vk_check.hpp"

namespace onelight::vk {

int findMemoryType(const Context& ctx, uint32_t typeBits, VkMemoryPropertyFlags flags) {
    const VkPhysicalDeviceMemoryProperties& mem = ctx.memoryProperties;
    for (uint32_t i = 0; i < mem.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (mem.memoryTypes[i].propertyFlags & flags) == flags)
            return int(i);
    return -1;
}

namespace {

// Creates the buffer and binds memory of the first type found among `preferences` (each a set of
// property flags the type must have).
void createBufferWithMemory(const Context& ctx, Buffer& buffer, VkDeviceSize size,
                            VkBufferUsageFlags usage,
                            std::initializer_list<VkMemoryPropertyFlags> preferences,
                            const char* what) {
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VK_CHECK(vkCreateBuffer(ctx.device, &info, nullptr, &buffer.buffer));
    buffer.size = size;
    try {
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(ctx.device, buffer.buffer, &req);
        int type = -1;
        for (VkMemoryPropertyFlags flags : preferences)
            if (type < 0) type = findMemoryType(ctx, req.memoryTypeBits, flags);
        if (type < 0) throw std::runtime_error(std::string("no memory type for ") + what);
        VkMemoryAllocateInfo alloc{};
        alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = uint32_t(type);
        VK_CHECK(vkAllocateMemory(ctx.device, &alloc, nullptr, &buffer.memory));
        VK_CHECK(vkBindBufferMemory(ctx.device, buffer.buffer, buffer.memory, 0));
    } catch (...) {
        destroyBuffer(ctx, buffer);
        throw;
    }
}

}  // namespace

void createHostBuffer(const Context& ctx, Buffer& buffer, VkDeviceSize size,
                      VkBufferUsageFlags usage) {
    const VkMemoryPropertyFlags coherent =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    createBufferWithMemory(ctx, buffer, size, usage,
                           {coherent | VK_MEMORY_PROPERTY_HOST_CACHED_BIT, coherent},
                           "a host-visible, host-coherent buffer");
    try {
        VK_CHECK(vkMapMemory(ctx.device, buffer.memory, 0, VK_WHOLE_SIZE, 0, &buffer.mapped));
    } catch (...) {
        destroyBuffer(ctx, buffer);
        throw;
    }
}

void createDeviceBuffer(const Context& ctx, Buffer& buffer, std::span<const uint8_t> bytes,
                        VkBufferUsageFlags usage) {
    const VkDeviceSize size = std::max<VkDeviceSize>(bytes.size(), 16);
    createBufferWithMemory(ctx, buffer, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           {VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0}, "a device-local buffer");
    if (bytes.empty()) return;
    Buffer staging;
    try {
        createHostBuffer(ctx, staging, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        std::memcpy(staging.mapped, bytes.data(), bytes.size());
        submitOnce(ctx, [&](VkCommandBuffer cmd) {
            const VkBufferCopy region{0, 0, bytes.size()};
            vkCmdCopyBuffer(cmd, staging.buffer, buffer.buffer, 1, &region);
            // Every later reader (vertex input, index, shader reads) waits for the copy.
            bufferBarrier(cmd, buffer, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_READ_BIT);
        });
    } catch (...) {
        destroyBuffer(ctx, staging);
        destroyBuffer(ctx, buffer);
        throw;
    }
    destroyBuffer(ctx, staging);
}

void destroyBuffer(const Context& ctx, Buffer& buffer) {
    if (buffer.mapped) vkUnmapMemory(ctx.device, buffer.memory);
    buffer.mapped = nullptr;
    if (buffer.buffer) vkDestroyBuffer(ctx.device, buffer.buffer, nullptr);
    buffer.buffer = VK_NULL_HANDLE;
    if (buffer.memory) vkFreeMemory(ctx.device, buffer.memory, nullptr);
    buffer.memory = VK_NULL_HANDLE;
    buffer.size = 0;
}

}  // namespace onelight::vk
