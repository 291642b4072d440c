// Images, their views and samplers, and image layout barriers.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

#include "vk/buffer.hpp"
#include "vk/context.hpp"

namespace onelight::vk {

// How to create an Image. 2D (with layers), 3D (depth > 1) or cube (cube = true, layers = 6).
struct ImageDesc {
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    uint32_t width = 1, height = 1, depth = 1;
    uint32_t layers = 1;
    uint32_t mipLevels = 1;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT;
    bool cube = false;                                       // a cube map: view type CUBE
    VkImageViewType viewType = VK_IMAGE_VIEW_TYPE_MAX_ENUM;  // MAX_ENUM: picked from the rest
};

// An image with its own device-local memory and one view of all its mips and layers.
struct Image {
    VkImage image = VK_NULL_HANDLE;          // owned
    VkDeviceMemory memory = VK_NULL_HANDLE;  // owned
    VkImageView view = VK_NULL_HANDLE;       // owned, every mip and layer
    ImageDesc desc;                          // what it was created with

    Image() = default;
    Image(const Image&) = delete;
    Image& operator=(const Image&) = delete;
};

// The aspect of a format: DEPTH for depth formats, COLOR otherwise.
[[nodiscard]] VkImageAspectFlags aspectOf(VkFormat format);

// Creates the image, its memory (device-local preferred) and its view. Throws on failure, leaving
// `image` destroyed.
void createImage(const Context& ctx, Image& image, const ImageDesc& desc);

// A view of one layer range of an image (e.g. one shadow-map layer as a depth attachment). The
// caller destroys it with vkDestroyImageView before the image.
[[nodiscard]] VkImageView createLayerView(const Context& ctx, const Image& image,
                                          uint32_t firstLayer, uint32_t layerCount);

// Destroys view, image and memory. Safe on an empty Image.
void destroyImage(const Context& ctx, Image& image);

// A layout transition of mips [baseMip, baseMip + mipCount) and layers [baseLayer, ...) of an
// image, with the access scopes of the transition.
struct ImageBarrier {
    VkImageLayout oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout newLayout = VK_IMAGE_LAYOUT_GENERAL;
    VkPipelineStageFlags srcStage = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
    VkAccessFlags srcAccess = 0;
    VkPipelineStageFlags dstStage = VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT;
    VkAccessFlags dstAccess = 0;
    uint32_t baseMip = 0, mipCount = VK_REMAINING_MIP_LEVELS;
    uint32_t baseLayer = 0, layerCount = VK_REMAINING_ARRAY_LAYERS;
};

// A layout transition over every mip and layer.
[[nodiscard]] inline ImageBarrier layoutBarrier(VkImageLayout from, VkImageLayout to,
                                                VkPipelineStageFlags srcStage,
                                                VkAccessFlags srcAccess,
                                                VkPipelineStageFlags dstStage,
                                                VkAccessFlags dstAccess) {
    ImageBarrier b;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcStage = srcStage;
    b.srcAccess = srcAccess;
    b.dstStage = dstStage;
    b.dstAccess = dstAccess;
    return b;
}

// The same over layers [first, first + count) only.
[[nodiscard]] inline ImageBarrier layersBarrier(uint32_t first, uint32_t count, VkImageLayout from,
                                                VkImageLayout to, VkPipelineStageFlags srcStage,
                                                VkAccessFlags srcAccess,
                                                VkPipelineStageFlags dstStage,
                                                VkAccessFlags dstAccess) {
    ImageBarrier b = layoutBarrier(from, to, srcStage, srcAccess, dstStage, dstAccess);
    b.baseLayer = first;
    b.layerCount = count;
    return b;
}

// Records one image memory barrier.
void imageBarrier(VkCommandBuffer cmd, const Image& image, const ImageBarrier& barrier);
void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect,
                  const ImageBarrier& barrier);

// Fills every layer of mip 0 of `image` (layers tightly packed in `bytes`), then builds the other
// mips with linear blits (the format must support linear blit when mipLevels > 1), and leaves
// the image in SHADER_READ_ONLY_OPTIMAL. Waits for the upload to finish.
void uploadImage(const Context& ctx, Image& image, std::span<const uint8_t> bytes);

// Fills every mip and layer of `image` from `bytes`, which hold, mip after mip from the largest,
// every layer of that mip tightly packed (no blits: the caller made the mips, e.g. prefiltered
// probes), and leaves it in SHADER_READ_ONLY_OPTIMAL. Waits for the upload to finish.
void uploadImageMips(const Context& ctx, Image& image, std::span<const uint8_t> bytes);

// A sampler. Create-info helper; the caller destroys it with vkDestroySampler.
struct SamplerDesc {
    VkFilter magFilter = VK_FILTER_LINEAR;
    VkFilter minFilter = VK_FILTER_LINEAR;
    VkSamplerMipmapMode mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    VkSamplerAddressMode addressU = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    VkSamplerAddressMode addressV = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    VkSamplerAddressMode addressW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    bool compare = false;  // a depth-compare (shadow) sampler, LESS_OR_EQUAL
    float maxLod = VK_LOD_CLAMP_NONE;
    // Anisotropic filtering's most taps along the footprint's long axis; <= 1 is off (the
    // device feature samplerAnisotropy must be enabled for more).
    float maxAnisotropy = 1.0f;
};
[[nodiscard]] VkSampler createSampler(const Context& ctx, const SamplerDesc& desc);

}  // namespace onelight::vk
