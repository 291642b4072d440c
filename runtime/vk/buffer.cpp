#include "vk/buffer.hpp"

#include <stdexcept>

#include "vk/vk_check.hpp"

namespace onelight::vk {

int findMemoryType(const Context& ctx, uint32_t typeBits, VkMemoryPropertyFlags flags) {
    const VkPhysicalDeviceMemoryProperties& mem = ctx.memoryProperties;
    for (uint32_t i = 0; i < mem.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (mem.memoryTypes[i].propertyFlags & flags) == flags)
            return int(i);
    return -1;
}

void createHostBuffer(const Context& ctx, Buffer& buffer, VkDeviceSize size,
                      VkBufferUsageFlags usage) {
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
        const VkMemoryPropertyFlags coherent =
            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        int type =
            findMemoryType(ctx, req.memoryTypeBits, coherent | VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
        if (type < 0) type = findMemoryType(ctx, req.memoryTypeBits, coherent);
        if (type < 0)
            throw std::runtime_error("no host-visible, host-coherent memory for a buffer");

        VkMemoryAllocateInfo alloc{};

        alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = uint32_t(type);
        VK_CHECK(vkAllocateMemory(ctx.device, &alloc, nullptr, &buffer.memory));
        VK_CHECK(vkBindBufferMemory(ctx.device, buffer.buffer, buffer.memory, 0));
        VK_CHECK(vkMapMemory(ctx.device, buffer.memory, 0, VK_WHOLE_SIZE, 0, &buffer.mapped));
    } catch (...) {
        destroyBuffer(ctx, buffer);
        throw;
    }
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
