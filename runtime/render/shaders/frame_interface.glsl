// The forward pass's resources: descriptor sets and push constants, declared with the bindings
// and records of shaders/gpu_interface.glsl (the one source shared with C++). Included by the
// forward entry points only.
#ifndef ONELIGHT_FRAME_INTERFACE_GLSL
#define ONELIGHT_FRAME_INTERFACE_GLSL

#include "gpu_interface.glsl"

// Set 0: the frame.
layout(set = 0, binding = BINDING_FRAME, std140) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = BINDING_SHADOW_VIEWS, std140) uniform ShadowViews {
    GpuShadowView shadowViews[MAX_SHADOW_VIEWS];
};
layout(set = 0, binding = BINDING_SHADOW_MAPS) uniform sampler2DArrayShadow shadowMaps;
layout(set = 0, binding = BINDING_PRIMARY_LIGHTS, std140) uniform PrimaryLights {
    GpuLight primaryLights[MAX_PRIMARY_RECORDS];
};
// Dynamic objects: the light grid sampled at each object's origin.
layout(set = 0, binding = BINDING_OBJECT_LIGHTING, std430) readonly buffer ObjectLighting {
    GpuObjectLighting objectLighting[];
};

// Baked lighting from the package (neutral placeholders for a level without it).
// Lightmap: layer 3 * atlas + channel holds (c0, cx, cy, cz) of irradianceLinear, times a
// power-of-two storage scale (frame.baked.y undoes it). Atlases share the array's size; an
// atlas smaller than the array sits at its top-left corner (draw.lightmapScale).
layout(set = 0, binding = BINDING_LIGHTMAP) uniform sampler2DArray lightmap;
// Layer atlas: r = the primary's baked visibility.
layout(set = 0, binding = BINDING_SHADOW_MASK) uniform sampler2DArray shadowMask;
// Environment probes (runtime/render/probe_records.hpp): cube i of the array is record i, in
// blending order; RGB9E5 normalised radiance, mip m prefiltered for probeGlossOfMip(m).
layout(set = 0, binding = BINDING_PROBES) uniform samplerCubeArray probes;
layout(set = 0, binding = BINDING_PROBE_RECORDS, std430) readonly buffer Probes {
    GpuProbe probeRecords[];
};
layout(set = 0, binding = BINDING_PROBE_CELLS, std430) readonly buffer ProbeCells {
    GpuProbeGrid probeGrid;
    uint probeCells[];
};
// The split-sum table (shaders/lighting.glsl, env_brdf_table.hpp; rg = scale, bias), read at
// envBrdfTableCoord(NoV, gloss): the probes' environment "Fresnel" and the diffuse's energy
// weight in one fetch.
layout(set = 0, binding = BINDING_ENV_BRDF) uniform sampler2D envBrdfTable;
// The level's sky image (equirectangular, linear, x frame.sky.rgb), a black texel without one.
layout(set = 0, binding = BINDING_SKY) uniform sampler2D skyImage;

layout(set = 0, binding = BINDING_MATERIAL_RECORDS, std140) uniform MaterialRecords {
    GpuMaterial materialRecords[MAX_MATERIAL_RECORDS];
};

// Set 1: the material's textures (placeholders where it has none).
layout(set = 1, binding = TEXTURE_BASE_COLOR) uniform sampler2D baseColorTexture;
layout(set = 1, binding = TEXTURE_METALLIC_ROUGHNESS) uniform sampler2D metallicRoughnessTexture;
layout(set = 1, binding = TEXTURE_NORMAL) uniform sampler2D normalTexture;
layout(set = 1, binding = TEXTURE_OCCLUSION) uniform sampler2D occlusionTexture;
layout(set = 1, binding = TEXTURE_EMISSIVE) uniform sampler2D emissiveTexture;
layout(set = 1, binding = TEXTURE_CAVITY) uniform sampler2D cavityTexture;
layout(set = 1, binding = TEXTURE_FACETS) uniform sampler2D facetTexture;

// Per draw.
layout(push_constant) uniform DrawBlock { DrawPush draw; };

// Whether the material fills texture slot `slot` (TEXTURE_*).
bool hasTexture(GpuMaterial m, int slot) { return (m.textures.x & (1u << uint(slot))) != 0u; }
// Whether the material has flag `flag` (MATERIAL_FLAG_*).
bool hasMaterialFlag(GpuMaterial m, int flag) { return (m.textures.y & uint(flag)) != 0u; }

#endif
