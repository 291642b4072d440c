// Dynamic rendering (Vulkan 1.3): attachment create-info helpers and a begin that also sets the
// viewport and scissor to the render area.
#pragma once

#include <vulkan/vulkan.h>

namespace onelight::vk {

// A colour attachment in COLOR_ATTACHMENT_OPTIMAL, cleared to `clear` when load is CLEAR.
[[nodiscard]] VkRenderingAttachmentInfo colorAttachment(VkImageView view, VkAttachmentLoadOp load,
                                                        VkAttachmentStoreOp store,
                                                        VkClearColorValue clear = {});

// The same, multisampled, averaged into `resolve` (COLOR_ATTACHMENT_OPTIMAL) at the end.
[[nodiscard]] VkRenderingAttachmentInfo resolvedColorAttachment(VkImageView multisampled,
                                                                VkImageView resolve,
                                                                VkAttachmentLoadOp load,
                                                                VkClearColorValue clear = {});

// A depth attachment in DEPTH_ATTACHMENT_OPTIMAL, cleared to `clearDepth` when load is CLEAR.
[[nodiscard]] VkRenderingAttachmentInfo depthAttachment(VkImageView view, VkAttachmentLoadOp load,
                                                        VkAttachmentStoreOp store,
                                                        float clearDepth = 1.0f);

// Begins rendering one layer of `extent` into `color` and/or `depth` (either may be null), with
// the viewport (depth 0..1) and the scissor set to the whole extent.
void beginRendering(VkCommandBuffer cmd, VkExtent2D extent, const VkRenderingAttachmentInfo* color,
                    const VkRenderingAttachmentInfo* depth);

}  // namespace onelight::vk
