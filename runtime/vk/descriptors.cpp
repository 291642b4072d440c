#include "vk/descriptors.hpp"

#include <vector>

#include "vk/vk_check.hpp"

namespace onelight::vk {

void createStorageBufferSet(const Context& ctx, DescriptorSet& set, VkDescriptorSetLayout layout,
                            std::span<const Buffer* const> buffers) {
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, uint32_t(buffers.size())};
    VkDescriptorPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(ctx.device, &poolInfo, nullptr, &set.pool));

    try {
        VkDescriptorSetAllocateInfo alloc{};
        alloc.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
        alloc.descriptorPool = set.pool;
        alloc.descriptorSetCount = 1;
        alloc.pSetLayouts = &layout;
        VK_CHECK(vkAllocateDescriptorSets(ctx.device, &alloc, &set.set));
    } catch (...) {
        destroyDescriptorSet(ctx, set);
        throw;
    }

    std::vector<VkDescriptorBufferInfo> infos(buffers.size());
    std::vector<VkWriteDescriptorSet> writes(buffers.size());
    for (size_t i = 0; i < buffers.size(); ++i) {
        infos[i] = {buffers[i]->buffer, 0, VK_WHOLE_SIZE};
        writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[i].dstSet = set.set;
        writes[i].dstBinding = uint32_t(i);
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes[i].pBufferInfo = &infos[i];
    }
    vkUpdateDescriptorSets(ctx.device, uint32_t(writes.size()), writes.data(), 0, nullptr);
}

void destroyDescriptorSet(const Context& ctx, DescriptorSet& set) {
    if (set.pool) vkDestroyDescriptorPool(ctx.device, set.pool, nullptr);
    set.pool = VK_NULL_HANDLE;
    set.set = VK_NULL_HANDLE;
}

}  // namespace onelight::vk
