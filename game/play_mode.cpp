#include "play_mode.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "ecs/schedule.hpp"
#include "render_target.hpp"
#include "session.hpp"

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

// The window's title: the level, twice a second the mean frame time, frames per second and GPU
// time over the frames since the last update, and the frame's size and render scale.
struct FrameRateTitle {
    std::string level;
    std::string frameSize;  // e.g. "640x360 at render scale 0.50"
    std::chrono::steady_clock::time_point since{};
    uint32_t frames = 0;
    double gpuMs = 0.0;

    void add(GLFWwindow* window, std::chrono::steady_clock::time_point now, double frameGpuMs) {
        if (frames == 0 && since == std::chrono::steady_clock::time_point{}) since = now;
        ++frames;
        gpuMs += frameGpuMs;
        const double seconds = std::chrono::duration<double>(now - since).count();
        if (seconds < 0.5) return;
        char text[512];
        std::snprintf(text, sizeof text, "onelight - %s - %.1f ms (%.1f fps), GPU %.1f ms - %s",
                      level.c_str(), 1000.0 * seconds / frames, frames / seconds, gpuMs / frames,
                      frameSize.c_str());
        glfwSetWindowTitle(window, text);
        since = now;
        frames = 0;
        gpuMs = 0.0;
    }
};

}  // namespace

int runPlay(const CommandLine& cl, const assets::LoadedLevel& level) {
    RenderTarget target;
    openRenderTarget(target, cl, level, true);
    Session session;
    startSession(session, level);
    session.fixedExposure = cl.hasEv100;
    session.ev100 = cl.ev100;
    session.secondaryLux = std::max(render::rendererInfo(target.renderer).ambientLux, 1.0f);
    char frameSize[96];
    std::snprintf(frameSize, sizeof frameSize, "%ux%u at render scale %.2f", target.frameWidth,
                  target.frameHeight, double(target.renderScale));
    std::printf("onelight: playing %s, window %ux%u, frame %s, MSAA %ux\n", level.path.c_str(),
                target.window.swapchain.extent.width, target.window.swapchain.extent.height,
                frameSize, render::rendererInfo(target.renderer).msaaInUse);
    std::fflush(stdout);
    try {
        if (cl.frames == 0)
            glfwSetInputMode(target.window.window, GLFW_CURSOR, GLFW_CURSOR_DISABLED);
        InputReader reader;
        ecs::FixedClock clock;
        clock.tickSeconds = session.tickSeconds;
        std::vector<render::DynamicTransform> transforms;
        auto last = std::chrono::steady_clock::now();
        FrameRateTitle title{level.path, frameSize};
        for (uint32_t frame = 0; !targetWantsToClose(target); ++frame) {
            auto now = std::chrono::steady_clock::now();
            int ticks = clock.advance(std::chrono::duration<double>(now - last).count());
            last = now;
            reader.read(target.window.window, session.input);
            for (int t = 0; t < std::max(ticks, frame == 0 ? 1 : 0); ++t) stepSession(session);
            const render::FrameStats stats =
                drawToTarget(target, frameInputsOf(session, transforms), false);
            title.add(target.window.window, now, stats.gpuMs);
            if (cl.frames > 0 && frame + 1 >= cl.frames) break;
        }
    } catch (...) {
        closeRenderTarget(target);
        throw;
    }
    if (uint32_t errors = closeRenderTarget(target)) {
        std::fprintf(stderr, "onelight: %u Vulkan validation errors\n", errors);
        return 1;
    }
    return 0;
}

}  // namespace onelight::game
