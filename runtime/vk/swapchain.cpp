#include "vk/swapchain.hpp"

#include <algorithm>
#include <stdexcept>

#include "vk/commands.hpp"
#include "vk/vk_check.hpp"

namespace onelight::vk {

namespace {

void destroySemaphores(const Context& ctx, Swapchain& swapchain) {
    for (VkSemaphore semaphore : swapchain.acquireRing)
        vkDestroySemaphore(ctx.device, semaphore, nullptr);
    for (VkSemaphore semaphore : swapchain.frameCopied)
        vkDestroySemaphore(ctx.device, semaphore, nullptr);
    swapchain.acquireRing.clear();
    swapchain.frameCopied.clear();
    swapchain.imageAcquired.clear();
}

}  // namespace

void createSwapchain(const Context& ctx, Swapchain& swapchain, VkSurfaceKHR surface, uint32_t width,
                     uint32_t height) {
    VkBool32 canPresent = VK_FALSE;
    VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(ctx.physicalDevice, ctx.queueFamily, surface,
                                                  &canPresent));
    if (!canPresent) throw std::runtime_error("the Vulkan queue cannot present to the window");

    uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(ctx.physicalDevice, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VK_CHECK(
        vkGetPhysicalDeviceSurfaceFormatsKHR(ctx.physicalDevice, surface, &count, formats.data()));
    bool found = false;
    for (const VkSurfaceFormatKHR& f : formats)
        found = found || (f.format == VK_FORMAT_B8G8R8A8_UNORM &&
                          f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR);
    if (!found) throw std::runtime_error("the window offers no B8G8R8A8_UNORM swapchain format");

    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx.physicalDevice, surface, &caps));
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == 0xFFFFFFFFu) {
        extent.width = std::clamp(width, caps.minImageExtent.width, caps.maxImageExtent.width);
        extent.height = std::clamp(height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    uint32_t imageCount = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) imageCount = std::min(imageCount, caps.maxImageCount);

    VkSwapchainKHR old = swapchain.swapchain;
    VkSwapchainCreateInfoKHR info{};
    info.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR;
    info.surface = surface;
    info.minImageCount = imageCount;
    info.imageFormat = VK_FORMAT_B8G8R8A8_UNORM;
    info.imageColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    info.imageExtent = extent;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always supported
    info.clipped = VK_TRUE;
    info.oldSwapchain = old;
    VK_CHECK(vkCreateSwapchainKHR(ctx.device, &info, nullptr, &swapchain.swapchain));
    if (old) vkDestroySwapchainKHR(ctx.device, old, nullptr);

    swapchain.surface = surface;
    swapchain.extent = extent;
    VK_CHECK(vkGetSwapchainImagesKHR(ctx.device, swapchain.swapchain, &count, nullptr));
    swapchain.images.resize(count);
    VK_CHECK(
        vkGetSwapchainImagesKHR(ctx.device, swapchain.swapchain, &count, swapchain.images.data()));

    destroySemaphores(ctx, swapchain);  // the old ones may count other images
    for (uint32_t i = 0; i <= count; ++i) swapchain.acquireRing.push_back(createSemaphore(ctx));
    for (uint32_t i = 0; i < count; ++i) swapchain.frameCopied.push_back(createSemaphore(ctx));
    swapchain.imageAcquired.assign(count, VK_NULL_HANDLE);
    swapchain.nextAcquire = 0;
}

void destroySwapchain(const Context& ctx, Swapchain& swapchain) {
    destroySemaphores(ctx, swapchain);
    swapchain.images.clear();
    if (swapchain.swapchain) vkDestroySwapchainKHR(ctx.device, swapchain.swapchain, nullptr);
    swapchain.swapchain = VK_NULL_HANDLE;
}

int acquireNextImage(const Context& ctx, Swapchain& swapchain) {
    uint32_t index = 0;
    const VkSemaphore signal = swapchain.acquireRing[swapchain.nextAcquire];
    const VkResult result = vkAcquireNextImageKHR(ctx.device, swapchain.swapchain, UINT64_MAX,
                                                  signal, VK_NULL_HANDLE, &index);
    if (result == VK_ERROR_OUT_OF_DATE_KHR) return -1;
    if (result != VK_SUBOPTIMAL_KHR) VK_CHECK(result);
    swapchain.nextAcquire = (swapchain.nextAcquire + 1) % uint32_t(swapchain.acquireRing.size());
    swapchain.imageAcquired.at(index) = signal;
    return int(index);
}

bool presentImage(const Context& ctx, Swapchain& swapchain, uint32_t index) {
    VkPresentInfoKHR info{};
    info.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR;
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &swapchain.frameCopied.at(index);
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain.swapchain;
    info.pImageIndices = &index;
    const VkResult result = vkQueuePresentKHR(ctx.queue, &info);
    if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) return false;
    VK_CHECK(result);
    return true;
}

}  // namespace onelight::vk
