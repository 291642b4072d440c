#include "vk/pipeline.hpp"

#include "vk/vk_check.hpp"

namespace onelight::vk {

VkShaderModule createShaderModule(const Context& ctx, std::span<const uint32_t> spirv) {
    VkShaderModuleCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    info.codeSize = spirv.size_bytes();
    info.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(ctx.device, &info, nullptr, &module));
    return module;
}

VkDescriptorSetLayoutBinding storageBufferBinding(uint32_t binding, VkShaderStageFlags stages) {
    VkDescriptorSetLayoutBinding b{};
    b.binding = binding;
    b.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    b.descriptorCount = 1;
    b.stageFlags = stages;
    return b;
}

void createComputePipeline(const Context& ctx, ComputePipeline& pipeline,
                           std::span<const uint32_t> spirv,
                           std::span<const VkDescriptorSetLayoutBinding> bindings,
                           uint32_t pushConstantBytes) {
    VkShaderModule module = VK_NULL_HANDLE;
    try {
        VkDescriptorSetLayoutCreateInfo setInfo{};
        setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
        setInfo.bindingCount = uint32_t(bindings.size());
        setInfo.pBindings = bindings.data();
        VK_CHECK(vkCreateDescriptorSetLayout(ctx.device, &setInfo, nullptr, &pipeline.setLayout));

        VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes};
        VkPipelineLayoutCreateInfo layoutInfo{};
        layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
        layoutInfo.setLayoutCount = 1;
        layoutInfo.pSetLayouts = &pipeline.setLayout;
        layoutInfo.pushConstantRangeCount = pushConstantBytes > 0 ? 1 : 0;
        layoutInfo.pPushConstantRanges = &push;
        VK_CHECK(vkCreatePipelineLayout(ctx.device, &layoutInfo, nullptr, &pipeline.layout));

        module = createShaderModule(ctx, spirv);
        VkComputePipelineCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
        info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        info.stage.module = module;
        info.stage.pName = "main";
        info.layout = pipeline.layout;
        VK_CHECK(vkCreateComputePipelines(ctx.device, ctx.pipelineCache, 1, &info, nullptr,
                                          &pipeline.pipeline));
    } catch (...) {
        if (module) vkDestroyShaderModule(ctx.device, module, nullptr);
        destroyComputePipeline(ctx, pipeline);
        throw;
    }
    vkDestroyShaderModule(ctx.device, module, nullptr);
}

void destroyComputePipeline(const Context& ctx, ComputePipeline& pipeline) {
    if (pipeline.pipeline) vkDestroyPipeline(ctx.device, pipeline.pipeline, nullptr);
    pipeline.pipeline = VK_NULL_HANDLE;
    if (pipeline.layout) vkDestroyPipelineLayout(ctx.device, pipeline.layout, nullptr);
    pipeline.layout = VK_NULL_HANDLE;
    if (pipeline.setLayout) vkDestroyDescriptorSetLayout(ctx.device, pipeline.setLayout, nullptr);
    pipeline.setLayout = VK_NULL_HANDLE;
}

}  // namespace onelight::vk
