// What a frame sees and draws, worked out on the CPU before recording (frame_view.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render/camera.hpp"
#include "render/gpu_types.hpp"
#include "render/renderer.hpp"
#include "render/scene.hpp"

namespace onelight::render {

/// Light records (gpu_interface.glsl GpuLight): a level light with its shadow views, and
/// the effect lights (no shadow).
[[nodiscard]] GpuLight gpuLightOf(const world::Light& light, ShadowViewRange shadowViews);
[[nodiscard]] GpuLight gpuLightOf(const EffectOmni& omni);
[[nodiscard]] GpuLight gpuLightOf(const EffectSpot& spot);

/// One draw of the forward pass.
struct Draw {
    uint32_t key = 0;  // permutationKey of the material (0 with flat shading)
    uint32_t material = 0;
    uint32_t firstIndex = 0, indexCount = 0;
    int32_t vertexOffset = 0;
    uint32_t primaryLight = kNoIndex, atlas = kNoIndex;
    uint32_t primaryKind = 0;    // a static surface's PRIMARY_* (DrawSurface::primaryKind)
    uint32_t entity = kNoIndex;  // kNoIndex for static; a dynamic object's record in objectLighting
    uint32_t fadeLight = kNoIndex;  // a dynamic object's old primary while it cross-fades
    float primaryWeight = 1.0f;     // primaryLight's share (fadeLight's is 1 - this)
    bool primaryShadow = true;      // false: an unoccluded surface no dynamic shadow reaches
    bool directEdges = false;       // its lightmap draws a baked shadow edge (DrawSurface's)
    float distance2 = 0.0f;         // squared metres from the camera: dynamic draws front to back
};

/// The camera, the exposure and the dynamic objects' transforms and primaries of one frame.
struct FrameView {
    Camera camera;
    glm::mat4 projection{1.0f}, viewProj{1.0f};
    float ev100 = 0.0f, exposure = 1.0f;
    std::vector<glm::mat4> entityTransforms;  // per entity: given, else its placement
    std::vector<uint32_t> entityPrimary;      // per entity: the game's pick, or kNoIndex
    std::vector<uint8_t> entityHidden;        // per entity: 1 = not drawn, no shadow
    std::vector<uint32_t> entityFadeFrom;     // per entity: the primary it cross-fades from
    std::vector<float> entityPrimaryWeight;   // per entity: its primary's share (1 not fading)
    bool effectLights = false;                // any effect omni or the spot is on
};
/// The view of a frame `aspect` wide per unit of height.
[[nodiscard]] FrameView frameViewOf(const LevelData& level, float aspect,
                                    const FrameInputs& inputs);

/// Orders the culled draws for recording and merges each run of static draws that bind and push
/// the same state (pipeline, material, primary, lightmap atlas) over adjacent index ranges into
/// one draw; dynamic meshes stay one draw each, front to back. With geometryOnly every adjacent
/// range merges whatever it binds (the raster floor, RendererOptions::rasterFloor).
void batchDraws(std::vector<Draw>& draws, bool geometryOnly);

/// The frame's draws, sorted by pipeline then front to back, and the primaries they use.
struct DrawList {
    std::vector<Draw> draws;
    std::vector<uint32_t> visibleLights;  // sorted, unique
    std::vector<uint8_t> entityVisible;   // per entity
};
/// Culls static surfaces (against the frustum and the baked visibility) and dynamic meshes
/// (against the frustum); counts them in `stats`. An unoccluded surface is drawn with its
/// primary's shadow when a dynamic caster's shadow may reach it (any dynamic mesh, seen or not).
[[nodiscard]] DrawList buildDrawList(const Scene& scene, const RendererOptions& options,
                                     const FrameView& view, FrameStats& stats);

/// The warm-up frame's draws (createRenderer): one triangle of the first surface or dynamic mesh
/// of each material and pipeline, for frames with effect lights and without, so that every
/// forward pipeline is drawn once with every material's textures bound, and `shadowedLight`
/// (kNoIndex: none) as the one visible light, so that the shadow pipeline is drawn too.
[[nodiscard]] DrawList warmUpDrawList(const SceneGeometry& geometry,
                                      const SceneMaterials& materials,
                                      const RendererOptions& options, size_t entityCount,
                                      uint32_t shadowedLight);

/// The grid's lighting of every visible dynamic object, into `out` (one record per entity): at
/// its origin, or for an object longer than a grid cell at a lattice over its bounds, a cell or
/// less apart along each edge and on both faces of a thin one (at most 8 x 3 x 2 =
/// MAX_OBJECT_SAMPLES; GpuObjectLighting), which the shader interpolates trilinearly.
void writeObjectLighting(const LevelData& level, const BakedLightingMaps& baked,
                         const SceneGeometry& geometry, const FrameView& view, const DrawList& list,
                         GpuObjectLighting* out);

/// The frame's uniforms: camera, exposure, shadow and baked parameters, effect lights.
[[nodiscard]] FrameUniforms frameUniformsOf(const Scene& scene, const RendererOptions& options,
                                            const FrameView& view, const EffectLights& effects);

}  // namespace onelight::render
