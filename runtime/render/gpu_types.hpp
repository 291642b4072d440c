// The records the renderer shares with its shaders (shaders/frame_interface.glsl), laid out
// byte for byte: std140 for the uniform block, std430 for the storage buffers.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace onelight::render {

inline constexpr uint32_t kMaxEffectOmnis = 4;  // MAX_EFFECT_OMNIS
inline constexpr uint32_t kNoIndex = 0xFFFFFFFFu;
inline constexpr float kHdrMax = 65000.0f;  // HALF_MAX of forward.frag: the RGBA16F target's cap

struct FrameUniforms {
    glm::mat4 viewProj;
    glm::vec4 cameraPosition;  // xyz metres, w exposure
    glm::vec4 shadowParams;    // x radius, y band, z 1 / shadow map size, w 0
    glm::vec4 baked;           // x placeholder ambient (lux), y lightmap decode factor, zw 0
    glm::vec4 probeParams;     // x mip count of the probes' cubes, yzw 0
    glm::uvec4 counts;         // x effect omnis, y effect spot on, z probe records
    glm::vec4 omniPositionRange[kMaxEffectOmnis];
    glm::vec4 omniColor[kMaxEffectOmnis];
    glm::vec4 spotPositionRange;
    glm::vec4 spotDirection;
    glm::vec4 spotColor;
    glm::vec4 spotCones;
};
static_assert(sizeof(FrameUniforms) == 336);

struct GpuLight {
    glm::vec4 positionRange;
    glm::vec4 direction;
    glm::vec4 color;  // rgb colour * intensity
    glm::vec4 cones;  // x cos inner, y cos outer
    glm::uvec4 info;  // x type, y first shadow view or kNoIndex
};
static_assert(sizeof(GpuLight) == 80);

struct GpuShadowView {
    glm::mat4 viewProj;
    glm::vec4 params;  // x world texel size (per metre when perspective), y 1 = perspective
};
static_assert(sizeof(GpuShadowView) == 80);

struct GpuMaterial {
    glm::vec4 baseColor;
    glm::vec4 f0Gloss;
    glm::vec4 emissive;  // a = alpha cutoff
    glm::vec4 params;    // metallic, roughness, normal scale, occlusion strength
    glm::uvec4 textures;
};
static_assert(sizeof(GpuMaterial) == 80);

/// A dynamic object's baked lighting, sampled from the light grid at its lighting origin.
struct GpuObjectLighting {
    glm::vec4 ambientCube[6];  // rgb lux facing +x -x +y -y +z -z; [0].w baked primary visibility
};
static_assert(sizeof(GpuObjectLighting) == 96);

/// An environment probe (render/probe_records.hpp; shaders/probe.glsl for the rules).
struct GpuProbe {
    glm::vec4 position;      // xyz capture point, metres
    glm::vec4 boxMin;        // xyz box-projection box, w 1 = box projection
    glm::vec4 boxMax;        // xyz
    glm::vec4 influenceMin;  // xyz influence box, w blend band (metres)
    glm::vec4 influenceMax;  // xyz
};
static_assert(sizeof(GpuProbe) == 80);

struct DrawPush {
    glm::mat4 model;
    uint32_t material;
    uint32_t primaryLight;
    uint32_t lightmapAtlas;
    uint32_t objectLighting;  // into the object-lighting records or kNoIndex
    glm::vec4 lightmapScale;  // xy: uv1 (over the surface's atlas) to the lightmap array's uv
};
static_assert(sizeof(DrawPush) == 96);

}  // namespace onelight::render
