// What every mode of `onelight` draws with: the Vulkan context, the window and its swapchain
// when there is one, and the renderer, created together and destroyed in reverse order.
#pragma once

#include <string>

#include "assets/level_assets.hpp"
#include "command_line.hpp"
#include "platform/window.hpp"
#include "render/renderer.hpp"
#include "vk/context.hpp"

namespace onelight::game {

struct RenderTarget {
    bool windowed = false;
    float renderScale = 1.0f;  // the frame's size over the window's (windowed; 1 headless)
    uint32_t frameWidth = 0, frameHeight = 0;  // the renderer's frame, in pixels
    platform::Window window;                   // owned, open when windowed
    vk::Context ctx;                           // owned
    std::string pipelineCachePath;             // game/pipeline_cache_file.hpp; empty: none
    size_t pipelineCacheLoaded = 0;            // bytes the cache started from
    render::Renderer renderer;                 // owned
};

// Opens the window (when `windowed`), the context and the renderer at the command line's size
// and MSAA. Throws when there is no display or on Vulkan failures (after releasing what it
// created).
void openRenderTarget(RenderTarget& target, const CommandLine& commandLine,
                      const assets::LoadedLevel& level, bool windowed);

// Draws one frame, into the window when there is one (acquiring, presenting, and following a
// resized swapchain), and reads it back when asked. `presented` tells whether the window showed it.
render::FrameStats drawToTarget(RenderTarget& target, const render::FrameInputs& inputs,
                                bool readback, bool readbackSwapchain = false);

// Whether the window was asked to close (Esc or the close button); false headless.
[[nodiscard]] bool targetWantsToClose(RenderTarget& target);

// Destroys in reverse creation order; returns the Vulkan validation errors counted meanwhile.
uint32_t closeRenderTarget(RenderTarget& target);

}  // namespace onelight::game
