#include "vk/image.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "vk/commands.hpp"
#include "vk/vk_check.hpp"

namespace onelight::vk {

namespace {

VkImageViewType viewTypeOf(const ImageDesc& desc) {
    if (desc.viewType != VK_IMAGE_VIEW_TYPE_MAX_ENUM) return desc.viewType;
    if (desc.depth > 1) return VK_IMAGE_VIEW_TYPE_3D;
    if (desc.cube) return desc.layers > 6 ? VK_IMAGE_VIEW_TYPE_CUBE_ARRAY : VK_IMAGE_VIEW_TYPE_CUBE;
    return desc.layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
}

uint32_t bytesPerTexel(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8_UNORM:
            return 1;
        case VK_FORMAT_R16_SFLOAT:
            return 2;
        case VK_FORMAT_R8G8B8A8_UNORM:
        case VK_FORMAT_R8G8B8A8_SRGB:
        case VK_FORMAT_B8G8R8A8_UNORM:
        case VK_FORMAT_B8G8R8A8_SRGB:
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_R32_SFLOAT:
        case VK_FORMAT_E5B9G9R9_UFLOAT_PACK32:
            return 4;
        case VK_FORMAT_R16G16B16A16_SFLOAT:
            return 8;
        case VK_FORMAT_R32G32B32A32_SFLOAT:
            return 16;
        default:
            throw std::runtime_error("uploadImage: unsupported format " +
                                     std::to_string(int(format)));
    }
}

}  // namespace

VkImageAspectFlags aspectOf(VkFormat format) {
    switch (format) {
        case VK_FORMAT_D16_UNORM:
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_X8_D24_UNORM_PACK32:
            return VK_IMAGE_ASPECT_DEPTH_BIT;
        case VK_FORMAT_D24_UNORM_S8_UINT:
        case VK_FORMAT_D32_SFLOAT_S8_UINT:
            return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
        default:
            return VK_IMAGE_ASPECT_COLOR_BIT;
    }
}

void createImage(const Context& ctx, Image& image, const ImageDesc& desc) {
    image.desc = desc;
    VkImageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    info.flags = desc.cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
    info.imageType = desc.depth > 1 || desc.viewType == VK_IMAGE_VIEW_TYPE_3D ? VK_IMAGE_TYPE_3D
                                                                              : VK_IMAGE_TYPE_2D;
    info.format = desc.format;
    info.extent = {desc.width, desc.height, desc.depth};
    info.mipLevels = desc.mipLevels;
    info.arrayLayers = desc.layers;
    info.samples = desc.samples;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VK_CHECK(vkCreateImage(ctx.device, &info, nullptr, &image.image));

    try {
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(ctx.device, image.image, &req);
        int type = findMemoryType(ctx, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        if (type < 0) type = findMemoryType(ctx, req.memoryTypeBits, 0);
        if (type < 0) throw std::runtime_error("no memory type for an image");
        VkMemoryAllocateInfo alloc{};
        alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = uint32_t(type);
        VK_CHECK(vkAllocateMemory(ctx.device, &alloc, nullptr, &image.memory));
        VK_CHECK(vkBindImageMemory(ctx.device, image.image, image.memory, 0));

        VkImageViewCreateInfo viewInfo{};
        viewInfo.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
        viewInfo.image = image.image;
        viewInfo.viewType = viewTypeOf(desc);
        viewInfo.format = desc.format;
        viewInfo.subresourceRange = {aspectOf(desc.format), 0, desc.mipLevels, 0, desc.layers};
        VK_CHECK(vkCreateImageView(ctx.device, &viewInfo, nullptr, &image.view));
    } catch (...) {
        destroyImage(ctx, image);
        throw;
    }
}

VkImageView createLayerView(const Context& ctx, const Image& image, uint32_t firstLayer,
                            uint32_t layerCount) {
    VkImageViewCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    info.image = image.image;
    info.viewType = layerCount > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
    info.format = image.desc.format;
    info.subresourceRange = {aspectOf(image.desc.format), 0, 1, firstLayer, layerCount};
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(ctx.device, &info, nullptr, &view));
    return view;
}

void destroyImage(const Context& ctx, Image& image) {
    if (image.view) vkDestroyImageView(ctx.device, image.view, nullptr);
    image.view = VK_NULL_HANDLE;
    if (image.image) vkDestroyImage(ctx.device, image.image, nullptr);
    image.image = VK_NULL_HANDLE;
    if (image.memory) vkFreeMemory(ctx.device, image.memory, nullptr);
    image.memory = VK_NULL_HANDLE;
}

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect,
                  const ImageBarrier& b) {
    VkImageMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    barrier.srcAccessMask = b.srcAccess;
    barrier.dstAccessMask = b.dstAccess;
    barrier.oldLayout = b.oldLayout;
    barrier.newLayout = b.newLayout;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {aspect, b.baseMip, b.mipCount, b.baseLayer, b.layerCount};
    vkCmdPipelineBarrier(cmd, b.srcStage, b.dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

void imageBarrier(VkCommandBuffer cmd, const Image& image, const ImageBarrier& barrier) {
    imageBarrier(cmd, image.image, aspectOf(image.desc.format), barrier);
}

void uploadImage(const Context& ctx, Image& image, std::span<const uint8_t> bytes) {
    const ImageDesc& d = image.desc;
    const VkDeviceSize expected =
        VkDeviceSize(d.width) * d.height * d.depth * d.layers * bytesPerTexel(d.format);
    if (bytes.size() != expected)
        throw std::runtime_error("uploadImage: " + std::to_string(bytes.size()) + " bytes given, " +
                                 std::to_string(expected) + " expected");
    Buffer staging;
    createHostBuffer(ctx, staging, expected, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memcpy(staging.mapped, bytes.data(), bytes.size());
    try {
        submitOnce(ctx, [&](VkCommandBuffer cmd) {
            ImageBarrier toDst;
            toDst.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            toDst.dstStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
            toDst.dstAccess = VK_ACCESS_TRANSFER_WRITE_BIT;
            imageBarrier(cmd, image, toDst);

            VkBufferImageCopy copy{};
            copy.imageSubresource = {aspectOf(d.format), 0, 0, d.layers};
            copy.imageExtent = {d.width, d.height, d.depth};
            vkCmdCopyBufferToImage(cmd, staging.buffer, image.image,
                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);

            int32_t w = int32_t(d.width), h = int32_t(d.height);
            for (uint32_t mip = 1; mip < d.mipLevels; ++mip) {
                ImageBarrier toSrc;
                toSrc.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
                toSrc.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
                toSrc.srcStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
                toSrc.srcAccess = VK_ACCESS_TRANSFER_WRITE_BIT;
                toSrc.dstStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
                toSrc.dstAccess = VK_ACCESS_TRANSFER_READ_BIT;
                toSrc.baseMip = mip - 1;
                toSrc.mipCount = 1;
                imageBarrier(cmd, image, toSrc);
                const int32_t nw = std::max(w / 2, 1), nh = std::max(h / 2, 1);
                VkImageBlit blit{};
                blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip - 1, 0, d.layers};
                blit.srcOffsets[1] = {w, h, 1};
                blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip, 0, d.layers};
                blit.dstOffsets[1] = {nw, nh, 1};
                vkCmdBlitImage(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.image,
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
                w = nw;
                h = nh;
            }
            // Mips below the last are in TRANSFER_SRC, the last in TRANSFER_DST.
            ImageBarrier toReadSrc;
            toReadSrc.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
            toReadSrc.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
            toReadSrc.srcStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
            toReadSrc.srcAccess = VK_ACCESS_TRANSFER_READ_BIT;
            toReadSrc.dstStage = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
            toReadSrc.dstAccess = VK_ACCESS_SHADER_READ_BIT;
            toReadSrc.baseMip = 0;
            toReadSrc.mipCount = d.mipLevels - 1;
            if (d.mipLevels > 1) imageBarrier(cmd, image, toReadSrc);
            ImageBarrier toReadDst = toReadSrc;
            toReadDst.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            toReadDst.srcAccess = VK_ACCESS_TRANSFER_WRITE_BIT;
            toReadDst.baseMip = d.mipLevels - 1;
            toReadDst.mipCount = 1;
            imageBarrier(cmd, image, toReadDst);
        });
    } catch (...) {
        destroyBuffer(ctx, staging);
        throw;
    }
    destroyBuffer(ctx, staging);
}

void uploadImageMips(const Context& ctx, Image& image, std::span<const uint8_t> bytes) {
    const ImageDesc& d = image.desc;
    std::vector<VkBufferImageCopy> copies;
    VkDeviceSize offset = 0;
    for (uint32_t mip = 0; mip < d.mipLevels; ++mip) {
        const uint32_t w = std::max(d.width >> mip, 1u), h = std::max(d.height >> mip, 1u);
        VkBufferImageCopy copy{};
        copy.bufferOffset = offset;
        copy.imageSubresource = {aspectOf(d.format), mip, 0, d.layers};
        copy.imageExtent = {w, h, 1};
        copies.push_back(copy);
        offset += VkDeviceSize(w) * h * d.layers * bytesPerTexel(d.format);
    }
    if (bytes.size() != offset)
        throw std::runtime_error("uploadImageMips: " + std::to_string(bytes.size()) +
                                 " bytes given, " + std::to_string(offset) + " expected");
    Buffer staging;
    createHostBuffer(ctx, staging, offset, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memcpy(staging.mapped, bytes.data(), bytes.size());
    try {
        submitOnce(ctx, [&](VkCommandBuffer cmd) {
            imageBarrier(
                cmd, image,
                layoutBarrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                              VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                              VK_ACCESS_TRANSFER_WRITE_BIT));
            vkCmdCopyBufferToImage(cmd, staging.buffer, image.image,
                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, uint32_t(copies.size()),
                                   copies.data());
            imageBarrier(
                cmd, image,
                layoutBarrier(VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                              VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                              VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT));
        });
    } catch (...) {
        destroyBuffer(ctx, staging);
        throw;
    }
    destroyBuffer(ctx, staging);
}

VkSampler createSampler(const Context& ctx, const SamplerDesc& desc) {
    VkSamplerCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
    info.magFilter = desc.magFilter;
    info.minFilter = desc.minFilter;
    info.mipmapMode = desc.mipmapMode;
    info.addressModeU = desc.addressU;
    info.addressModeV = desc.addressV;
    info.addressModeW = desc.addressW;
    info.anisotropyEnable = desc.maxAnisotropy > 1.0f ? VK_TRUE : VK_FALSE;
    info.maxAnisotropy = std::max(desc.maxAnisotropy, 1.0f);
    info.compareEnable = desc.compare ? VK_TRUE : VK_FALSE;
    info.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    info.minLod = 0.0f;
    info.maxLod = desc.maxLod;
    info.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
    VkSampler sampler = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSampler(ctx.device, &info, nullptr, &sampler));
    return sampler;
}

}  // namespace onelight::vk
