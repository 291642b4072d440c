#include "replay_mode.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "capture/capture.hpp"
#include "render/camera.hpp"
#include "render_target.hpp"
#include "session.hpp"
#include "sim/replay_runner.hpp"
#include "world/file_read.hpp"
#include "world/file_write.hpp"
#include "world/images/image_files.hpp"

namespace onelight::game {

namespace {

struct Capture {
    std::string name;
    uint32_t width, height;
    std::vector<uint8_t> rgba8;
};

// NAME.json: the tick, the camera, the frame's timings and each visible dynamic object's
// primary light.
nlohmann::json captureJson(Session& s, const render::Renderer& renderer,
                           const render::FrameInputs& in, const render::FrameStats& stats,
                           uint64_t tick, double tickSeconds) {
    const render::RendererInfo& info = render::rendererInfo(renderer);
    const render::CapturedFrame& frame = render::capturedFrame(renderer);
    const Player& p = s.registry.get<Player>(s.player);
    glm::mat4 clip = render::projectionMatrix(in.camera, float(frame.width) / float(frame.height),
                                              in.camera.zfar > 0.0f ? in.camera.zfar : 500.0f) *
                     render::viewMatrix(in.camera);
    render::Frustum frustum = render::frustumOf(clip);
    nlohmann::json objects = nlohmann::json::array();
    for (auto [e, name, transform, lit] :
         s.registry.view<Name, Transform, DynamicLighting>().each()) {
        glm::vec3 half(0.75f);
        if (!render::intersects(frustum, transform.position - half, transform.position + half))
            continue;
        objects.push_back(
            {{"name", name.value},
             {"position", {transform.position.x, transform.position.y, transform.position.z}},
             {"primary",
              lit.pick.primary < s.lightNames.size() ? s.lightNames[lit.pick.primary] : "none"}});
    }
    return {{"level", s.level->path},
            {"tick", tick},
            {"time", double(tick) * tickSeconds},
            {"size", {frame.width, frame.height}},
            {"camera",
             {{"position", {in.camera.position.x, in.camera.position.y, in.camera.position.z}},
              {"yaw_degrees", glm::degrees(p.yaw)},
              {"pitch_degrees", glm::degrees(p.pitch)},
              {"ev100", stats.ev100}}},
            {"msaa", {{"requested", info.msaaRequested}, {"in_use", info.msaaInUse}}},
            {"timings_ms", {{"cpu", stats.cpuMs}, {"gpu", stats.gpuMs}}},
            {"effect_lights", {{"omni", in.effects.omniCount}, {"spot", in.effects.spotOn}}},
            {"dynamic_objects", objects}};
}

/// The q-quantile of `values` (nearest rank), 0 when empty.
double quantile(std::vector<double> values, double q) {
    if (values.empty()) return 0.0;
    const size_t k = std::min(values.size() - 1, size_t(std::ceil(q * double(values.size()))) - 1);
    std::nth_element(values.begin(), values.begin() + long(k), values.end());
    return values[k];
}

/// Frame times of a benchmark run: wall time of each drawn frame (submit to its end, as the
/// player waits for it) and the GPU's own time from its timestamps.
struct FrameTimes {
    std::vector<double> wallMs, gpuMs;
};

/// One line a script can read: `onelight-benchmark key=value ...`, times in milliseconds.
void printBenchmark(const CommandLine& cl, const FrameTimes& t, const render::RendererInfo& info) {
    const double median = quantile(t.wallMs, 0.5);
    std::printf(
        "onelight-benchmark replay=%s frames=%zu width=%u height=%u msaa=%u median_ms=%.3f "
        "p95_ms=%.3f gpu_median_ms=%.3f gpu_p95_ms=%.3f fps=%.2f\n",
        cl.replay.c_str(), t.wallMs.size(), cl.width, cl.height, info.msaaInUse, median,
        quantile(t.wallMs, 0.95), quantile(t.gpuMs, 0.5), quantile(t.gpuMs, 0.95),
        median > 0.0 ? 1000.0 / median : 0.0);
}

// All captures side by side at half size, in script order: one PNG to look at.
void writeContactSheet(const std::string& path, const std::vector<Capture>& captures) {
    if (captures.empty()) return;
    uint32_t cw = (captures[0].width + 1) / 2, ch = (captures[0].height + 1) / 2;
    uint32_t columns = uint32_t(std::ceil(std::sqrt(double(captures.size()))));
    uint32_t rows = uint32_t((captures.size() + columns - 1) / columns);
    uint32_t gap = 4, width = columns * (cw + gap) + gap, height = rows * (ch + gap) + gap;
    std::vector<uint8_t> sheet(size_t(width) * height * 4, 40);
    for (size_t i = 0; i < captures.size(); ++i) {
        const Capture& c = captures[i];
        uint32_t ox = gap + uint32_t(i % columns) * (cw + gap),
                 oy = gap + uint32_t(i / columns) * (ch + gap);
        for (uint32_t y = 0; y < ch && 2 * y < c.height; ++y)
            for (uint32_t x = 0; x < cw && 2 * x < c.width; ++x)
                for (int k = 0; k < 4; ++k)
                    sheet[(size_t(oy + y) * width + ox + x) * 4 + k] =
                        c.rgba8[(size_t(2 * y) * c.width + 2 * x) * 4 + k];
    }
    for (size_t i = 3; i < sheet.size(); i += 4) sheet[i] = 255;
    world::writePngFile(path, width, height, sheet);
}

}  // namespace

int runReplay(const CommandLine& cl, const assets::LoadedLevel& level) {
    Session session;
    startSession(session, level);
    session.fixedExposure = cl.hasEv100;
    session.ev100 = cl.ev100;
    ReplayRunner runner =
        makeReplayRunner(replay::loadScript(cl.replay), session.lightNames, session.registry);
    const double tickSeconds = 1.0 / runner.script.tickRate;
    session.tickSeconds = tickSeconds;
    const std::string dir = cl.captureDir.empty() ? std::string("captures") : cl.captureDir;
    if (!cl.benchmark) world::makeFolder(dir, "--capture-dir");

    RenderTarget target;
    openRenderTarget(target, cl, level, !cl.headless);
    session.secondaryLux = std::max(render::rendererInfo(target.renderer).ambientLux, 1.0f);
    std::printf("onelight: replay %s on %s, %zu commands, MSAA %ux\n", cl.replay.c_str(),
                level.path.c_str(), runner.script.commands.size(),
                render::rendererInfo(target.renderer).msaaInUse);
    int code = 0;
    std::vector<Capture> captures;
    FrameTimes times;
    try {
        uint64_t lastTick = runner.script.commands.empty() ? 0 : runner.script.commands.back().tick;
        std::vector<render::DynamicTransform> transforms;
        for (uint64_t tick = 0; tick <= lastTick; ++tick) {
            applyReplayInput(runner, tick, session.input, session.registry, session.player,
                             session.tuning);
            stepSession(session);
            ReplayAfterTick after = finishReplayTick(runner, tick, session.registry);
            // Headless, only the captured ticks are drawn; in a window, and when benchmarking,
            // every tick is (a benchmark captures nothing).
            if (!after.captures.empty() || target.windowed || cl.benchmark) {
                if (targetWantsToClose(target)) break;
                render::FrameInputs in = frameInputsOf(session, transforms);
                const auto start = std::chrono::steady_clock::now();
                render::FrameStats stats =
                    drawToTarget(target, in, !after.captures.empty() && !cl.benchmark);
                if (cl.benchmark) {
                    times.wallMs.push_back(std::chrono::duration<double, std::milli>(
                                               std::chrono::steady_clock::now() - start)
                                               .count());
                    times.gpuMs.push_back(stats.gpuMs);
                }
                for (const std::string& name : after.captures) {
                    if (cl.benchmark) break;  // a benchmark captures nothing
                    const render::CapturedFrame& frame = render::capturedFrame(target.renderer);
                    std::string base = dir + "/" + name;
                    capture::writeCaptureFiles(
                        base, frame,
                        captureJson(session, target.renderer, in, stats, tick, tickSeconds));
                    captures.push_back({name, frame.width, frame.height, frame.rgba8});
                    std::printf("onelight: tick %llu captured %s.png\n", (unsigned long long)tick,
                                base.c_str());
                }
            }
            if (after.quit) break;
        }
        if (cl.benchmark)
            printBenchmark(cl, times, render::rendererInfo(target.renderer));
        else
            writeContactSheet(dir + "/contact_sheet.png", captures);
    } catch (const ReplayFailure& e) {
        std::fprintf(stderr, "onelight: %s\n", world::oneLineMessage(e.what()).c_str());
        code = 1;
    } catch (...) {
        closeRenderTarget(target);
        throw;
    }
    if (uint32_t errors = closeRenderTarget(target)) {
        std::fprintf(stderr, "onelight: %u Vulkan validation errors\n", errors);
        code = 1;
    }
    if (code == 0 && !cl.benchmark)
        std::printf("onelight: replay done, %zu captures and a contact sheet in %s/\n",
                    captures.size(), dir.c_str());
    return code;
}

}  // namespace onelight::game
