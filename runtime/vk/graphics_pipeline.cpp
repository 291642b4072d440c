#include "vk/graphics_pipeline.hpp"

#include "vk/pipeline.hpp"
#include "vk/vk_check.hpp"

namespace onelight::vk {

VkDescriptorSetLayoutBinding layoutBinding(uint32_t binding, VkDescriptorType type,
                                           VkShaderStageFlags stages, uint32_t count) {
    VkDescriptorSetLayoutBinding b{};
    b.binding = binding;
    b.descriptorType = type;
    b.descriptorCount = count;
    b.stageFlags = stages;
    return b;
}

void createPipelineLayout(const Context& ctx, PipelineLayout& layout,
                          std::span<const std::vector<VkDescriptorSetLayoutBinding>> sets,
                          uint32_t pushBytes, VkShaderStageFlags pushStages) {
    try {
        for (const std::vector<VkDescriptorSetLayoutBinding>& bindings : sets) {
            VkDescriptorSetLayoutCreateInfo info{};
            info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
            info.bindingCount = uint32_t(bindings.size());
            info.pBindings = bindings.data();
            VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
            VK_CHECK(vkCreateDescriptorSetLayout(ctx.device, &info, nullptr, &setLayout));
            layout.setLayouts.push_back(setLayout);
        }
        VkPushConstantRange push{pushStages, 0, pushBytes};
        VkPipelineLayoutCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
        info.setLayoutCount = uint32_t(layout.setLayouts.size());
        info.pSetLayouts = layout.setLayouts.data();
        info.pushConstantRangeCount = pushBytes > 0 ? 1 : 0;
        info.pPushConstantRanges = &push;
        VK_CHECK(vkCreatePipelineLayout(ctx.device, &info, nullptr, &layout.layout));
    } catch (...) {
        destroyPipelineLayout(ctx, layout);
        throw;
    }
}

void destroyPipelineLayout(const Context& ctx, PipelineLayout& layout) {
    if (layout.layout) vkDestroyPipelineLayout(ctx.device, layout.layout, nullptr);
    layout.layout = VK_NULL_HANDLE;
    for (auto it = layout.setLayouts.rbegin(); it != layout.setLayouts.rend(); ++it)
        vkDestroyDescriptorSetLayout(ctx.device, *it, nullptr);
    layout.setLayouts.clear();
}

VkPipeline createGraphicsPipeline(const Context& ctx, const PipelineLayout& layout,
                                  const GraphicsPipelineDesc& desc) {
    const size_t stageCount = desc.stages.size();
    std::vector<VkShaderModule> modules;
    std::vector<VkPipelineShaderStageCreateInfo> stages(stageCount);
    std::vector<std::vector<VkSpecializationMapEntry>> entries(stageCount);
    std::vector<std::vector<int32_t>> values(stageCount);
    std::vector<VkSpecializationInfo> specs(stageCount);
    VkPipeline pipeline = VK_NULL_HANDLE;
    try {
        for (size_t i = 0; i < stageCount; ++i) {
            const ShaderStage& s = desc.stages[i];
            modules.push_back(createShaderModule(ctx, s.spirv));
            for (const auto& [id, value] : s.constants) {
                entries[i].push_back(
                    {id, uint32_t(values[i].size() * sizeof(int32_t)), sizeof(int32_t)});
                values[i].push_back(value);
            }
            specs[i].mapEntryCount = uint32_t(entries[i].size());
            specs[i].pMapEntries = entries[i].data();
            specs[i].dataSize = values[i].size() * sizeof(int32_t);
            specs[i].pData = values[i].data();
            stages[i].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
            stages[i].stage = s.stage;
            stages[i].module = modules.back();
            stages[i].pName = "main";
            stages[i].pSpecializationInfo = entries[i].empty() ? nullptr : &specs[i];
        }

        VkPipelineVertexInputStateCreateInfo vertexInput{};
        vertexInput.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
        vertexInput.vertexBindingDescriptionCount = uint32_t(desc.vertexBindings.size());
        vertexInput.pVertexBindingDescriptions = desc.vertexBindings.data();
        vertexInput.vertexAttributeDescriptionCount = uint32_t(desc.vertexAttributes.size());
        vertexInput.pVertexAttributeDescriptions = desc.vertexAttributes.data();

        VkPipelineInputAssemblyStateCreateInfo assembly{};
        assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
        assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;

        VkPipelineViewportStateCreateInfo viewport{};
        viewport.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
        viewport.viewportCount = 1;
        viewport.scissorCount = 1;

        VkPipelineRasterizationStateCreateInfo raster{};
        raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
        raster.polygonMode = VK_POLYGON_MODE_FILL;
        raster.cullMode = desc.cullMode;
        raster.frontFace = desc.frontFace;
        raster.depthBiasEnable = desc.dynamicDepthBias ? VK_TRUE : VK_FALSE;
        raster.lineWidth = 1.0f;

        VkPipelineMultisampleStateCreateInfo multisample{};
        multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
        multisample.rasterizationSamples = desc.samples;

        VkPipelineDepthStencilStateCreateInfo depth{};
        depth.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
        depth.depthTestEnable = desc.depthTest ? VK_TRUE : VK_FALSE;
        depth.depthWriteEnable = desc.depthWrite ? VK_TRUE : VK_FALSE;
        depth.depthCompareOp = desc.depthCompare;

        std::vector<VkPipelineColorBlendAttachmentState> blends(desc.colorFormats.size());
        for (VkPipelineColorBlendAttachmentState& b : blends) {
            b.colorWriteMask = desc.colorWrite
                                   ? VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                         VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT
                                   : 0u;
            if (desc.alphaBlend) {
                b.blendEnable = VK_TRUE;
                b.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
                b.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
                b.colorBlendOp = VK_BLEND_OP_ADD;
                b.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
                b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
                b.alphaBlendOp = VK_BLEND_OP_ADD;
            }
        }
        VkPipelineColorBlendStateCreateInfo blend{};
        blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
        blend.attachmentCount = uint32_t(blends.size());
        blend.pAttachments = blends.data();

        std::vector<VkDynamicState> dynamicStates = {VK_DYNAMIC_STATE_VIEWPORT,
                                                     VK_DYNAMIC_STATE_SCISSOR};
        if (desc.dynamicDepthBias) dynamicStates.push_back(VK_DYNAMIC_STATE_DEPTH_BIAS);
        VkPipelineDynamicStateCreateInfo dynamic{};
        dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
        dynamic.dynamicStateCount = uint32_t(dynamicStates.size());
        dynamic.pDynamicStates = dynamicStates.data();

        VkPipelineRenderingCreateInfo rendering{};
        rendering.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO;
        rendering.colorAttachmentCount = uint32_t(desc.colorFormats.size());
        rendering.pColorAttachmentFormats = desc.colorFormats.data();
        rendering.depthAttachmentFormat = desc.depthFormat;

        VkGraphicsPipelineCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
        info.pNext = &rendering;
        info.stageCount = uint32_t(stages.size());
        info.pStages = stages.data();
        info.pVertexInputState = &vertexInput;
        info.pInputAssemblyState = &assembly;
        info.pViewportState = &viewport;
        info.pRasterizationState = &raster;
        info.pMultisampleState = &multisample;
        info.pDepthStencilState = &depth;
        info.pColorBlendState = &blend;
        info.pDynamicState = &dynamic;
        info.layout = layout.layout;
        VK_CHECK(
            vkCreateGraphicsPipelines(ctx.device, ctx.pipelineCache, 1, &info, nullptr, &pipeline));
    } catch (...) {
        for (VkShaderModule m : modules) vkDestroyShaderModule(ctx.device, m, nullptr);
        throw;
    }
    for (VkShaderModule m : modules) vkDestroyShaderModule(ctx.device, m, nullptr);
    return pipeline;
}

}  // namespace onelight::vk
