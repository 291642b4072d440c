// A swapchain on a surface: B8G8R8A8_UNORM images usable as copy destinations and sources (the
// frame is copied in; a screenshot can be copied out), FIFO presentation.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "vk/context.hpp"

namespace onelight::vk {

struct Swapchain {
    VkSurfaceKHR surface = VK_NULL_HANDLE;      // borrowed from the window
    VkSwapchainKHR swapchain = VK_NULL_HANDLE;  // owned
    std::vector<VkImage> images;                // borrowed from swapchain
    VkFormat format = VK_FORMAT_B8G8R8A8_UNORM;
    VkExtent2D extent{};
    // Acquire signals the next semaphore of a ring of images + 1, so that with frames in flight
    // a semaphore is reused only after the frame that waited on it has finished.
    std::vector<VkSemaphore> acquireRing;    // owned
    uint32_t nextAcquire = 0;                // into acquireRing
    std::vector<VkSemaphore> imageAcquired;  // per image: borrowed from acquireRing, signalled by
                                             // the acquire that returned it, waited by its frame
    std::vector<VkSemaphore> frameCopied;    // owned, per image: signalled by the frame that
                                             // fills it, waited by its present

    Swapchain() = default;
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;
};

// Creates (or, when swapchain.swapchain exists, recreates) the swapchain of `surface` at the
// surface's current extent, or width x height when the surface leaves it to the application.
// Throws when the queue cannot present to the surface or B8G8R8A8_UNORM is not offered.
void createSwapchain(const Context& ctx, Swapchain& swapchain, VkSurfaceKHR surface, uint32_t width,
                     uint32_t height);

// Destroys the semaphores and the swapchain (not the surface).
void destroySwapchain(const Context& ctx, Swapchain& swapchain);

// The index of the next image, signalling swapchain.imageAcquired[index]; -1 when the swapchain is
// out of date and must be recreated.
[[nodiscard]] int acquireNextImage(const Context& ctx, Swapchain& swapchain);

// Presents image `index` after swapchain.frameCopied[index]. False when out of date or
// suboptimal.
[[nodiscard]] bool presentImage(const Context& ctx, Swapchain& swapchain, uint32_t index);

}  // namespace onelight::vk
