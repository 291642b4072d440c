#include "render_target.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

namespace onelight::game {

void openRenderTarget(RenderTarget& t, const CommandLine& cl, const assets::LoadedLevel& level,
                      bool windowed) {
    t.windowed = windowed;
    if (windowed) platform::openWindow(t.window, "onelight", cl.width, cl.height);
    render::RenderDeviceFeatures features;
    try {
        vk::createContext(t.ctx, render::renderContextOptions(
                                     features, windowed ? platform::windowInstanceExtensions()
                                                        : std::vector<const char*>{}));
        if (windowed) platform::createWindowSwapchain(t.window, t.ctx);
        render::RendererOptions options;
        options.width = windowed ? t.window.swapchain.extent.width : cl.width;
        options.height = windowed ? t.window.swapchain.extent.height : cl.height;
        options.requestedMsaa = cl.msaa;
        options.visibilityCulling = cl.visibilityCulling;
        render::createRenderer(t.renderer, t.ctx, level, options);
    } catch (...) {
        closeRenderTarget(t);
        throw;
    }
}

render::FrameStats drawToTarget(RenderTarget& t, const render::FrameInputs& inputs, bool readback,
                                bool readbackSwapchain) {
    render::FrameOutput out;
    out.readback = readback;
    int image = -1;
    if (t.windowed) {
        image = vk::acquireNextImage(t.ctx, t.window.swapchain);
        if (image < 0) {
            platform::recreateWindowSwapchain(t.window, t.ctx);
            render::resizeRenderer(t.renderer, t.window.swapchain.extent.width,
                                   t.window.swapchain.extent.height);
            image = vk::acquireNextImage(t.ctx, t.window.swapchain);
        }
        if (image >= 0) {
            out.swapchain = &t.window.swapchain;
            out.swapchainImage = uint32_t(image);
            out.readbackSwapchain = readbackSwapchain;
        }
    }
    render::FrameStats stats = render::drawFrame(t.renderer, inputs, out);
    if (image >= 0 && !vk::presentImage(t.ctx, t.window.swapchain, uint32_t(image))) {
        platform::recreateWindowSwapchain(t.window, t.ctx);
        render::resizeRenderer(t.renderer, t.window.swapchain.extent.width,
                               t.window.swapchain.extent.height);
    }
    return stats;
}

bool targetWantsToClose(RenderTarget& t) {
    if (!t.windowed) return false;
    glfwPollEvents();
    return glfwWindowShouldClose(t.window.window) ||
           glfwGetKey(t.window.window, GLFW_KEY_ESCAPE) == GLFW_PRESS;
}

uint32_t closeRenderTarget(RenderTarget& t) {
    render::destroyRenderer(t.renderer);
    if (t.windowed) platform::closeWindow(t.window, t.ctx);
    vk::destroyContext(t.ctx);
    return uint32_t(t.ctx.validationCounts.errors.load());
}

}  // namespace onelight::game
