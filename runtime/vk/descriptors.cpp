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

VkDescriptorPool createDescriptorPool(const Context& ctx, uint32_t maxSets,
                                      std::span<const VkDescriptorPoolSize> sizes) {
    VkDescriptorPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    info.maxSets = maxSets;
    info.poolSizeCount = uint32_t(sizes.size());
    info.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorPool(ctx.device, &info, nullptr, &pool));
    return pool;
}

VkDescriptorSet allocateDescriptorSet(const Context& ctx, VkDescriptorPool pool,
                                      VkDescriptorSetLayout layout) {
    VkDescriptorSetAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    alloc.descriptorPool = pool;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateDescriptorSets(ctx.device, &alloc, &set));
    return set;
}

void DescriptorWriter::buffer(uint32_t binding, VkDescriptorType type, VkBuffer buffer,
                              VkDeviceSize offset, VkDeviceSize range) {
    pending_.push_back({binding, 0, type, {buffer, offset, range}, {}});
}

void DescriptorWriter::image(uint32_t binding, VkImageView view, VkSampler sampler,
                             VkImageLayout layout, uint32_t arrayElement) {
    pending_.push_back({binding,
                        arrayElement,
                        VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                        {},
                        {sampler, view, layout}});
}

void DescriptorWriter::update(const Context& ctx) {
    std::vector<VkWriteDescriptorSet> writes(pending_.size());
    for (size_t i = 0; i < pending_.size(); ++i) {
        const Pending& p = pending_[i];
        VkWriteDescriptorSet& w = writes[i];
        w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        w.dstSet = set;
        w.dstBinding = p.binding;
        w.dstArrayElement = p.arrayElement;
        w.descriptorCount = 1;
        w.descriptorType = p.type;
        if (p.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER)
            w.pImageInfo = &p.imageInfo;
        else
            w.pBufferInfo = &p.bufferInfo;
    }
    vkUpdateDescriptorSets(ctx.device, uint32_t(writes.size()), writes.data(), 0, nullptr);
    pending_.clear();
}

}  // namespace onelight::vk
