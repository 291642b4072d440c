#include "vk/rendering.hpp"

namespace onelight::vk {

VkRenderingAttachmentInfo colorAttachment(VkImageView view, VkAttachmentLoadOp load,
                                          VkAttachmentStoreOp store, VkClearColorValue clear) {
    VkRenderingAttachmentInfo a{};
    a.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
    a.imageView = view;
    a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    a.loadOp = load;
    a.storeOp = store;
    a.clearValue.color = clear;
    return a;
}

VkRenderingAttachmentInfo resolvedColorAttachment(VkImageView multisampled, VkImageView resolve,
                                                  VkAttachmentLoadOp load,
                                                  VkClearColorValue clear) {
    VkRenderingAttachmentInfo a =
        colorAttachment(multisampled, load, VK_ATTACHMENT_STORE_OP_DONT_CARE, clear);
    a.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
    a.resolveImageView = resolve;
    a.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    return a;
}

VkRenderingAttachmentInfo depthAttachment(VkImageView view, VkAttachmentLoadOp load,
                                          VkAttachmentStoreOp store, float clearDepth) {
    VkRenderingAttachmentInfo a{};
    a.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
    a.imageView = view;
    a.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    a.loadOp = load;
    a.storeOp = store;
    a.clearValue.depthStencil = {clearDepth, 0};
    return a;
}

void beginRendering(VkCommandBuffer cmd, VkExtent2D extent, const VkRenderingAttachmentInfo* color,
                    const VkRenderingAttachmentInfo* depth) {
    VkRenderingInfo info{};
    info.sType = VK_STRUCTURE_TYPE_RENDERING_INFO;
    info.renderArea = {{0, 0}, extent};
    info.layerCount = 1;
    info.colorAttachmentCount = color ? 1 : 0;
    info.pColorAttachments = color;
    info.pDepthAttachment = depth;
    vkCmdBeginRendering(cmd, &info);
    const VkViewport viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

}  // namespace onelight::vk
