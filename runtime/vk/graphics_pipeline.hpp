// Graphics pipelines for dynamic rendering (Vulkan 1.3 core), with their layouts.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <vector>

#include "vk/context.hpp"

namespace onelight::vk {

// A pipeline layout and the descriptor-set layouts it owns.
struct PipelineLayout {
    std::vector<VkDescriptorSetLayout> setLayouts;  // owned, set i
    VkPipelineLayout layout = VK_NULL_HANDLE;       // owned

    PipelineLayout() = default;
    PipelineLayout(const PipelineLayout&) = delete;
    PipelineLayout& operator=(const PipelineLayout&) = delete;
};

// Create-info helper: binding `binding` holds `count` descriptors of `type` seen by `stages`.
[[nodiscard]] VkDescriptorSetLayoutBinding layoutBinding(uint32_t binding, VkDescriptorType type,
                                                         VkShaderStageFlags stages,
                                                         uint32_t count = 1);

// One descriptor-set layout per entry of `sets`, and push constants of `pushBytes` bytes
// (0 for none) seen by `pushStages`.
void createPipelineLayout(const Context& ctx, PipelineLayout& layout,
                          std::span<const std::vector<VkDescriptorSetLayoutBinding>> sets,
                          uint32_t pushBytes, VkShaderStageFlags pushStages);
void destroyPipelineLayout(const Context& ctx, PipelineLayout& layout);

// One shader stage: SPIR-V words, and specialization constants as (constant_id, int value).
struct ShaderStage {
    VkShaderStageFlagBits stage = VK_SHADER_STAGE_VERTEX_BIT;
    std::span<const uint32_t> spirv;
    std::vector<std::pair<uint32_t, int32_t>> constants;
};

// What a graphics pipeline draws: vertex layout, raster state and attachment formats.
struct GraphicsPipelineDesc {
    std::vector<ShaderStage> stages;
    std::vector<VkVertexInputBindingDescription> vertexBindings;
    std::vector<VkVertexInputAttributeDescription> vertexAttributes;
    VkCullModeFlags cullMode = VK_CULL_MODE_BACK_BIT;
    VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    bool depthTest = true;
    bool depthWrite = true;
    VkCompareOp depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
    bool colorWrite = true;  // false: the colour attachments are left as they are (depth only)
    // Colour over what is there by the source alpha: rgb = src a + dst (1 - a), alpha kept.
    bool alphaBlend = false;
    bool dynamicDepthBias = false;  // depth bias enabled, its values set per draw
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    std::vector<VkFormat> colorFormats;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
};

// Creates a pipeline for vkCmdBeginRendering with dynamic viewport and scissor.
[[nodiscard]] VkPipeline createGraphicsPipeline(const Context& ctx, const PipelineLayout& layout,
                                                const GraphicsPipelineDesc& desc);

}  // namespace onelight::vk
