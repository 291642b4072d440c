// onelight-bench-render: one run at 1280x720 on a generated level of about 50k triangles (a floor,
// spheres and boxes of all four material classes, a sun, a spot and an omni primary). Reports
// median frame times, the full-PBR / Lambert-only permutation ratio on the same frame (goal
// <= 1.15), the full-frame / flat-shaded-floor ratio with the same geometry and MSAA (goal <= 1.3)
// and resident memory; the material pipeline's runtime pieces on and off (goal <= 1.1); then the
// probes' cost on a baked level (`onelight-bench-render
// [PACKAGE]`, default the demo's draft package) and its frame loop with and without frames in
// flight. `onelight-bench-render --view PACKAGE CAMERA` instead: where one view of a real level's
// frame goes, feature by feature (benchView); `--objects PACKAGE CAMERA`: only what a Quake 3
// map's items and movers cost there, over more frames; `--aa PACKAGE CAMERA`: anti-aliasing by its
// edge error and cost (benchAntiAliasing). Compare ratios from one run only (docs/toolchain.md,
// "Timing things": timings are noisy).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bumpy_floor.hpp"
#include "render/camera.hpp"
#include "render/gpu_types.hpp"
#include "shading.hpp"
#include "test_scene.hpp"
#include "vk/context.hpp"
#include "world/entity_transform.hpp"

namespace {

using namespace onelight;

constexpr int kWarmup = 2;
// Each measured frame is waited for, so that its GPU times are its own.
const onelight::render::FrameOutput waited = [] {
    onelight::render::FrameOutput o;
    o.wait = true;
    return o;
}();
constexpr int kFrames = 7;

test::Scene benchScene() {
    test::Scene s;
    s.materials = {{{0.6f, 0.6f, 0.6f, 1.0f}, 0.0f, 1.0f},   // lambert
                   {{0.8f, 0.3f, 0.2f, 1.0f}, 0.0f, 0.4f},   // dielectric
                   {{0.9f, 0.8f, 0.5f, 1.0f}, 1.0f, 0.3f},   // metal
                   {{0.3f, 0.6f, 0.9f, 1.0f}, 0.5f, 0.5f}};  // full
    test::addFloor(s, 0.0f, 0.0f, 20.0f, 0.0f, 0);
    for (int z = 0; z < 6; ++z)
        for (int x = 0; x < 8; ++x) {
            const glm::vec3 c(-10.5f + 3.0f * float(x), 0.9f, -16.0f + 3.0f * float(z));
            test::addSphere(s, c, 0.9f, 12, 20, uint32_t(1 + (x + z) % 3));
            test::addBox(s, c + glm::vec3(1.1f, -0.9f, 0.6f), c + glm::vec3(1.7f, 0.3f, 1.2f),
                         uint32_t((x + 2 * z) % 4));
        }
    test::SceneLight sun;
    sun.intensity = 20000.0f;
    sun.direction = glm::normalize(glm::vec3(0.5f, -0.8f, 0.3f));
    s.lights.push_back(sun);
    test::SceneLight spot;
    spot.type = 2;
    spot.intensity = 3000.0f;
    spot.range = 20.0f;
    spot.position = {-6.0f, 6.0f, -4.0f};
    spot.direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.2f));
    s.lights.push_back(spot);
    test::SceneLight omni;
    omni.type = 1;
    omni.intensity = 2000.0f;
    omni.range = 10.0f;
    omni.position = {6.0f, 3.0f, -8.0f};
    s.lights.push_back(omni);
    return s;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

std::string statusLine(const char* key) {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(key, 0) == 0) return line.substr(std::string(key).size());
    return "?";
}

// The probes' frame cost on a baked level (the demo's draft package unless a path is given):
// its first camera rendered with the package's probes and with the uniform placeholder
// environment (RendererOptions::probes off), frames interleaved, medians.
void benchProbes(vk::Context& ctx, const std::string& package) {
    const assets::LoadedLevel level = assets::loadLevel(package);
    if (level.level.cameras.empty()) throw std::runtime_error(package + ": no camera");
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromLevel(level.level.cameras.front());
    std::vector<render::RendererOptions> configs(2);
    configs[1].probes = false;
    std::vector<render::Renderer> renderers(configs.size());
    for (size_t c = 0; c < configs.size(); ++c) {
        render::createRenderer(renderers[c], ctx, level, configs[c]);
        for (int i = 0; i < kWarmup; ++i) render::drawFrame(renderers[c], inputs);
    }
    std::vector<std::vector<double>> gpu(configs.size());
    for (int i = 0; i < kFrames; ++i)
        for (size_t c = 0; c < configs.size(); ++c)
            gpu[c].push_back(render::drawFrame(renderers[c], inputs, waited).gpuMs);
    const render::RendererInfo info = render::rendererInfo(renderers[0]);
    for (auto it = renderers.rbegin(); it != renderers.rend(); ++it) render::destroyRenderer(*it);
    const double with = median(gpu[0]), without = median(gpu[1]);
    std::printf("  probes: %s, camera '%s': %u probes, %.1f KiB of cube array (%.1f KiB each)\n",
                package.c_str(), level.level.cameras.front().name.c_str(), info.probes,
                double(info.probeBytes) / 1024.0,
                info.probes ? double(info.probeBytes) / 1024.0 / info.probes : 0.0);
    std::printf(
        "  frame with probes %8.2f ms GPU, with the uniform placeholder %8.2f ms GPU, "
        "ratio %.3f\n",
        with, without, with / without);
}

// The frame loop on the same baked level: wall time per frame over runs of kLoopFrames frames,
// each frame waited for before the next starts (the loop before frames in flight) against
// frames submitted without waiting (two in flight, as the window plays), runs interleaved.
void benchFrameLoop(vk::Context& ctx, const std::string& package) {
    constexpr int kLoopFrames = 12, kLoopRuns = 3;
    const assets::LoadedLevel level = assets::loadLevel(package);
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromLevel(level.level.cameras.front());
    render::Renderer renderer;
    render::createRenderer(renderer, ctx, level, render::RendererOptions{});
    for (int i = 0; i < kWarmup; ++i) render::drawFrame(renderer, inputs, waited);
    std::vector<double> waitedMs, inFlightMs;
    for (int run = 0; run < kLoopRuns; ++run)
        for (bool inFlight : {false, true}) {
            const auto start = std::chrono::steady_clock::now();
            for (int i = 0; i < kLoopFrames; ++i)
                render::drawFrame(renderer, inputs, inFlight ? render::FrameOutput{} : waited);
            render::waitForFrames(renderer);
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count() /
                kLoopFrames;
            (inFlight ? inFlightMs : waitedMs).push_back(ms);
        }
    render::destroyRenderer(renderer);
    const double before = median(waitedMs), after = median(inFlightMs);
    std::printf(
        "  frame loop on that level: %8.2f ms a frame waiting for each, %8.2f ms with two in "
        "flight, ratio %.3f\n",
        before, after, after / before);
}

// The same view of a level and of one four times its length: a chicane hall of 3 rooms (40 m)
// and of 13 (160 m), baked at draft, seen from the first room down the hall, with the visible
// set's culling and without; frames interleaved, medians.
void benchLevelScale(vk::Context& ctx) {
    struct Config {
        int rooms;
        bool culling;
    };
    const std::vector<Config> configs = {{3, true}, {13, true}, {3, false}, {13, false}};
    std::vector<assets::LoadedLevel> levels;
    for (int rooms : {3, 13}) {
        test::Scene s;
        s.materials = {{{0.6f, 0.6f, 0.6f, 1.0f}, 0.0f, 0.6f}};
        test::addChicaneHall(s, rooms);
        const std::string name = test::outputDir() + "/bench_hall_" + std::to_string(rooms);
        test::writeGltf(s, name + ".gltf");
        levels.push_back(
            test::bakeAndLoad(name + ".gltf", name + ".olpak", "--texels-per-metre 2"));
    }
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({-18.0f, 1.7f, 9.0f}, -90.0f, -5.0f);
    std::vector<render::Renderer> renderers(configs.size());
    for (size_t c = 0; c < configs.size(); ++c) {
        render::RendererOptions o;
        o.visibilityCulling = configs[c].culling;
        render::createRenderer(renderers[c], ctx, levels[configs[c].rooms == 3 ? 0 : 1], o);
        for (int i = 0; i < kWarmup; ++i) render::drawFrame(renderers[c], inputs, waited);
    }
    std::vector<std::vector<double>> gpu(configs.size());
    std::vector<render::FrameStats> last(configs.size());
    for (int i = 0; i < kFrames; ++i)
        for (size_t c = 0; c < configs.size(); ++c) {
            last[c] = render::drawFrame(renderers[c], inputs, waited);
            gpu[c].push_back(last[c].gpuMs);
        }
    for (auto it = renderers.rbegin(); it != renderers.rend(); ++it) render::destroyRenderer(*it);
    for (size_t c = 0; c < configs.size(); ++c)
        std::printf(
            "  hall of %2d rooms, culling %-3s: %8.2f ms GPU, %u surfaces drawn, %u hidden, "
            "%u draws\n",
            configs[c].rooms, configs[c].culling ? "on" : "off", median(gpu[c]),
            last[c].surfacesDrawn, last[c].surfacesHidden, last[c].draws);
    std::printf(
        "  4x the level, the same view: %.3f with culling by the visible set (goal <= 1.2), %.3f "
        "without\n",
        median(gpu[1]) / median(gpu[0]), median(gpu[3]) / median(gpu[2]));
}

// The material pipeline's runtime pieces (the fold of a filtered normal into gloss, the cavity,
// the direct lights' energy weight; docs/materials.md) against the same frame without them
// (RendererOptions::materialPipeline), frames interleaved: on a bump-mapped glossy floor that
// fills the view (every pixel normal-mapped, its worst case) and on a baked level.
void benchMaterialPipeline(vk::Context& ctx, const std::string& package) {
    const std::string folder = test::outputDir() + "/bench_material_pipeline";
    std::filesystem::create_directories(folder);
    const std::string floorGltf = test::writeBumpyGlossyFloor(folder, "black_ops", 16.0f / 9.0f);
    struct Level {
        const char* name;
        assets::LoadedLevel level;
        render::FrameInputs inputs;
    };
    std::vector<Level> levels;
    levels.push_back(
        {"bump-mapped glossy floor", test::bakeAndLoad(floorGltf, folder + "/floor.olpak"), {}});
    levels.back().inputs.camera = render::cameraFromLevel(levels.back().level.level.cameras.at(0));
    levels.push_back({"baked level", assets::loadLevel(package), {}});
    levels.back().inputs.camera = render::cameraFromYawPitch({-6.0f, 1.7f, 0.0f}, -90.0f, -3.0f);
    for (Level& l : levels) {
        std::vector<render::Renderer> renderers(2);  // with the pipeline, without
        for (size_t c = 0; c < 2; ++c) {
            render::RendererOptions o;
            o.materialPipeline = c == 0;
            render::createRenderer(renderers[c], ctx, l.level, o);
            for (int i = 0; i < kWarmup; ++i) render::drawFrame(renderers[c], l.inputs, waited);
        }
        std::vector<double> gpu[2];
        for (int i = 0; i < kFrames; ++i)
            for (size_t c = 0; c < 2; ++c)
                gpu[c].push_back(render::drawFrame(renderers[c], l.inputs, waited).gpuMs);
        for (auto it = renderers.rbegin(); it != renderers.rend(); ++it)
            render::destroyRenderer(*it);
        std::printf(
            "  material pipeline, %s: %.2f ms GPU with it, %.2f without, ratio %.3f (goal <= "
            "1.1)\n",
            l.name, median(gpu[0]), median(gpu[1]), median(gpu[0]) / median(gpu[1]));
    }
}

// The level's camera `name`; throws naming the package when it has none of that name.
render::Camera cameraNamed(const assets::LoadedLevel& level, const std::string& package,
                           const std::string& name) {
    for (const world::Camera& c : level.level.cameras)
        if (c.name == name) return render::cameraFromLevel(c);
    throw std::runtime_error(package + ": no camera named '" + name + "'");
}

// Where a real level's frame goes: one view of a package (`onelight-bench-render --view PACKAGE
// CAMERA`, e.g. a Quake 3 map's spawn0) at 1280x720 with MSAA 4x, configurations interleaved
// frame by frame: the frame as the game draws it, and with one feature changed each, down to
// the raster floor. Each row's difference to the full frame is that feature's cost. With
// `objectsOnly`, only the rows of the items and movers, over 25 frames: their cost is a few
// percent, within the spread of seven frames.
void benchView(vk::Context& ctx, const std::string& package, const std::string& cameraName,
               bool objectsOnly) {
    const assets::LoadedLevel level = assets::loadLevel(package);
    render::FrameInputs inputs;
    inputs.camera = cameraNamed(level, package, cameraName);
    struct Config {
        const char* name;
        render::RendererOptions options;
        uint32_t hide = 0;    // entity flags whose objects are hidden (a Quake 3 map's pickups,
                              // movers)...
        bool shrink = false;  // ...or drawn shrunk to a hundredth instead
    };
    std::vector<Config> configs(22);
    for (Config& c : configs) c.options.requestedMsaa = 4;
    configs[0].name = "full frame, as the game draws it";
    configs[1].name = "general pipelines (choices at run time)";
    configs[1].options.specializeDraws = false;
    configs[2].name = "no probes (a uniform environment)";
    configs[2].options.probes = false;
    configs[3].name = "no material pipeline pieces";
    configs[3].options.materialPipeline = false;
    const std::pair<const char*, int> off[] = {
        {"no base colour texture", glsl::FEATURE_BASE_TEXTURE},
        {"no lightmap (a constant ambient)", glsl::FEATURE_LIGHTMAP},
        {"no runtime shadow", glsl::FEATURE_RUNTIME_SHADOW},
        {"no baked shadow mask", glsl::FEATURE_BAKED_SHADOW},
        {"no primary light", glsl::FEATURE_PRIMARY},
        {"no emissive texture", glsl::FEATURE_EMISSIVE_TEXTURE}};
    for (size_t i = 0; i < std::size(off); ++i) {
        configs[4 + i].name = off[i].first;
        configs[4 + i].options.featuresOff = uint32_t(off[i].second);
    }
    configs[10].name = "MSAA 1x";
    configs[10].options.requestedMsaa = 1;
    configs[11].name = "flat-shaded, the frame's draws";
    configs[11].options.flatShading = true;
    configs[12].name = "raster floor (fewest draws)";
    configs[12].options.flatShading = configs[12].options.rasterFloor = true;
    configs[13].name = "raster floor, MSAA 1x";
    configs[13].options.flatShading = configs[13].options.rasterFloor = true;
    configs[13].options.requestedMsaa = 1;
    configs[14].name = "full frame again (the run's noise)";
    configs[15].name = "the sun in one map (no cascades)";
    configs[15].options.sunCascades = 1;
    configs[16].name = "shadow lookups on every lit surface";
    configs[16].options.skipUniformShadows = false;
    configs[17].name = "without the level's items and movers";
    configs[17].hide = world::kEntityItem | world::kEntityMover;
    configs[18].name = "without the level's items";
    configs[18].hide = world::kEntityItem;
    configs[19].name = "without the level's movers";
    configs[19].hide = world::kEntityMover;
    // The same draws, each object shrunk about its origin to a hundredth (its pixels gone, its
    // draw, pipeline, textures and vertices kept): what the objects cost per draw.
    configs[20].name = "items and movers shrunk to a hundredth";
    configs[20].hide = world::kEntityItem | world::kEntityMover;
    configs[20].shrink = true;
    configs[21].name = "no baked direct light's edges (bilinear)";
    configs[21].options.featuresOff = uint32_t(glsl::FEATURE_DIRECT_EDGE);
    // The hidden objects where the level places them (as inputs without transforms draw them).
    std::vector<render::FrameInputs> hiddenInputs(configs.size(), inputs);
    std::vector<std::vector<render::DynamicTransform>> hidden(configs.size());
    for (size_t c = 0; c < configs.size(); ++c) {
        if (!configs[c].hide) continue;
        for (uint32_t e = 0; e < level.level.entities.size(); ++e)
            if (level.level.entities[e].flags & configs[c].hide) {
                render::DynamicTransform t;
                t.entity = e;
                t.worldFromObject = world::worldFromObject(level.level.entities[e],
                                                           level.level.entities[e].position);
                t.hidden = !configs[c].shrink;
                if (configs[c].shrink)
                    t.worldFromObject = glm::scale(t.worldFromObject, glm::vec3(0.01f));
                hidden[c].push_back(t);
            }
        hiddenInputs[c].dynamicTransforms = hidden[c];
    }
    auto inputsOf = [&](size_t c) -> const render::FrameInputs& {
        return configs[c].hide ? hiddenInputs[c] : inputs;
    };
    std::vector<size_t> run(configs.size());
    for (size_t c = 0; c < configs.size(); ++c) run[c] = c;
    if (objectsOnly) run = {0, 14, 17, 18, 19, 20};
    const int frameCount = objectsOnly ? 25 : kFrames;
    std::vector<render::Renderer> renderers(configs.size());
    for (size_t c : run) {
        render::createRenderer(renderers[c], ctx, level, configs[c].options);
        for (int i = 0; i < kWarmup; ++i) render::drawFrame(renderers[c], inputsOf(c), waited);
    }
    render::FrameOutput readback = waited;
    readback.readback = true;
    std::vector<std::vector<double>> gpu(configs.size()), forward(configs.size()),
        tonemap(configs.size()), shadows(configs.size());
    std::vector<double> withReadback;
    std::vector<render::FrameStats> last(configs.size());
    for (int i = 0; i < frameCount; ++i) {
        for (size_t c : run) {
            last[c] = render::drawFrame(renderers[c], inputsOf(c), waited);
            gpu[c].push_back(last[c].gpuMs);
            forward[c].push_back(last[c].gpuForwardMs);
            tonemap[c].push_back(last[c].gpuTonemapMs);
            shadows[c].push_back(last[c].gpuShadowMs);
        }
        const auto start = std::chrono::steady_clock::now();
        render::drawFrame(renderers[0], inputs, readback);
        withReadback.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
    }
    // How far each configuration's displayed frame is from the full frame's: the share of
    // pixels off by more than 8/255 in a channel (the goldens' threshold).
    std::vector<double> changed(configs.size());
    std::vector<render::CapturedFrame> frames(configs.size());
    for (size_t c : run) {
        render::drawFrame(renderers[c], inputsOf(c), readback);
        frames[c] = render::capturedFrame(renderers[c]);
    }
    for (size_t c : run)
        changed[c] = 100.0 * test::shareOfPixelsOff(frames[0].rgba8, frames[c].rgba8);
    std::vector<std::string> permutations = render::rendererInfo(renderers[0]).permutations;
    const uint32_t msaa = render::rendererInfo(renderers[0]).msaaInUse;
    const render::RendererInfo info = render::rendererInfo(renderers[0]);
    for (auto it = run.rbegin(); it != run.rend(); ++it) render::destroyRenderer(renderers[*it]);
    std::printf(
        "onelight-bench-render --view %s %s: 1280x720, MSAA %ux, %s, %d interleaved frames, "
        "medians; %u surfaces, %u dynamic meshes (%u more in view hidden by the visible set), "
        "%llu triangles drawn (%llu without the items and movers), %u draws binding %u "
        "pipelines and %u material sets (without the items and movers: %u draws, %u and %u)\n",
        package.c_str(), cameraName.c_str(), msaa, ctx.properties.deviceName, frameCount,
        last[0].surfacesDrawn, last[0].dynamicMeshesDrawn, last[0].dynamicMeshesHidden,
        static_cast<unsigned long long>(last[0].trianglesDrawn),
        static_cast<unsigned long long>(last[17].trianglesDrawn), last[0].draws,
        last[0].pipelineBinds, last[0].materialBinds, last[17].draws, last[17].pipelineBinds,
        last[17].materialBinds);
    std::printf("  %-42s %9s %9s %9s %9s %9s %11s\n", "configuration", "GPU ms", "shadows",
                "forward", "tonemap", objectsOnly ? "/ without" : "/ floor", "px off %");
    // Without the raster floor's row (objectsOnly), each row over the frame without the items
    // and movers instead.
    const double floor = median(gpu[objectsOnly ? 17 : 12]);
    for (size_t c : run)
        std::printf("  %-42s %9.2f %9.2f %9.2f %9.2f %9.3f %11.3f\n", configs[c].name,
                    median(gpu[c]), median(shadows[c]), median(forward[c]), median(tonemap[c]),
                    median(gpu[c]) / floor, changed[c]);
    std::printf("  items and movers: the full frame %.3fx the frame without them (goal <= 1.1)\n",
                median(gpu[0]) / median(gpu[17]));
    std::printf("  full frame with its readback (wall): %.2f ms\n", median(withReadback));
    std::printf(
        "  static surfaces with a primary: %u, of which their baked masks light %u whole "
        "and shadow %u whole\n",
        info.surfacesWithPrimary, info.surfacesUnoccluded, info.surfacesInShadow);
    std::printf("  permutations:");
    for (const std::string& p : permutations) std::printf(" [%s]", p.c_str());
    std::printf("\n");
}

// Anti-aliasing chosen by its error and cost (`onelight-bench-render --aa PACKAGE CAMERA`): MSAA
// 1x and 4x, each with and without FXAA, at 1280x720, timed over interleaved frames, against a
// reference of 16 samples a pixel (the view at 2560x1440 with MSAA 4x, each 2x2 block averaged in
// linear light, then exposed and display-encoded on the CPU with shaders/tonemap.glsl). The error
// is measured where geometry aliases: the edge pixels, those whose MSAA 1x and 4x frames differ by
// more than 2/255 (MSAA changes nothing else). Reports each configuration's mean error over them
// (in 1/255) and the share of them off by more than 8/255.
void benchAntiAliasing(vk::Context& ctx, const std::string& package,
                       const std::string& cameraName) {
    const assets::LoadedLevel level = assets::loadLevel(package);
    render::FrameInputs inputs;
    inputs.camera = cameraNamed(level, package, cameraName);
    struct Config {
        const char* name;
        uint32_t msaa;
        bool fxaa;
    };
    const Config configs[] = {{"MSAA 1x", 1, false},
                              {"MSAA 4x", 4, false},
                              {"MSAA 1x + FXAA", 1, true},
                              {"MSAA 4x + FXAA", 4, true}};
    constexpr size_t kConfigs = std::size(configs);
    std::vector<render::Renderer> renderers(kConfigs);
    for (size_t c = 0; c < kConfigs; ++c) {
        render::RendererOptions o;
        o.requestedMsaa = configs[c].msaa;
        o.fxaa = configs[c].fxaa;
        render::createRenderer(renderers[c], ctx, level, o);
        for (int i = 0; i < kWarmup; ++i) render::drawFrame(renderers[c], inputs, waited);
    }
    std::vector<std::vector<double>> gpu(kConfigs), post(kConfigs);
    for (int i = 0; i < kFrames; ++i)
        for (size_t c = 0; c < kConfigs; ++c) {
            const render::FrameStats s = render::drawFrame(renderers[c], inputs, waited);
            gpu[c].push_back(s.gpuMs);
            post[c].push_back(s.gpuTonemapMs);
        }
    render::FrameOutput readback = waited;
    readback.readback = true;
    std::vector<std::vector<uint8_t>> frames(kConfigs);
    for (size_t c = 0; c < kConfigs; ++c) {
        render::drawFrame(renderers[c], inputs, readback);
        frames[c] = render::capturedFrame(renderers[c]).rgba8;
    }
    for (auto it = renderers.rbegin(); it != renderers.rend(); ++it) render::destroyRenderer(*it);

    // The reference: 2x2 blocks of a 4x-MSAA frame at twice the size, in linear light.
    render::RendererOptions big;
    big.width = 2 * 1280;
    big.height = 2 * 720;
    big.requestedMsaa = 4;
    render::Renderer r;
    render::createRenderer(r, ctx, level, big);
    const render::FrameStats s = render::drawFrame(r, inputs, readback);
    const std::vector<float> linear = render::capturedFrame(r).linearRgba;
    render::destroyRenderer(r);
    std::vector<uint8_t> reference(size_t(1280) * 720 * 4, 255);
    for (uint32_t y = 0; y < 720; ++y)
        for (uint32_t x = 0; x < 1280; ++x)
            for (int k = 0; k < 3; ++k) {
                double sum = 0.0;
                for (uint32_t dy = 0; dy < 2; ++dy)
                    for (uint32_t dx = 0; dx < 2; ++dx)
                        sum += double(
                            linear[((size_t(2 * y + dy) * 2560) + 2 * x + dx) * 4 + size_t(k)]);
                const float display = glsl::displayValue(float(sum / 4.0) * s.exposure);
                reference[(size_t(y) * 1280 + x) * 4 + size_t(k)] =
                    uint8_t(std::lround(std::clamp(display, 0.0f, 1.0f) * 255.0f));
            }
    std::vector<size_t> edges;  // pixels
    for (size_t p = 0; p < frames[0].size() / 4; ++p)
        if (test::worstChannelDifference(frames[0], frames[1], p) > 2) edges.push_back(p);
    std::printf(
        "onelight-bench-render --aa %s %s: 1280x720, %s, %d interleaved frames, medians; "
        "%zu edge pixels (%.2f%%), reference 16 samples a pixel\n",
        package.c_str(), cameraName.c_str(), ctx.properties.deviceName, kFrames, edges.size(),
        100.0 * double(edges.size()) / (1280.0 * 720.0));
    std::printf("  %-18s %9s %16s %14s %16s %14s\n", "configuration", "GPU ms", "tonemap+AA ms",
                "edge error", "edge px > 8/255", "all px > 8/255");
    for (size_t c = 0; c < kConfigs; ++c) {
        double sum = 0.0;
        size_t over = 0;
        for (size_t p : edges) {
            const int d = test::worstChannelDifference(frames[c], reference, p);
            sum += d;
            over += d > 8 ? 1 : 0;
        }
        std::printf("  %-18s %9.2f %16.2f %14.2f %15.2f%% %13.2f%%\n", configs[c].name,
                    median(gpu[c]), median(post[c]),
                    sum / double(std::max<size_t>(edges.size(), 1)),
                    100.0 * double(over) / double(std::max<size_t>(edges.size(), 1)),
                    100.0 * test::shareOfPixelsOff(frames[c], reference));
    }
}

}  // namespace

int main(int argc, char** argv) {
    try {
        if (argc == 4 &&
            (std::string(argv[1]) == "--view" || std::string(argv[1]) == "--objects")) {
            render::RenderDeviceFeatures features;
            vk::Context ctx;
            vk::createContext(ctx, render::renderContextOptions(features, {}));
            benchView(ctx, argv[2], argv[3], std::string(argv[1]) == "--objects");
            vk::destroyContext(ctx);
            return 0;
        }
        if (argc == 4 && std::string(argv[1]) == "--aa") {
            render::RenderDeviceFeatures features;
            vk::Context ctx;
            vk::createContext(ctx, render::renderContextOptions(features, {}));
            benchAntiAliasing(ctx, argv[2], argv[3]);
            vk::destroyContext(ctx);
            return 0;
        }
        const std::string dir = test::outputDir();
        const std::string gltf = dir + "/bench_level.gltf";
        test::writeGltf(benchScene(), gltf);
        const assets::LoadedLevel level = test::compileAndLoad(gltf, dir + "/bench_level.olpak");
        size_t triangles = level.level.indices.size() / 3;

        render::RenderDeviceFeatures features;
        vk::Context ctx;
        vk::createContext(ctx, render::renderContextOptions(features, {}));
        render::FrameInputs inputs;
        inputs.camera = render::cameraFromYawPitch({0.0f, 7.0f, 12.0f}, 0.0f, -25.0f);
        // Four renderers of the same frame, their frames interleaved so that a load change on
        // the machine hits each configuration alike: the level's permutations, everything full
        // PBR, everything Lambert-only, and a flat-shaded floor (same geometry and MSAA).
        // A fifth draws the raster floor: the same triangles, depth and a constant colour, in
        // the fewest draws (every adjacent index range merged).
        // A sixth is the full frame without the depth pre-pass.
        std::vector<render::RendererOptions> configs(6);  // 1280x720, MSAA 2x requested
        configs[1].forceMaterialClass = int(world::MaterialClass::kFull);
        configs[2].forceMaterialClass = int(world::MaterialClass::kLambert);
        configs[3].flatShading = true;
        configs[4].flatShading = true;
        configs[4].rasterFloor = true;
        configs[5].depthPrepass = false;
        std::vector<render::Renderer> renderers(configs.size());
        std::string rssOne;
        for (size_t c = 0; c < configs.size(); ++c) {
            render::createRenderer(renderers[c], ctx, level, configs[c]);
            for (int i = 0; i < kWarmup; ++i) render::drawFrame(renderers[c], inputs);
            if (c == 0) rssOne = statusLine("VmRSS:");
        }
        std::vector<std::vector<double>> gpu(configs.size()), cpu(configs.size());
        std::vector<double> shadowPass, forwardPass, tonemapPass;  // the full frame's passes
        uint64_t drawn = 0;
        std::vector<uint32_t> draws(configs.size(), 0);
        for (int i = 0; i < kFrames; ++i)
            for (size_t c = 0; c < configs.size(); ++c) {
                const render::FrameStats stats = render::drawFrame(renderers[c], inputs, waited);
                gpu[c].push_back(stats.gpuMs);
                cpu[c].push_back(stats.cpuMs);
                draws[c] = stats.draws;
                if (c != 0) continue;
                drawn = stats.trianglesDrawn;
                shadowPass.push_back(stats.gpuShadowMs);
                forwardPass.push_back(stats.gpuForwardMs);
                tonemapPass.push_back(stats.gpuTonemapMs);
            }
        const uint32_t msaa = render::rendererInfo(renderers[0]).msaaInUse;
        for (auto it = renderers.rbegin(); it != renderers.rend(); ++it)
            render::destroyRenderer(*it);
        benchLevelScale(ctx);
        benchMaterialPipeline(ctx, argc > 1 ? argv[1] : ONELIGHT_DEMO_PACKAGE);
        benchProbes(ctx, argc > 1 ? argv[1] : ONELIGHT_DEMO_PACKAGE);
        benchFrameLoop(ctx, argc > 1 ? argv[1] : ONELIGHT_DEMO_PACKAGE);
        vk::destroyContext(ctx);
        struct Row {
            double gpuMs, cpuMs;
        };
        Row full{median(gpu[0]), median(cpu[0])}, pbr{median(gpu[1]), median(cpu[1])},
            lambert{median(gpu[2]), median(cpu[2])}, flat{median(gpu[3]), median(cpu[3])},
            floor{median(gpu[4]), median(cpu[4])}, noPrepass{median(gpu[5]), median(cpu[5])};

        std::printf(
            "onelight-bench-render: 1280x720, MSAA %ux (2x requested), %s, %d interleaved frames "
            "each after %d "
            "warm-up, medians\n",
            msaa, ctx.properties.deviceName, kFrames, kWarmup);
        std::printf(
            "  level: %zu static triangles in %zu surfaces, %llu drawn in the measured view\n",
            triangles, level.level.surfaces.size(), static_cast<unsigned long long>(drawn));
        std::printf(
            "  full frame (level's permutations, shadows cached): %8.2f ms GPU %8.2f ms CPU, "
            "%u draws\n",
            full.gpuMs, full.cpuMs, draws[0]);
        std::printf(
            "  the same without the depth pre-pass:              %8.2f ms GPU %8.2f ms CPU\n",
            noPrepass.gpuMs, noPrepass.cpuMs);
        std::printf("    its passes: shadows %.2f ms, forward %.2f ms, tonemap %.2f ms GPU\n",
                    median(shadowPass), median(forwardPass), median(tonemapPass));
        std::printf(
            "  every material full PBR:                          %8.2f ms GPU %8.2f ms CPU\n",
            pbr.gpuMs, pbr.cpuMs);
        std::printf(
            "  every material Lambert-only:                      %8.2f ms GPU %8.2f ms CPU\n",
            lambert.gpuMs, lambert.cpuMs);
        std::printf(
            "  flat-shaded, the full frame's draws:              %8.2f ms GPU %8.2f ms CPU, "
            "%u draws\n",
            flat.gpuMs, flat.cpuMs, draws[3]);
        std::printf(
            "  raster floor (same triangles and MSAA, fewest draws): %5.2f ms GPU %8.2f ms CPU, "
            "%u draws\n",
            floor.gpuMs, floor.cpuMs, draws[4]);
        std::printf("  ratio full PBR / Lambert-only: %.3f (goal <= 1.15)\n",
                    pbr.gpuMs / lambert.gpuMs);
        std::printf(
            "  ratio full frame / raster floor: %.3f (goal <= 1.3); flat with the frame's "
            "draws / raster floor: %.3f\n",
            full.gpuMs / floor.gpuMs, flat.gpuMs / floor.gpuMs);
        std::printf("  resident memory with one renderer: VmRSS%s; peak of the run VmHWM%s\n",
                    rssOne.c_str(), statusLine("VmHWM:").c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "onelight-bench-render: %s\n", e.what());
        return 1;
    }
}
