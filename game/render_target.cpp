#include "render_target.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pipeline_cache_file.hpp"

namespace onelight::game {

namespace {

// The render scale in use: the command line's, else 0.5 on a CPU device (lavapipe draws every
// pixel on the cores) and 1 on a GPU; 1 when the display format cannot be scaled by a blit.
float chooseRenderScale(const vk::Context& ctx, float requested, VkFormat format) {
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(ctx.physicalDevice, format, &props);
    const VkFormatFeatureFlags blit = VK_FORMAT_FEATURE_BLIT_SRC_BIT |
                                      VK_FORMAT_FEATURE_BLIT_DST_BIT |
                                      VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
    if ((props.optimalTilingFeatures & blit) != blit) return 1.0f;
    if (requested > 0.0f) return requested;
    return ctx.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 0.5f : 1.0f;
}

uint32_t scaled(uint32_t size, float scale) {
    return std::max(1u, uint32_t(std::lround(double(size) * double(scale))));
}

void resizeToWindow(RenderTarget& t) {
    platform::recreateWindowSwapchain(t.window, t.ctx);
    t.frameWidth = scaled(t.window.swapchain.extent.width, t.renderScale);
    t.frameHeight = scaled(t.window.swapchain.extent.height, t.renderScale);
    render::resizeRenderer(t.renderer, t.frameWidth, t.frameHeight);
}

}  // namespace

void openRenderTarget(RenderTarget& t, const CommandLine& cl, const assets::LoadedLevel& level,
                      bool windowed) {
    t.windowed = windowed;
    if (windowed) platform::openWindow(t.window, "onelight", cl.width, cl.height);
    render::RenderDeviceFeatures features;
    try {
        vk::createContext(t.ctx, render::renderContextOptions(
                                     features, windowed ? platform::windowInstanceExtensions()
                                                        : std::vector<const char*>{}));
        t.pipelineCachePath = pipelineCachePath();
        t.pipelineCacheLoaded = openPipelineCache(t.ctx, t.pipelineCachePath);
        render::RendererOptions options;
        options.width = cl.width;
        options.height = cl.height;
        if (windowed) {
            platform::createWindowSwapchain(t.window, t.ctx);
            t.renderScale = chooseRenderScale(t.ctx, cl.renderScale, t.window.swapchain.format);
            options.width = scaled(t.window.swapchain.extent.width, t.renderScale);
            options.height = scaled(t.window.swapchain.extent.height, t.renderScale);
        }
        options.requestedMsaa = cl.msaa;
        options.anisotropy = float(cl.anisotropy);
        // Measured on Mesa 22.3's lavapipe: a 400 m floor to the horizon, normal-mapped, took over
        // 100 s a frame at 320x180 with 4 taps (0.8 s with 1; 0.5 s at 64x36 with 16), its
        // threads inside the sampler's code. The option is kept, and said to be slow there.
        if (cl.anisotropy > 1 && t.ctx.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU)
            std::fprintf(stderr,
                         "onelight: warning: --anisotropy %u on a CPU device (%s): its anisotropic "
                         "filter can take minutes a frame on surfaces seen at grazing angles\n",
                         cl.anisotropy, t.ctx.properties.deviceName);
        options.fxaa = cl.fxaa;
        options.probesPerNormal = cl.probesPerNormal;
        options.visibilityCulling = cl.visibilityCulling;
        options.flatShading = options.rasterFloor = cl.rasterFloor;
        options.shadowMapSize = cl.shadowMapSize;
        options.sunCascades = cl.sunCascades;
        options.shadowRadius = cl.shadowDistance;
        options.probes = cl.probes;
        t.frameWidth = options.width;
        t.frameHeight = options.height;
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
            resizeToWindow(t);
            image = vk::acquireNextImage(t.ctx, t.window.swapchain);
        }
        if (image >= 0) {
            out.swapchain = &t.window.swapchain;
            out.swapchainImage = uint32_t(image);
            out.readbackSwapchain = readbackSwapchain;
        }
    }
    render::FrameStats stats = render::drawFrame(t.renderer, inputs, out);
    if (image >= 0 && !vk::presentImage(t.ctx, t.window.swapchain, uint32_t(image)))
        resizeToWindow(t);
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
    if (t.ctx.device) keepPipelineCache(t.ctx, t.pipelineCachePath, t.pipelineCacheLoaded);
    if (t.windowed) platform::closeWindow(t.window, t.ctx);
    vk::destroyContext(t.ctx);
    return uint32_t(t.ctx.validationCounts.errors.load());
}

}  // namespace onelight::game
