// The renderer's GPU interface: descriptor sets, push constants and records, as the C++ side
// (runtime/render/gpu_types.hpp) lays them out. Included by the entry points only.
#ifndef ONELIGHT_FRAME_INTERFACE_GLSL
#define ONELIGHT_FRAME_INTERFACE_GLSL

#define NO_INDEX 0xFFFFFFFFu
#define MAX_EFFECT_OMNIS 4

// Set 0, binding 0: per-frame values (FrameUniforms, std140).
layout(set = 0, binding = 0, std140) uniform FrameUniforms {
    mat4 viewProj;
    vec4 cameraPosition;  // xyz metres, w = exposure (pre-exposure of the HDR target)
    vec4 shadowParams;    // x runtime-shadow radius, y blend band (metres), z 1 / map size
    vec4 baked;           // x placeholder ambient (lux), y lightmap decode factor (stored x this = lux)
    vec4 probeParams;     // x mip count of the probes' cubes
    uvec4 counts;         // x effect omnis in use, y effect spot on (0/1), z probe records
    vec4 omniPositionRange[MAX_EFFECT_OMNIS];  // xyz metres, w range (0 unlimited)
    vec4 omniColor[MAX_EFFECT_OMNIS];          // rgb colour * intensity (candela)
    vec4 spotPositionRange;
    vec4 spotDirection;  // xyz unit, the way light travels
    vec4 spotColor;      // rgb colour * intensity (candela)
    vec4 spotCones;      // x cos inner, y cos outer
} frame;

// A level light (GpuLight, std430).
struct GpuLight {
    vec4 positionRange;   // xyz metres, w range
    vec4 direction;       // xyz unit, the way light travels
    vec4 color;           // rgb colour * intensity (lux or candela)
    vec4 cones;           // x cos inner, y cos outer
    uvec4 info;           // x type, y first shadow view or NO_INDEX
};
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };

// One shadow-map view (GpuShadowView, std430): layer i of the shadow array.
struct GpuShadowView {
    mat4 viewProj;
    vec4 params;  // x world texel size (ortho) or per metre of distance (perspective), y 1 = perspective
};
layout(set = 0, binding = 2, std430) readonly buffer ShadowViews { GpuShadowView shadowViews[]; };

layout(set = 0, binding = 3) uniform sampler2DArrayShadow shadowMaps;

// Baked lighting from the package (neutral placeholders for a level without it).
// Lightmap: layer 3 * atlas + channel holds (c0, cx, cy, cz) of irradianceLinear, times a
// power-of-two storage scale (frame.baked.y undoes it). Atlases share the array's size; an
// atlas smaller than the array sits at its top-left corner (draw.lightmapScale).
layout(set = 0, binding = 4) uniform sampler2DArray lightmap;
layout(set = 0, binding = 5) uniform sampler2DArray shadowMask;  // layer atlas: r = primary visibility
// Dynamic objects: the light grid sampled at each object's lighting origin (GpuObjectLighting).
struct GpuObjectLighting {
    vec4 ambientCube[6];  // rgb lux facing +x -x +y -y +z -z; [0].w baked visibility of the primary
};
layout(set = 0, binding = 6, std430) readonly buffer ObjectLighting { GpuObjectLighting objectLighting[]; };
// Environment probes (render/probe_records.hpp): cube i of the array is record i, in blending
// order; RGB9E5 normalised radiance, mip m prefiltered for probeGlossOfMip(m).
layout(set = 0, binding = 7) uniform samplerCubeArray probes;
struct GpuProbe {
    vec4 position;      // xyz capture point
    vec4 boxMin;        // xyz box-projection box, w 1 = box projection
    vec4 boxMax;
    vec4 influenceMin;  // xyz influence box, w blend band (metres)
    vec4 influenceMax;
};
layout(set = 0, binding = 10, std430) readonly buffer Probes { GpuProbe probeRecords[]; };

// A material (GpuMaterial, std430).
struct GpuMaterial {
    vec4 baseColor;  // linear RGBA factor
    vec4 f0Gloss;    // rgb specular colour factor, a gloss factor
    vec4 emissive;   // rgb emissive factor (exposure-relative), a alpha cutoff
    vec4 params;     // x metallic, y roughness, z normal scale, w occlusion strength
    uvec4 textures;  // x bit mask: 1 base, 2 metallic-roughness, 4 normal, 8 occlusion, 16 emissive
};
layout(set = 0, binding = 8, std430) readonly buffer Materials { GpuMaterial materials[]; };

// EnvBRDF_Fit(NoV, gloss) tabulated at texel centres (rg = scale, bias): one fetch instead of the
// 27-term fit per pixel.
layout(set = 0, binding = 9) uniform sampler2D envBrdfTable;

// Set 1: the material's textures (placeholders where it has none).
layout(set = 1, binding = 0) uniform sampler2D baseColorTexture;
layout(set = 1, binding = 1) uniform sampler2D metallicRoughnessTexture;
layout(set = 1, binding = 2) uniform sampler2D normalTexture;
layout(set = 1, binding = 3) uniform sampler2D occlusionTexture;
layout(set = 1, binding = 4) uniform sampler2D emissiveTexture;

// Per draw (DrawPush).
layout(push_constant) uniform DrawPush {
    mat4 model;            // world from object (identity for static surfaces)
    uint material;         // into materials
    uint primaryLight;     // into lights or NO_INDEX
    uint lightmapAtlas;    // atlas of a static surface, NO_INDEX for a dynamic object (grid)
    uint objectLighting;   // a dynamic object's record in objectLighting[], or NO_INDEX
    vec4 lightmapScale;    // xy: uv1 (over the surface's atlas) to the lightmap array's uv
} draw;

#endif
