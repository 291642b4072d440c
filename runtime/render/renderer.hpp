// The forward renderer: one primary light per surface with its runtime shadow, up to four
// diffuse omni effect lights and one spot effect light, baked secondary lighting, HDR with
// exposure, a filmic colour LUT and sRGB output. One renderer for both backends: headless
// (readback of the frame) and a window (the frame is copied into a swapchain image).
//
// Use: loadLevel (runtime/assets) -> createContext with renderContextOptions -> createRenderer ->
// drawFrame per frame -> destroyRenderer -> destroyContext. Frames are submitted without waiting:
// while the GPU draws one, the CPU prepares the next (two frames in flight); a frame whose output
// is read back is waited for.
//
// The renderer draws what it is handed: dynamic objects' transforms and primaries come from the
// game (world/dynamic_primary.hpp picks them), never from the renderer.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "assets/level_assets.hpp"
#include "render/camera.hpp"
#include "render/gpu_types.hpp"
#include "vk/context.hpp"
#include "vk/swapchain.hpp"
#include "world/light_model.hpp"

namespace onelight::render {

/// A diffuse-only omni effect light (a gun flash), glTF units.
struct EffectOmni {
    glm::vec3 position{0.0f};  // metres
    glm::vec3 color{1.0f};     // linear
    float intensity = 0.0f;    // candela
    float range = 0.0f;        // metres, 0 = unlimited
};

/// The spot effect light (the flashlight): diffuse and specular, glTF units.
struct EffectSpot {
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit, the way light travels
    glm::vec3 color{1.0f};
    float intensity = 0.0f;  // candela
    float range = 0.0f;      // metres, 0 = unlimited
    float innerCone = 0.2f;  // radians
    float outerCone = 0.4f;  // radians
};

struct EffectLights {
    std::array<EffectOmni, kMaxEffectOmnis> omni{};
    uint32_t omniCount = 0;  // <= kMaxEffectOmnis
    bool spotOn = false;
    EffectSpot spot;
};

/// Where a dynamic entity is this frame (overrides the entity's placement in the package) and the
/// primary light it is lit by.
struct DynamicTransform {
    uint32_t entity = 0;  // into level.entities
    glm::mat4 worldFromObject{1.0f};
    uint32_t primary = kNoIndex;  // the game's pick, into level.lights; kNoIndex: no primary
    // While the pick cross-fades (world::kPrimaryFadeSeconds): the primary it leaves, lit at
    // 1 - fadeWeight, and `primary` at fadeWeight.
    uint32_t fadingFrom = kNoIndex;
    float fadeWeight = 1.0f;
    bool hidden = false;  // not drawn and casting no shadow (a taken item)
};

/// Everything a frame depends on besides the level: the same inputs give the same pixels.
struct FrameInputs {
    Camera camera;
    EffectLights effects;
    std::span<const DynamicTransform> dynamicTransforms;
};

/// Where the frame goes besides the renderer's own targets.
struct FrameOutput {
    bool readback = false;               // copy the frame to the CPU (capturedFrame)
    vk::Swapchain* swapchain = nullptr;  // borrowed: copy (or scale) the frame into...
    uint32_t swapchainImage = 0;         // ...this image (acquired), to present after
    bool readbackSwapchain = false;      // copy the swapchain image back too (screenshot)
    bool wait = false;  // wait for this frame and report its own GPU times (benchmarks)
};

/// What a frame cost and did. The GPU times are those of frame `gpuFrame`: this frame when
/// drawFrame waited for it (readback or FrameOutput::wait), else the frame kFramesInFlight
/// before it, whose end drawFrame waited for before reusing its resources.
struct FrameStats {
    uint64_t frame = 0;          // this frame's number, counted from 0 per renderer
    double cpuMs = 0.0;          // drawFrame on the CPU: culling, recording, submit (and any wait)
    bool gpuTimestamps = false;  // the GPU times below are set (the device gives timestamps
                                 // and frame gpuFrame has finished)
    uint64_t gpuFrame = 0;
    double gpuMs = 0.0;  // first to last timestamp
    double gpuShadowMs = 0.0;
    double gpuForwardMs = 0.0;
    double gpuTonemapMs = 0.0;
    uint32_t surfacesDrawn = 0, surfacesCulled = 0, dynamicMeshesDrawn = 0;
    uint32_t surfacesHidden = 0;       // of the culled, outside the potentially visible set
    uint32_t dynamicMeshesHidden = 0;  // in the frustum, but every surface around them hidden
    uint32_t draws = 0;                // forward-pass draw calls, after batching
    uint32_t pipelineBinds = 0;        // ...the pipelines and material sets they bind (each a
    uint32_t materialBinds = 0;        // change from the draw before)
    uint32_t frameSetBinds = 0;  // set 0 rebound for another page of material records (a level
                                 // of more than glsl::MAX_MATERIAL_RECORDS materials)
    uint32_t shadowViewsRendered = 0;  // static views redrawn this frame
    uint64_t trianglesDrawn = 0;       // forward pass
    float ev100 = 0.0f, exposure = 1.0f;
};

/// The last frame read back.
struct CapturedFrame {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;           // tonemapped, sRGB, top row first
    std::vector<float> linearRgba;        // cd/m^2 before exposure, top row first
    std::vector<uint8_t> swapchainRgba8;  // the swapchain image, when asked
};

struct RendererOptions {
    uint32_t width = 1280, height = 720;
    uint32_t requestedMsaa = 2;     // Black Ops' choice; the nearest supported is used
    uint32_t shadowMapSize = 1024;  // texels, every shadow layer
    uint32_t maxShadowLayers = 48;  // sun sunCascades, spot 1, omni 6 layers; <= MAX_SHADOW_VIEWS
    // Post-process anti-aliasing of the tonemapped frame (FXAA, runtime/render/shaders/
    // fxaa.frag), for MSAA 1x: docs/frame-rate.md compares the two on frame time and edge error.
    bool fxaa = false;
    // Static surfaces whose baked shadow mask is one value over all of them (world/
    // surface_shadow.hpp) skip their primary's shadow lookups: a wholly lit one is drawn
    // unshadowed while no dynamic caster's shadow may reach it, a wholly shadowed one without
    // its primary. Not exact: a shadow finer than the mask's texels (a thin pole's) is lost on
    // them (onelight-bench-render --view gives the pixels it changes). Off: every surface with a
    // primary looks up both shadows.
    bool skipUniformShadows = true;
    // The sun's shadow in cascades (render/shadows.hpp): 1 is one map over the whole radius,
    // whose 10 cm texels stair-step the courtyard's shadows near the camera.
    uint32_t sunCascades = 3;
    float shadowRadius =
        world::kRuntimeShadowRadius;  // metres from the camera with runtime shadows
    float shadowBand =
        world::kRuntimeShadowBand;        // metres over which they blend into the baked ones
    float placeholderAmbientLux = -1.0f;  // constant ambient without baked lighting; < 0 = auto
    int forceMaterialClass = -1;          // >= 0: every material in this class (benchmarks)
    bool flatShading = false;             // constant colour, no shadows (benchmark floor)
    // A depth-only pass over the opaque draws before the forward pass, so that the forward
    // shader runs once per visible sample (the forward pipelines' test is LESS_OR_EQUAL and the
    // same invariant vertex shader gives the same depth; alpha-masked draws are left to the
    // forward pass). Off: on lavapipe it does not pay (onelight-bench-render: 164 ms with it,
    // 149 without; aggressor's forward pass 285 against 266-277 ms), the frames are identical.
    bool depthPrepass = false;
    bool rasterFloor = false;  // with flatShading: the fewest draws, every adjacent index range
                               // merged whatever its material (the benchmark's raster floor)
    bool samplePlaceholders = false;  // fetch the placeholder baked textures anyway (tests);
                                      // else a level without baked lighting fetches none
    bool probes = true;  // false: the package's probes ignored, a uniform environment instead
    // The probes' statistic at the capture (shaders/probe.glsl, "Normalization"): false, the
    // mean of its irradiance over normals; true, its irradiance at the pixel's normal, as the
    // pixel's side is (the seed's same statistic at both ends: exact where the pixel is lit as
    // the capture point, worse in closed rooms; docs/lighting.md "Normalisation" measures both).
    bool probesPerNormal = false;
    // Static surfaces outside the camera cell's potentially visible set are not drawn
    // (world/visibility.hpp). The frame is the same either way (a test checks it).
    bool visibilityCulling = true;
    // createRenderer draws a hidden frame that uses every pipeline with every material's textures,
    // so that the shader variants a driver compiles at first draw are compiled at load and the
    // first frame shown does not stall (the stall is 3x a frame on lavapipe; off: to measure it).
    bool warmUp = true;
    // Forward pipelines specialized by what their draws need (forward_shading.glsl SPEC_TEXTURES,
    // SPEC_PRIMARY, SPEC_SECONDARY): the same pixels, without the fetches of the texture slots a
    // material leaves empty, of the primary's shadows where a surface has none, and of the
    // lightmap or grid record a draw does not read. Off: one pipeline per material class,
    // sidedness and alpha mode, choosing at run time (to measure it, and as the reference).
    bool specializeDraws = true;
    // Benchmarks only: forward_shading.glsl's FEATURE_* bits left out, each a constant instead
    // (onelight-bench-render --view measures what each costs; the frame is then wrong).
    uint32_t featuresOff = 0;
    // Anisotropic filtering of the material textures (1: off, else up to 16 taps along a
    // footprint's long axis, clamped to the device's limit). At grazing view a pixel's footprint
    // on the surface is long and thin: an isotropic mip is chosen by its long axis and blurs
    // across it. Off by default: with 16 taps from a finer mip, the spread of the normals along
    // the long axis is averaged into a renormalized normal and lost from the gloss, so a bumpy
    // glossy floor turns back into a mirror (onelight_render_material_mips_test: 2-6x the
    // isotropic error in every band). It pays once the shader folds the filtered normal's
    // shortening into gloss (docs/materials.md, "Anisotropic filtering").
    float anisotropy = 1.0f;
    // false: the forward pass without the material pipeline's runtime pieces (the fold of the
    // filter's spread, the cavity, the direct lights' energy weight), to measure their cost
    // (onelight-bench-render). The frame is then not the level's.
    bool materialPipeline = true;
};

/// What the renderer settled on.
struct RendererInfo {
    std::string deviceName;
    uint32_t msaaRequested = 0, msaaInUse = 0;
    std::vector<std::string> permutations;  // the forward pipelines built
    float autoEv100 = 0.0f;                 // exposure when neither camera nor level gives one
    float ambientLux = 0.0f;                // the placeholder ambient in use
    bool bakedLighting = false;             // lightmaps, shadow masks and grid from the package
    float lightmapDecode = 1.0f;            // lux per stored RGBA16F lightmap unit
    uint32_t shadowLayers = 0;
    uint32_t probes = 0;      // environment probes in use (0: the uniform placeholder)
    uint64_t probeBytes = 0;  // their cube array, every mip
    bool skyImage = false;    // the sky pass draws the level's sky image behind it
    double warmUpMs = 0.0;    // the warm-up frame in createRenderer (RendererOptions::warmUp)
    // Static surfaces with a primary whose baked mask is lit over all of them, and those it
    // shadows whole (RendererOptions::skipUniformShadows), of those with a primary.
    uint32_t surfacesUnoccluded = 0, surfacesInShadow = 0, surfacesWithPrimary = 0;
};

struct RendererState;  // render/renderer_state.hpp

/// The renderer of one level on one context. Not copyable; destroy with destroyRenderer.
struct Renderer {
    std::unique_ptr<RendererState> state;  // owned
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;
};

/// Device features the renderer needs (Vulkan 1.3 dynamic rendering), kept alive for
/// createContext.
struct RenderDeviceFeatures {
    VkPhysicalDeviceVulkan13Features vulkan13{};
};

/// Context options for the renderer: Vulkan 1.3 with dynamic rendering, plus the instance
/// extensions a window needs (pass glfwGetRequiredInstanceExtensions) and the swapchain.
[[nodiscard]] vk::ContextOptions renderContextOptions(
    RenderDeviceFeatures& features, const std::vector<const char*>& windowExtensions);

/// Uploads the level and builds the pipelines it needs. Throws std::runtime_error.
void createRenderer(Renderer& renderer, vk::Context& ctx, const assets::LoadedLevel& level,
                    const RendererOptions& options);

/// Waits for the device and destroys everything, in reverse order. Safe on an empty Renderer.
void destroyRenderer(Renderer& renderer);

[[nodiscard]] const RendererInfo& rendererInfo(const Renderer& renderer);

/// Records and submits one frame (shadow passes, forward pass, tonemap, outputs). It first waits
/// for the frame kFramesInFlight before (whose resources it reuses), and afterwards for this
/// frame only when `output` reads it back or asks to wait.
FrameStats drawFrame(Renderer& renderer, const FrameInputs& inputs, const FrameOutput& output = {});

/// Waits until every submitted frame has finished.
void waitForFrames(Renderer& renderer);

/// The frame of the last drawFrame with output.readback.
[[nodiscard]] const CapturedFrame& capturedFrame(const Renderer& renderer);

/// The primary light (into level.lights) the last frame drew dynamic entity `entity` with;
/// kNoIndex when it drew the entity with none, or did not draw it (culled, or not dynamic).
[[nodiscard]] uint32_t drawnPrimary(const Renderer& renderer, uint32_t entity);

/// Changes the size of the offscreen targets (a resized window).
void resizeRenderer(Renderer& renderer, uint32_t width, uint32_t height);

}  // namespace onelight::render
