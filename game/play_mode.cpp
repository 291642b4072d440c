#include "play_mode.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>

#include "ecs/schedule.hpp"
#include "platform/window.hpp"
#include "session.hpp"
#include "vk/context.hpp"

namespace onelight::game {

namespace {

constexpr float kMouseDegreesPerPixel = 0.12f;

// Held keys, mouse look and the one-shot presses of this frame, into the session's input.
struct InputReader {
    double lastX = 0.0, lastY = 0.0;
    bool first = true, flashlightWasDown = false, fireWasDown = false;

    void read(GLFWwindow* window, InputState& input) {
        static const std::pair<int, const char*> keys[] = {
            {GLFW_KEY_W, "W"}, {GLFW_KEY_A, "A"},         {GLFW_KEY_S, "S"},
            {GLFW_KEY_D, "D"}, {GLFW_KEY_SPACE, "SPACE"}, {GLFW_KEY_LEFT_SHIFT, "SHIFT"}};
        for (auto [code, name] : keys) {
            if (glfwGetKey(window, code) == GLFW_PRESS) {
                input.keysDown.insert(name);
            } else {
                input.keysDown.erase(name);
            }
        }
        double x, y;
        glfwGetCursorPos(window, &x, &y);
        if (!first) {
            input.lookYawDegrees -= float(x - lastX) * kMouseDegreesPerPixel;
            input.lookPitchDegrees -= float(y - lastY) * kMouseDegreesPerPixel;
        }
        first = false;
        lastX = x, lastY = y;
        bool flashlightDown = glfwGetKey(window, GLFW_KEY_F) == GLFW_PRESS;
        if (flashlightDown && !flashlightWasDown) input.toggleFlashlight = true;
        flashlightWasDown = flashlightDown;
        bool fireDown = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        if (fireDown && !fireWasDown) input.fire = true;
        fireWasDown = fireDown;
    }
};

}  // namespace

int runPlay(const CommandLine& cl, const assets::LoadedLevel& level) {
    platform::Window window;
    std::string error;
    if (!platform::openWindow(window, "onelight", cl.width, cl.height, error)) {
        std::fprintf(stderr, "onelight: %s\n", error.c_str());
        return 1;
    }
    render::RenderDeviceFeatures features;
    vk::Context ctx;
    render::Renderer renderer;
    Session session;
    startSession(session, level);
    try {
        vk::createContext(
            ctx, render::renderContextOptions(features, platform::windowInstanceExtensions()));
        platform::createWindowSwapchain(window, ctx);
        render::RendererOptions options;
        options.width = window.swapchain.extent.width;
        options.height = window.swapchain.extent.height;
        options.requestedMsaa = cl.msaa;
        render::createRenderer(renderer, ctx, level, options);
        session.secondaryLux = std::max(render::rendererInfo(renderer).ambientLux, 1.0f);
        std::printf("onelight: playing %s, %ux%u, MSAA %ux\n", level.path.c_str(), options.width,
                    options.height, render::rendererInfo(renderer).msaaInUse);
        std::fflush(stdout);
        if (cl.frames == 0) glfwSetInputMode(window.window, GLFW_CURSOR, GLFW_CURSOR_DISABLED);

        InputReader reader;
        ecs::FixedClock clock;
        clock.tickSeconds = session.tickSeconds;
        std::vector<render::DynamicTransform> transforms;
        auto last = std::chrono::steady_clock::now();
        for (uint32_t frame = 0; !glfwWindowShouldClose(window.window); ++frame) {
            glfwPollEvents();
            if (glfwGetKey(window.window, GLFW_KEY_ESCAPE) == GLFW_PRESS) break;
            auto now = std::chrono::steady_clock::now();
            int ticks = clock.advance(std::chrono::duration<double>(now - last).count());
            last = now;
            reader.read(window.window, session.input);
            for (int t = 0; t < std::max(ticks, frame == 0 ? 1 : 0); ++t) stepSession(session);

            int image = vk::acquireNextImage(ctx, window.swapchain);
            if (image < 0) {
                platform::recreateWindowSwapchain(window, ctx);
                render::resizeRenderer(renderer, window.swapchain.extent.width,
                                       window.swapchain.extent.height);
                continue;
            }
            render::FrameOutput out;
            out.swapchain = &window.swapchain;
            out.swapchainImage = uint32_t(image);
            render::drawFrame(renderer, frameInputsOf(session, transforms), out);
            if (!vk::presentImage(ctx, window.swapchain, uint32_t(image))) {
                platform::recreateWindowSwapchain(window, ctx);
                render::resizeRenderer(renderer, window.swapchain.extent.width,
                                       window.swapchain.extent.height);
            }
            if (cl.frames > 0 && frame + 1 >= cl.frames) break;
        }
    } catch (...) {
        render::destroyRenderer(renderer);
        platform::closeWindow(window, ctx);
        vk::destroyContext(ctx);
        throw;
    }
    render::destroyRenderer(renderer);
    platform::closeWindow(window, ctx);
    vk::destroyContext(ctx);
    if (ctx.validationCounts.errors.load() > 0) {
        std::fprintf(stderr, "onelight: %u Vulkan validation errors\n",
                     unsigned(ctx.validationCounts.errors.load()));
        return 1;
    }
    return 0;
}

}  // namespace onelight::game
