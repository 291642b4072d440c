#include "platform/window.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "vk/vk_check.hpp"

namespace onelight::platform {

void openWindow(Window& window, const char* title, uint32_t width, uint32_t height) {
    if (!glfwInit()) {
        const char* why = nullptr;
        glfwGetError(&why);
        throw std::runtime_error(std::string("cannot initialise GLFW (") +
                                 (why ? why : "no display?") + ")");
    }
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw std::runtime_error("GLFW finds no Vulkan loader");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window.window = glfwCreateWindow(int(width), int(height), title, nullptr, nullptr);
    if (!window.window) {
        const char* why = nullptr;
        glfwGetError(&why);
        glfwTerminate();
        throw std::runtime_error(std::string("cannot open a window (") + (why ? why : "unknown") +
                                 ")");
    }
}

std::vector<const char*> windowInstanceExtensions() {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    return std::vector<const char*>(names, names + count);
}

void framebufferSize(const Window& window, uint32_t& width, uint32_t& height) {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window.window, &w, &h);
    width = uint32_t(std::max(w, 0));
    height = uint32_t(std::max(h, 0));
}

void createWindowSwapchain(Window& window, const vk::Context& ctx) {
    VK_CHECK(glfwCreateWindowSurface(ctx.instance, window.window, nullptr, &window.surface));
    recreateWindowSwapchain(window, ctx);
}

void recreateWindowSwapchain(Window& window, const vk::Context& ctx) {
    VK_CHECK(vkDeviceWaitIdle(ctx.device));
    uint32_t width = 0, height = 0;
    framebufferSize(window, width, height);
    vk::createSwapchain(ctx, window.swapchain, window.surface, width, height);
}

void closeWindow(Window& window, const vk::Context& ctx) {
    if (ctx.device) vkDeviceWaitIdle(ctx.device);
    vk::destroySwapchain(ctx, window.swapchain);
    if (window.surface) vkDestroySurfaceKHR(ctx.instance, window.surface, nullptr);
    window.surface = VK_NULL_HANDLE;
    if (window.window) glfwDestroyWindow(window.window);
    window.window = nullptr;
    glfwTerminate();
}

}  // namespace onelight::platform
