// The renderer's GPU interface, written once for GLSL and C++ (see common.glsl for the dialect):
// the limits, the descriptor bindings, the specialization constants, the material texture slots
// and the records the renderer shares with its shaders, laid out byte for byte: std140 for the
// uniform blocks, std430 for the storage buffers and the push constants. Every member is a
// vec4, a mat4 or a 4-byte scalar in an order without padding, so both layouts equal C++'s.
//
// Only constants and structs live here (no functions): C++ includes it once, outside an anonymous
// namespace (runtime/render/gpu_types.hpp), so the records are one type in every translation
// unit. The GLSL resource declarations that use it are in runtime/render/shaders/
// frame_interface.glsl.
#ifndef ONELIGHT_GPU_INTERFACE_GLSL
#define ONELIGHT_GPU_INTERFACE_GLSL

// ---------------------------------------------------------------------------------------------
// Limits and markers

const uint NO_INDEX = 0xFFFFFFFFu;  // "none" in every index field (world::kNoIndex)
const uint MAX_EFFECT_OMNIS = 4u;   // Black Ops' budget of diffuse omni effect lights
const float HDR_MAX = 65000.0f;     // the RGBA16F targets' cap (half's largest finite is 65504)
// The lightmap array's layers per atlas (runtime/render/scene.cpp uploadLightmaps): 0..2 the
// irradianceLinear coefficients of red, green and blue; 3 the baked direct light's irradiance
// (rgb) and visibility (a); 4 its direction (xyz, not scaled); 5 the rest's average over normals
// (rgb).
const uint LIGHTMAP_LAYERS = 6u;
const uint LIGHTMAP_LAYER_DIRECT = 3u;
const uint LIGHTMAP_LAYER_DIRECT_LIGHT = 4u;
const uint LIGHTMAP_LAYER_INDIRECT = 5u;
// The shadow mask's green, blue and alpha channels (unorm; runtime/render/scene.cpp): the direct
// light's signed distance to its shadow edge in penumbra widths (the width at least
// DIRECT_EDGE_MIN_WIDTH texels, the distance within +-DIRECT_EDGE_RAMPS of them), and the edge's
// low and high levels of visibility (both the texel's visibility where no edge is drawn):
// directEdgeFactor, lighting.glsl. One fetch that a draw makes anyway, and a pixel near an edge
// fetches the direct layer for the rest.
const float DIRECT_EDGE_RAMPS = 16.0f;
const float DIRECT_EDGE_MIN_WIDTH = 0.125f;

// ---------------------------------------------------------------------------------------------
// Descriptor set 0: the frame's resources.

const int BINDING_FRAME = 0;          // uniform FrameUniforms
const int BINDING_SHADOW_VIEWS = 1;   // uniform GpuShadowView[MAX_SHADOW_VIEWS]
const int BINDING_SHADOW_MAPS = 2;    // sampler2DArrayShadow
const int BINDING_LIGHTMAP = 3;       // sampler2DArray, LIGHTMAP_LAYERS per atlas
const int BINDING_SHADOW_MASK = 4;    // sampler2DArray
const int BINDING_PROBES = 5;         // samplerCubeArray
const int BINDING_ENV_BRDF = 6;       // sampler2D
const int BINDING_PROBE_RECORDS = 7;  // storage GpuProbe[]
const int BINDING_SKY = 8;            // sampler2D, the sky image (shaders/sky.glsl)
const int BINDING_PROBE_CELLS = 9;    // storage GpuProbeGrid then uint[] (probe_records.hpp)
// The primary lights' records, a uniform array read at the draw's index (draw.primaryLight): at
// a draw-uniform place a CPU rasterizer loads a uniform block's element once for a block of
// pixels, where a storage buffer's is loaded per pixel (llvmpipe gathers every lane).
const int BINDING_PRIMARY_LIGHTS = 10;   // uniform GpuLight[MAX_PRIMARY_RECORDS]
const int BINDING_OBJECT_LIGHTING = 11;  // storage GpuObjectLighting[], per entity
// The materials' records, a uniform array read at the draw's index (draw.material), bound once
// for the pass: a page of up to MAX_MATERIAL_RECORDS at a dynamic offset (a level of more
// materials rebinds the set where its draws cross to another page). Not a uniform block of its
// own per material: lavapipe re-specialises the bound shaders to the values of a uniform block
// (its uniform inlining) at every bind of one, about 1.3 ms each (docs/frame-rate.md); nor a
// storage buffer, which llvmpipe loads lane by lane.
const int BINDING_MATERIAL_RECORDS = 12;  // uniform GpuMaterial[MAX_MATERIAL_RECORDS], dynamic
const int FRAME_BINDING_COUNT = 13;
const uint MAX_MATERIAL_RECORDS = 512u;  // a page: 40 KiB of records
// The primary lights a level may have (40 KiB of records; the renderer refuses more, and a
// device whose uniform range is smaller).
const uint MAX_PRIMARY_RECORDS = 512u;
// The shadow views a frame can hold (RendererOptions::maxShadowLayers is clamped to it): 15 KiB,
// under Vulkan's smallest guaranteed uniform range (16 KiB).
const uint MAX_SHADOW_VIEWS = 192u;

// Descriptor set 1: a material's textures, binding = slot (images only: binding one costs no
// re-specialisation). GpuMaterial.textures.x holds bit (1 << slot) for every slot the material
// fills (the others hold placeholders).
const int TEXTURE_BASE_COLOR = 0;
const int TEXTURE_METALLIC_ROUGHNESS = 1;
const int TEXTURE_NORMAL = 2;
const int TEXTURE_OCCLUSION = 3;
const int TEXTURE_EMISSIVE = 4;
const int TEXTURE_CAVITY = 5;  // R8, made from the normal map by the texture stage
const int TEXTURE_FACETS = 6;  // R16F, the normal map's facet table (texture stage)
const int TEXTURE_SLOT_COUNT = 7;

// The tonemap pass's set 0.
const int BINDING_TONEMAP_HDR = 0;  // sampler2D, the resolved pre-exposed frame
const int BINDING_TONEMAP_LUT = 1;  // sampler3D, the colour LUT

// The post-process anti-aliasing pass's set 0 (RendererOptions::fxaa).
const int BINDING_FXAA_INPUT = 0;  // sampler2D, the tonemapped frame

// Specialization constants of forward_shading.glsl.
const int SPEC_MATERIAL_CLASS = 0;     // MATERIAL_* of lighting.glsl
const int SPEC_ALPHA_MODE = 1;         // ALPHA_MODE_*: the materials' glTF alpha mode
const int SPEC_FLAT_SHADING = 2;       // 1: constant colour (the benchmark floor)
const int SPEC_BAKED_LIGHTING = 3;     // 1: fetch the baked lighting (or its placeholders)
const int SPEC_DIFFUSE_MODEL = 4;      // DIFFUSE_* of lighting.glsl: the level's diffuse model
const int SPEC_MATERIAL_PIPELINE = 5;  // 0: without the material pipeline's pieces (benchmark)
const int SPEC_PROBES = 6;             // 0: a uniform environment, no probe fetched (none in use)
// What the draws of a pipeline need, so that what they do not is compiled out (a CPU rasterizer
// runs both sides of a branch under a mask: every texture behind an untaken branch is fetched).
const int SPEC_TEXTURES = 7;  // bit mask of the TEXTURE_* slots its materials may use
const int SPEC_PRIMARY = 8;   // PRIMARY_*: its draws' primary light, by type
const int SPEC_SECONDARY = 9;  // SECONDARY_*: where its draws' baked secondary lighting comes from
const int SPEC_EFFECT_LIGHTS = 10;  // 0: the frame has no effect light; 1: the frame's counts say
// Benchmarks only (onelight-bench-render --view): features left out, each a constant instead, to
// measure what it costs. Bits FEATURE_*; the frame is then wrong.
const int SPEC_FEATURES_OFF = 11;
// 0: its draws' primary is unoccluded (their baked masks are lit over them and no dynamic caster's
// shadow may reach them): neither shadow is looked up. 1: the runtime map and the baked mask.
const int SPEC_PRIMARY_SHADOW = 12;
// 1: its draws may cross-fade a dynamic object's primary switch (draw.fadeLight, when not
// NO_INDEX, lit at 1 - draw.primaryWeight); 0: compiled out (no draw of it fades).
const int SPEC_PRIMARY_FADE = 13;
// 1: its draws' lightmaps may draw a baked direct light's shadow edge (DrawSurface::directEdges);
// 0: compiled out (llvmpipe runs both sides of a branch, so the edge's fetches would cost every
// lightmapped pixel).
const int SPEC_DIRECT_EDGES = 14;
const int FEATURE_BASE_TEXTURE = 1;      // base colour texel: 1
const int FEATURE_LIGHTMAP = 2;          // a static surface's lightmap: the constant ambient
const int FEATURE_RUNTIME_SHADOW = 4;    // the primary's shadow map: unshadowed
const int FEATURE_BAKED_SHADOW = 8;      // the primary's shadow mask: unshadowed
const int FEATURE_PRIMARY = 16;          // the primary light: none
const int FEATURE_EMISSIVE_TEXTURE = 32; // emissive texel: 1
const int FEATURE_DIRECT_EDGE = 64;      // the baked direct light's edge: its bilinear visibility
const int SECONDARY_ANY = 0;       // the draw's push says (a lightmap atlas, an object record)
const int SECONDARY_LIGHTMAP = 1;  // a static surface's lightmap atlas
const int SECONDARY_OBJECT = 2;    // a dynamic object's grid record
const int SECONDARY_CONSTANT = 3;  // neither: the constant ambient
const int ALL_TEXTURES = 127;      // (1 << TEXTURE_SLOT_COUNT) - 1
const int PRIMARY_NONE = 0;         // no draw has one
const int PRIMARY_ANY = 1;          // the draw's push says which, of any type
const int PRIMARY_DIRECTIONAL = 2;  // 2 + LIGHT_* (lighting.glsl): each draw's is of that type
const int PRIMARY_POINT = 3;
const int PRIMARY_SPOT = 4;

const int ALPHA_MODE_OPAQUE = 0;  // world::AlphaMode: alpha ignored
const int ALPHA_MODE_MASK = 1;    // discarded below the cutoff
const int ALPHA_MODE_BLEND = 2;   // blended over what is behind by its alpha

// ---------------------------------------------------------------------------------------------
// Records

// A light: a level light (storage buffer) or an effect light (in FrameUniforms).
struct GpuLight {
    vec4 positionRange;  // xyz metres, w range (0 unlimited)
    vec4 direction;      // xyz unit, the way light travels
    vec4 color;          // rgb colour * intensity (lux or candela)
    vec4 cones;          // x cos inner, y cos outer
    uvec4 info;          // x type (LIGHT_* of lighting.glsl), y first shadow view or NO_INDEX,
                         // z shadow views (a sun's cascades, nearest first; an omni's 6 faces)
};

// Per-frame values (uniform block, std140).
struct FrameUniforms {
    mat4 viewProj;
    vec4 cameraPosition;  // xyz metres, w exposure (pre-exposure of the HDR target)
    vec4 shadowParams;    // x runtime-shadow radius, y blend band (metres), z 1 / map size
    vec4 baked;           // x placeholder ambient (lux), y lightmap decode (stored x this = lux)
    vec4 probeParams;     // x mip count of the probes' cubes, y 1: normalised per normal
    uvec4 counts;         // x effect omnis in use, y effect spot on (0/1), z probe records
    mat4 skyFromClip;     // clip position to world direction: inverse(proj x view's rotation)
    vec4 sky;             // rgb the sky image's scale (cd/m^2 per unit), w 1 = drawn
    GpuLight effectOmnis[MAX_EFFECT_OMNIS];  // diffuse only; info.y NO_INDEX (no shadow)
    GpuLight effectSpot;                     // the flashlight; no shadow
};

// One shadow-map view: layer i of the shadow array.
struct GpuShadowView {
    mat4 viewProj;
    vec4 params;  // x world texel size (ortho) or per metre of distance (perspective), y 1 =
                  // perspective, z a sun cascade's far view distance (metres)
};

// A material: the glTF factors; textures.x is the bit mask of TEXTURE_* slots in use.
struct GpuMaterial {
    vec4 baseColor;  // linear RGBA factor
    vec4 f0Gloss;    // rgb specular colour factor, a gloss factor
    vec4 emissive;   // rgb emission factor (cd/m^2), a alpha cutoff
    vec4 params;     // x metallic, y roughness, z normal scale, w occlusion strength
    uvec4 textures;  // x bit mask (1 << TEXTURE_*), y flags (MATERIAL_FLAG_*)
};
// The metallic-roughness texture's A is the normal map's texels' own roughness under each mip
// texel (world::MaterialTextureSlots::baseRoughnessInAlpha; shaders/material.glsl, "A
// footprint's bumps").
const int MATERIAL_FLAG_BASE_ROUGHNESS = 1;
// The normal texture's A is the kurtosis k of the slopes under each mip texel, as (k - 1) / 2
// (world::MaterialTextureSlots::slopeKurtosisInNormalAlpha).
const int MATERIAL_FLAG_SLOPE_KURTOSIS = 2;

// A dynamic object's baked lighting: the light grid sampled at its origin, or, for an object
// longer than a grid cell, at a lattice over its bounds (runtime/render/frame_view.hpp,
// writeObjectLighting), which a pixel interpolates trilinearly by where it lies in the box.
const uint MAX_OBJECT_SAMPLES = 48u;  // 8 x 3 x 2: along the box's longest, middle, shortest edge
struct GpuObjectLighting {
    vec4 from;     // xyz world metres: the lattice's first sample (a corner of the box)
    vec4 axes[3];  // xyz: the box's edge a in the world over its squared length (a point's
                   // dot with it from `from` is its place along the edge, 0..1); w: samples
                   // along it (1: one, and the edge is ignored)
    vec4 ambientCube[MAX_OBJECT_SAMPLES * 6u];  // sample s = i + n0 (j + n1 k) at 6 s .. 6 s + 5:
                                                // rgb lux facing +x -x +y -y +z -z; [6 s].w the
                                                // baked visibility of the primary there
};

// An environment probe (runtime/render/probe_records.hpp; shaders/probe.glsl for the rules).
struct GpuProbe {
    vec4 position;      // xyz capture point, metres
    vec4 boxMin;        // xyz box-projection box, w 1 = box projection
    vec4 boxMax;        // xyz
    vec4 influenceMin;  // xyz influence box, w blend band (metres)
    vec4 influenceMax;  // xyz
    // rgb: the capture's irradiance on surfaces facing +x -x +y -y +z -z over its mean
    // (world::EnvironmentProbe::irradianceCube / irradianceAverage; shaders/probe.glsl,
    // "Normalization")
    vec4 relativeIrradiance[6];
};

// The probes' cell grid (runtime/render/probe_records.hpp): a box of dims cells of cellSize
// metres from origin. Behind it, cell c's list starts at word probeCells[2c] of the same array
// and holds probeCells[2c + 1] & 0xFFFF records whose influence reaches the cell, in blending
// order, then probeCells[2c + 1] >> 16 records that can be the nearest probe to a point in it.
// dims.w 0: no grid (every record is walked).
struct GpuProbeGrid {
    vec4 origin;    // xyz metres
    vec4 cellSize;  // xyz metres
    uvec4 dims;     // xyz cells, w 1 = the grid is in use
};

// Per draw (push constants).
struct DrawPush {
    mat4 model;            // world from object (identity for static surfaces)
    uint material;         // its material's record in the bound page of materialRecords[]
    uint primaryLight;     // its primary light's record in primaryLights[], or NO_INDEX
    uint lightmapAtlas;    // a static surface's atlas, NO_INDEX for a dynamic object (grid)
    uint objectLighting;   // a dynamic object's record in objectLighting[], or NO_INDEX
    vec4 lightmapScale;    // xy: uv1 (over the surface's atlas) to the lightmap array's uv
    uint fadeLight;        // a dynamic object's old primary's record while it cross-fades, else
                           // NO_INDEX
    float primaryWeight;   // primaryLight's share of the light (fadeLight's is 1 - this)
    uint drawPad0, drawPad1;
};

// Per draw of an alpha-masked shadow caster (push constants; its material's set 1 bound as set 0).
struct MaskedShadowPush {
    mat4 clipFromObject;
    vec4 alpha;  // x the base colour factor's alpha, y the alpha cutoff (GpuMaterial emissive.a)
};

#endif
