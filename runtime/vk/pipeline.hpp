// Shader modules and compute pipelines (graphics pipelines: graphics_pipeline.hpp).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

#include "vk/context.hpp"

namespace onelight::vk {

// A compute pipeline with one descriptor set (set 0) and optional push constants.
struct ComputePipeline {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;  // owned, set 0
    VkPipelineLayout layout = VK_NULL_HANDLE;          // owned
    VkPipeline pipeline = VK_NULL_HANDLE;              // owned

    ComputePipeline() = default;
    ComputePipeline(const ComputePipeline&) = delete;
    ComputePipeline& operator=(const ComputePipeline&) = delete;
};

// A shader module from SPIR-V words (e.g. a header made by onelight_add_shaders). The caller
// owns it and destroys it with vkDestroyShaderModule once its pipelines exist.
[[nodiscard]] VkShaderModule createShaderModule(const Context& ctx,
                                                std::span<const uint32_t> spirv);

// Create-info helper: binding `binding` of a set is one storage buffer seen by `stages`.
[[nodiscard]] VkDescriptorSetLayoutBinding storageBufferBinding(uint32_t binding,
                                                                VkShaderStageFlags stages);

// A compute pipeline running entry point "main" of `spirv`, set 0 laid out by `bindings`, and
// `pushConstantBytes` (0 for none) of push constants at offset 0.
void createComputePipeline(const Context& ctx, ComputePipeline& pipeline,
                           std::span<const uint32_t> spirv,
                           std::span<const VkDescriptorSetLayoutBinding> bindings,
                           uint32_t pushConstantBytes);

// Destroys in reverse creation order. Safe on an empty ComputePipeline.
void destroyComputePipeline(const Context& ctx, ComputePipeline& pipeline);

}  // namespace onelight::vk
