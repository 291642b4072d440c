// Descriptor sets. For now one set of storage buffers from a pool of its own.
#pragma once

#include <vulkan/vulkan.h>

#include <span>

#include "vk/buffer.hpp"
#include "vk/context.hpp"

namespace onelight::vk {

// One descriptor set and the pool it came from.
struct DescriptorSet {
    VkDescriptorPool pool = VK_NULL_HANDLE;  // owned
    VkDescriptorSet set = VK_NULL_HANDLE;    // borrowed from pool, freed with it

    DescriptorSet() = default;
    DescriptorSet(const DescriptorSet&) = delete;
    DescriptorSet& operator=(const DescriptorSet&) = delete;
};

// A set of `layout` whose binding i is the whole of *buffers[i], as a storage buffer. The
// buffers are borrowed: they must outlive every use of the set.
void createStorageBufferSet(const Context& ctx, DescriptorSet& set, VkDescriptorSetLayout layout,
                            std::span<const Buffer* const> buffers);

// Destroys the pool and with it the set. Safe on an empty DescriptorSet.
void destroyDescriptorSet(const Context& ctx, DescriptorSet& set);

}  // namespace onelight::vk
