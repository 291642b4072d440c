// Descriptor sets: pools, set allocation, a writer of buffer and image descriptors, and a set of
// storage buffers with a pool of its own.
#pragma once

#include <vulkan/vulkan.h>

#include <span>
#include <vector>

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

// A descriptor pool for `maxSets` sets holding at most `sizes` descriptors. The caller destroys
// it with vkDestroyDescriptorPool, which frees its sets.
[[nodiscard]] VkDescriptorPool createDescriptorPool(const Context& ctx, uint32_t maxSets,
                                                    std::span<const VkDescriptorPoolSize> sizes);

// One set of `layout` from `pool` (borrowed by the caller from the pool).
[[nodiscard]] VkDescriptorSet allocateDescriptorSet(const Context& ctx, VkDescriptorPool pool,
                                                    VkDescriptorSetLayout layout);

// Collects descriptor writes to one set and applies them with update(). Buffer and image infos
// are stored inside, so the writer must live until update().
struct DescriptorWriter {
    VkDescriptorSet set = VK_NULL_HANDLE;  // borrowed

    // The whole buffer, or `range` bytes from `offset` (a dynamic binding's range: the record).
    void buffer(uint32_t binding, VkDescriptorType type, VkBuffer buffer, VkDeviceSize offset = 0,
                VkDeviceSize range = VK_WHOLE_SIZE);
    void image(uint32_t binding, VkImageView view, VkSampler sampler,
               VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
               uint32_t arrayElement = 0);
    void update(const Context& ctx);

private:
    struct Pending {
        uint32_t binding;
        uint32_t arrayElement;
        VkDescriptorType type;
        VkDescriptorBufferInfo bufferInfo;
        VkDescriptorImageInfo imageInfo;
    };
    std::vector<Pending> pending_;
};

}  // namespace onelight::vk
