// onelight LEVEL [--headless] [--size WxH] [--camera NAME|x,y,z,yaw,pitch] [--capture out/NAME]
//                [--replay SCRIPT --capture-dir DIR]
// Renders a level package (compiling and baking a glTF level first when needed) in a window
// with a free-fly camera, or one frame headless with its capture files; with --replay it plays
// the game from a replay script (replay_mode.hpp).
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "capture/capture.hpp"
#include "command_line.hpp"
#include "free_fly.hpp"
#include "level_source.hpp"
#include "lighting_view.hpp"
#include "platform/window.hpp"
#include "play_mode.hpp"
#include "render/renderer.hpp"
#include "render_target.hpp"
#include "replay_mode.hpp"
#include "session.hpp"
#include "vk/context.hpp"
#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/images/image_files.hpp"

namespace {

using namespace onelight;

int fail(const std::string& message) {
    std::fprintf(stderr, "onelight: %s\n", world::oneLineMessage(message).c_str());
    return 1;
}

// --camera NAME | x,y,z,yaw,pitch; empty: the level's first camera, else a view of the bounds.
render::Camera resolveCamera(const game::CommandLine& cl, const assets::LoadedLevel& level) {
    const world::CompiledLevel& l = level.level;
    if (cl.camera.empty()) {
        if (!l.cameras.empty()) return render::cameraFromLevel(l.cameras.front());
        const glm::vec3 centre = 0.5f * (l.settings.boundsMin + l.settings.boundsMax);
        const float radius =
            std::max(0.5f * glm::length(l.settings.boundsMax - l.settings.boundsMin), 0.5f);
        return render::cameraFromYawPitch(centre + glm::vec3(0.0f, 0.35f, 1.2f) * radius, 0.0f,
                                          -16.26f);
    }
    std::vector<float> numbers;
    std::stringstream in(cl.camera);
    std::string part;
    bool numeric = true;
    while (std::getline(in, part, ',')) {
        try {
            size_t used = 0;
            numbers.push_back(std::stof(part, &used));
            numeric = numeric && used == part.size() && std::isfinite(numbers.back());
        } catch (const std::exception&) {
            numeric = false;
        }
    }
    if (numeric && numbers.size() == 5) {
        for (int i = 0; i < 5; ++i)
            if (!(std::fabs(numbers[size_t(i)]) <= (i < 3 ? 1e6f : 36000.0f)))
                throw world::Error("--camera '" + world::clipForMessage(cl.camera) +
                                   "': expected x,y,z within 1e6 m and yaw,pitch within 36000 "
                                   "degrees (docs/limits.md)");
    }
    if (numeric && numbers.size() == 5)
        return render::cameraFromYawPitch({numbers[0], numbers[1], numbers[2]}, numbers[3],
                                          numbers[4]);
    std::string names;
    for (const world::Camera& c : l.cameras) {
        if (c.name == cl.camera) return render::cameraFromLevel(c);
        names += (names.empty() ? "" : ", ") + c.name;
    }
    throw world::Error(level.path + ": no camera '" + cl.camera +
                       "'; expected x,y,z,yaw,pitch or one of: " +
                       (names.empty() ? std::string("(the level has no cameras)") : names));
}

render::EffectLights effectsFor(const game::CommandLine& cl, const render::Camera& camera) {
    render::EffectLights fx;
    if (cl.flashlight) {
        fx.spotOn = true;
        fx.spot.position = camera.position;
        fx.spot.direction = render::forwardOf(camera);
        fx.spot.intensity = 300.0f;
        fx.spot.range = 30.0f;
        fx.spot.innerCone = glm::radians(15.0f);
        fx.spot.outerCone = glm::radians(25.0f);
    }
    return fx;
}

// The median of the frames' GPU times (0 when none was timed).
double medianMs(std::vector<double> ms) {
    if (ms.empty()) return 0.0;
    std::sort(ms.begin(), ms.end());
    const size_t n = ms.size();
    return n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
}

// What the package's error budget left out (onelight-bake --error-budget): the renderer honours
// it by what the package holds (no probe: the shader permutation without probes).
void printErrorBudget(const assets::LoadedLevel& level) {
    const world::ErrorBudgetChoices& b = level.baked.budget;
    if (!(b.budget > 0.0f)) return;
    const bool dropped = (b.flags & world::kBudgetProbesDropped) != 0;
    std::printf(
        "onelight: baked with an error budget of %.1f%% (predicted %.2f%%): probes %s, %u of %u "
        "lightmap texels, %u of %u grid cells\n",
        100.0 * double(b.budget), 100.0 * double(b.predictedError),
        dropped ? "dropped (a uniform environment)" : (b.probesPlaced ? "kept" : "none"),
        b.texelsSampled, b.texelsRequested, b.gridCells, b.gridCellsFull);
}

/// Times of a bounded run: the renderer's creation (pipelines warmed included) and each drawn
/// frame's GPU time and wall time (the caller waits for every frame headless).
struct RunTimes {
    double openMs = 0.0;
    std::vector<double> gpuMs, wallMs;
};

// The dynamic objects drawn, each as its entity (index and name) and world-from-object matrix
// (column-major), so that `onelight-bake reference --poses` traces them where the frame drew
// them (bake/reference/frame_poses.hpp).
nlohmann::json drawnDynamicObjects(const assets::LoadedLevel& level,
                                   const std::vector<render::DynamicTransform>& objects) {
    nlohmann::json list = nlohmann::json::array();
    for (const render::DynamicTransform& o : objects) {
        if (o.hidden || o.entity >= level.level.entities.size()) continue;
        nlohmann::json matrix = nlohmann::json::array();
        for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 4; ++row) matrix.push_back(o.worldFromObject[column][row]);
        list.push_back({{"entity", o.entity},
                        {"name", level.level.entities[o.entity].name},
                        {"world_from_object", matrix}});
    }
    return list;
}

// `times`: every drawn frame's, the last one included.
nlohmann::json sidecar(const game::CommandLine& cl, const assets::LoadedLevel& level,
                       const render::Renderer& renderer, const render::Camera& camera,
                       const render::FrameStats& stats, const char* backend, const RunTimes& times,
                       const std::vector<render::DynamicTransform>& dynamicObjects) {
    const render::RendererInfo& info = render::rendererInfo(renderer);
    const glm::vec3 f = render::forwardOf(camera);
    nlohmann::json j;
    j["level"] = level.path;
    j["backend"] = backend;
    j["device"] = info.deviceName;
    j["size"] = {render::capturedFrame(renderer).width, render::capturedFrame(renderer).height};
    j["camera"] = {{"argument", cl.camera},
                   {"position", {camera.position.x, camera.position.y, camera.position.z}},
                   {"rotation_xyzw",
                    {camera.rotation.x, camera.rotation.y, camera.rotation.z, camera.rotation.w}},
                   {"forward", {f.x, f.y, f.z}},
                   {"yfov", camera.yfov},
                   {"ev100", stats.ev100},
                   {"exposure", stats.exposure}};
    j["msaa"] = {{"requested", info.msaaRequested}, {"in_use", info.msaaInUse}};
    j["timings_ms"] = {
        {"cpu", stats.cpuMs},
        {"gpu", stats.gpuMs},
        {"gpu_shadows", stats.gpuShadowMs},
        {"gpu_forward", stats.gpuForwardMs},
        {"gpu_tonemap", stats.gpuTonemapMs},
        {"gpu_timestamps", stats.gpuTimestamps},
        {"frames", times.wallMs.size()},
        {"gpu_median", medianMs(times.gpuMs)},
        // The first frame after load, and the median of those after it: the
        // first-frame stall is their ratio.
        {"renderer_create", times.openMs},
        {"renderer_warm_up", info.warmUpMs},  // part of renderer_create
        {"first_frame_wall", times.wallMs.empty() ? 0.0 : times.wallMs.front()},
        {"wall_median_after_first",
         medianMs(times.wallMs.size() > 1
                      ? std::vector<double>(times.wallMs.begin() + 1, times.wallMs.end())
                      : times.wallMs)}};
    j["frame"] = {{"surfaces_drawn", stats.surfacesDrawn},
                  {"draws", stats.draws},
                  {"surfaces_culled", stats.surfacesCulled},
                  {"surfaces_hidden_by_visibility", stats.surfacesHidden},
                  {"dynamic_meshes_drawn", stats.dynamicMeshesDrawn},
                  {"shadow_views_rendered", stats.shadowViewsRendered},
                  {"triangles", stats.trianglesDrawn}};
    j["dynamic_objects"] = drawnDynamicObjects(level, dynamicObjects);
    j["permutations"] = info.permutations;
    j["placeholder_ambient_lux"] = info.ambientLux;
    j["probes_in_use"] = info.probes;
    const world::ErrorBudgetChoices& budget = level.baked.budget;
    if (budget.budget > 0.0f)
        j["error_budget"] = {{"budget", budget.budget},
                             {"probes_dropped", (budget.flags & world::kBudgetProbesDropped) != 0},
                             {"probe_error", budget.probeError},
                             {"grid_cells", budget.gridCells},
                             {"grid_cells_full", budget.gridCellsFull},
                             {"texels_sampled", budget.texelsSampled},
                             {"texels_requested", budget.texelsRequested},
                             {"predicted_error", budget.predictedError}};
    return j;
}

// One frame, headless (and its capture files), or a free-fly camera in a window.
int runViewer(const game::CommandLine& cl, const assets::LoadedLevel& level,
              render::Camera camera) {
    game::RenderTarget target;
    RunTimes times;
    const auto openStart = std::chrono::steady_clock::now();
    game::openRenderTarget(target, cl, level, !cl.headless);
    times.openMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - openStart)
            .count();
    const render::RendererInfo& info = render::rendererInfo(target.renderer);
    const char* backend = cl.headless ? "headless" : "window";
    if (cl.headless) {
        std::printf("onelight: %ux%u, MSAA %ux (requested %ux)", cl.width, cl.height,
                    info.msaaInUse, info.msaaRequested);
    } else {
        std::printf(
            "onelight: window %ux%u, frame %ux%u at render scale %.2f, MSAA %ux (requested %ux); "
            "WASD + mouse, Esc quits\n",
            target.window.swapchain.extent.width, target.window.swapchain.extent.height,
            target.frameWidth, target.frameHeight, double(target.renderScale), info.msaaInUse,
            info.msaaRequested);
        if (cl.frames == 0)
            glfwSetInputMode(target.window.window, GLFW_CURSOR, GLFW_CURSOR_DISABLED);
    }
    std::fflush(stdout);
    // Exposure: --ev100, else the camera's or the level's own, else metered in the view as the
    // game meters the player's (game/session.hpp meteredEv100).
    game::Session meter;
    game::startSession(meter, level);
    meter.secondaryLux = std::max(info.ambientLux, 1.0f);
    // The dynamic objects as the game starts them (items on the floor, each object with the
    // primary the game picks where it stands), nothing moving: a view, not a game.
    game::pickPrimariesAtRest(meter);
    std::vector<render::DynamicTransform> dynamicObjects;  // frameInputsOf fills it
    (void)game::frameInputsOf(meter, dynamicObjects);
    const bool metered = !cl.hasEv100 && !camera.hasExposure && !level.level.settings.hasExposure;
    const auto expose = [&](render::Camera c) {
        if (cl.hasEv100) {
            c.hasExposure = true;
            c.ev100 = cl.ev100;
        } else if (metered) {
            const float ev = game::meteredEv100(meter, c, NAN);
            c.hasExposure = std::isfinite(ev);
            c.ev100 = c.hasExposure ? ev : 0.0f;
        }
        return c;
    };
    camera = expose(camera);
    int code = 0;
    try {
        game::FreeFly fly = game::freeFlyFrom(camera);
        auto last = std::chrono::steady_clock::now();
        const uint32_t frames = cl.headless ? std::max(cl.frames, 1u) : cl.frames;
        for (uint32_t frame = 0; !game::targetWantsToClose(target); ++frame) {
            const auto now = std::chrono::steady_clock::now();
            const float dt = std::chrono::duration<float>(now - last).count();
            last = now;
            if (!cl.headless && cl.frames == 0) {
                game::updateFreeFly(fly, target.window.window, dt);
                camera = expose(game::cameraOf(fly, camera));
            }
            const bool lastFrame = frames > 0 && frame + 1 >= frames;
            render::FrameInputs inputs;
            inputs.camera = camera;
            inputs.effects = effectsFor(cl, camera);
            inputs.dynamicTransforms = dynamicObjects;
            const bool readback = lastFrame && !cl.capture.empty();
            const auto frameStart = std::chrono::steady_clock::now();
            const render::FrameStats stats = game::drawToTarget(
                target, inputs, readback || cl.headless, readback && !cl.headless);
            if (frames > 0) {
                if (stats.gpuTimestamps) times.gpuMs.push_back(double(stats.gpuMs));
                times.wallMs.push_back(std::chrono::duration<double, std::milli>(
                                           std::chrono::steady_clock::now() - frameStart)
                                           .count());
            }
            if (cl.headless && lastFrame)
                std::printf(", %.2f ms CPU, %.2f ms GPU, %u surfaces\n", stats.cpuMs, stats.gpuMs,
                            stats.surfacesDrawn);
            if (readback) {
                const render::CapturedFrame& captured = render::capturedFrame(target.renderer);
                capture::writeCaptureFiles(cl.capture, captured,
                                           sidecar(cl, level, target.renderer, camera, stats,
                                                   backend, times, dynamicObjects));
                if (!cl.headless)
                    world::writePngFile(
                        cl.capture + "_window.png", target.window.swapchain.extent.width,
                        target.window.swapchain.extent.height, captured.swapchainRgba8);
            }
            if (lastFrame) break;
        }
    } catch (...) {
        game::closeRenderTarget(target);
        throw;
    }
    if (uint32_t errors = game::closeRenderTarget(target))
        code = fail(std::to_string(errors) + " Vulkan validation errors");
    return code;
}

int run(int argc, char** argv) {
    const game::CommandLine cl = game::parseCommandLine(argc, argv);
    if (cl.help) {
        std::printf("%s", game::usage().c_str());
        return 0;
    }
    assets::LoadedLevel level = assets::loadLevel(game::resolveLevelPackage(cl.level, cl.quality));
    game::applyLightingView(level, cl.view);
    printErrorBudget(level);
    if (!cl.replay.empty()) return game::runReplay(cl, level);
    if (!cl.headless && !cl.freeFly && cl.camera.empty()) return game::runPlay(cl, level);
    return runViewer(cl, level, resolveCamera(cl, level));
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        return fail("out of memory");
    } catch (const std::exception& e) {
        return fail(e.what());
    }
}
