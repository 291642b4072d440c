// A GLFW window with a Vulkan surface and swapchain (works under Xvfb). The headless backend
// needs no platform object: the renderer reads its frame back (render::FrameOutput::readback).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/context.hpp"
#include "vk/swapchain.hpp"

struct GLFWwindow;

namespace onelight::platform {

struct Window {
    GLFWwindow* window = nullptr;           // owned
    VkSurfaceKHR surface = VK_NULL_HANDLE;  // owned, on the context's instance
    vk::Swapchain swapchain;                // owned

    Window() = default;
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;
};

/// Initialises GLFW and opens a window without a client API. Call before createContext (the
/// context needs windowInstanceExtensions). Throws std::runtime_error when there is no display.
void openWindow(Window& window, const char* title, uint32_t width, uint32_t height);

/// The instance extensions Vulkan needs to present to GLFW windows.
std::vector<const char*> windowInstanceExtensions();

/// Creates the surface and the swapchain on `ctx`.
void createWindowSwapchain(Window& window, const vk::Context& ctx);

/// Recreates the swapchain at the window's current framebuffer size (after a resize).
void recreateWindowSwapchain(Window& window, const vk::Context& ctx);

/// Framebuffer size in pixels.
void framebufferSize(const Window& window, uint32_t& width, uint32_t& height);

/// Destroys swapchain, surface and window (in that order) and terminates GLFW.
void closeWindow(Window& window, const vk::Context& ctx);

}  // namespace onelight::platform
