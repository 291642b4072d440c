// The .olpak level package: the whole on-disk format in one header.
//
// Layout, little-endian throughout:
//   FileHeader                        at offset 0
//   SectionEntry[sectionCount]       right after the header
//   section payloads                  each at an offset that is a multiple of 8, zero-padded
//
// A section is an array of one record type (or bytes). Records refer to each other by index
// and by first/count ranges, never by pointer or offset; kNoIndex marks "none". Strings live
// in the strings section and are referred to by StringRef. Every section carries a CRC32
// (IEEE 802.3, as zlib) of its bytes; the header carries one over itself and the table.
//
// `onelight-bake compile` writes every core section (possibly empty). The baker adds the
// baked-lighting sections (ids 32 and up) later; a reader keeps those it does not parse as
// raw bytes. Any other change of layout bumps kVersion.
#pragma once

#include <bit>
#include <cstdint>

#include "world/no_index.hpp"

namespace onelight::package {

static_assert(std::endian::native == std::endian::little,
              "the .olpak reader/writer copy records "
              "as they are; add byte swaps to port");

inline constexpr uint32_t kMagic = 0x4B504C4Fu;  // "OLPK" as the first four bytes
inline constexpr uint32_t kVersion = 9;  // 2: DiskLevel holds the sky; 3: its image; 4: models;
                                         // 5: items; 6: movers; 7: lightmap texels' direct part;
                                         // 8: its shadow edge; 9: a normal map's facet table
using world::kNoIndex;                   // world/no_index.hpp
inline constexpr uint32_t kMaxSections = 64;
inline constexpr uint32_t kSectionAlignment = 8;

enum SectionId : uint32_t {
    kSectionStrings = 0,           // char[]: UTF-8 bytes of every string, no terminators
    kSectionLevel = 1,             // DiskLevel[1]
    kSectionMaterials = 2,         // DiskMaterial[]
    kSectionTextures = 3,          // DiskTexture[]
    kSectionImages = 4,            // DiskImage[]
    kSectionImageBytes = 5,        // uint8_t[]: encoded (PNG/JPEG) bytes of embedded images
    kSectionLights = 6,            // DiskLight[]
    kSectionCameras = 7,           // DiskCamera[]
    kSectionVertices = 8,          // DiskVertex[]: static, world space
    kSectionIndices = 9,           // uint32_t[]: static triangles, grouped by leaf then surface
    kSectionSurfaces = 10,         // DiskSurface[]
    kSectionGivenUpLights = 11,    // uint32_t[]: light indices, ranges owned by surfaces
    kSectionCharts = 12,           // DiskChart[]
    kSectionAtlases = 13,          // DiskAtlas[]
    kSectionBspPlanes = 14,        // DiskBspPlane[]
    kSectionBspNodes = 15,         // DiskBspNode[]: node 0 is the root when any exists
    kSectionBspLeaves = 16,        // DiskBspLeaf[]: >= 1
    kSectionDynamicVertices = 17,  // DiskVertex[]: in their mesh's space
    kSectionDynamicIndices = 18,   // uint32_t[]: relative to the mesh's firstVertex
    kSectionDynamicMeshes = 19,    // DiskDynamicMesh[]
    kSectionEntities = 20,         // DiskEntity[]
    kSectionFeatures = 21,         // DiskFeatures[1]
    kSectionMovers = 22,           // DiskMover[]
    kSectionMoverPoints = 23,      // DiskMoverPoint[]: trains' paths, ranges owned by movers
    kCoreSectionCount = 24,        // ids below this are required, exactly once each
    // Baked lighting, added by the baker; unknown to `compile`, kept raw by the reader.
    kSectionLightmapTexels = 32,    // directional secondary irradiance per atlas
    kSectionShadowMasks = 33,       // baked primary shadow masks per atlas
    kSectionLightGrid = 34,         // dynamic objects' secondary lighting and dominant primary
    kSectionProbes = 35,            // prefiltered, normalised environment probes
    kSectionImportedLightmap = 36,  // the source format's own bake at the same texels
    kSectionVisibility = 37,        // potentially visible sets: view cells -> clusters of surfaces
    // Textures made by the texture stage: mip chains and per-material slots; kept raw too.
    kSectionProcessedTextures = 38,
    kSectionErrorBudget = 39,  // DiskErrorBudget[1]: what --error-budget left out, and why
    kSectionShardRange = 40,   // DiskShardRange[1]: what an unmerged part of a sharded bake holds
    // The player's collision (written by `compile` for a Quake 3 map, absent for glTF levels;
    // decoded into CompiledLevel::collision by the reader, never kept raw).
    kSectionCollision = 41,  // uint8_t[]: DiskCollisionHeader, planes, side planes, brushes
    kSectionTriggers = 42,   // DiskTrigger[]: jump pads, teleporters, hurt volumes
    kSectionIdLimit = 48,    // ids at or above this are invalid
};

struct FileHeader {
    uint32_t magic;         // kMagic
    uint32_t version;       // kVersion
    uint32_t headerSize;    // sizeof(FileHeader)
    uint32_t sectionCount;  // entries in the section table, kCoreSectionCount..kMaxSections
    uint64_t fileSize;      // bytes, the whole file
    uint32_t tableCrc32;    // CRC32 of this header (with this field 0) and the section table
    uint32_t reserved;      // 0
};
static_assert(sizeof(FileHeader) == 32);

struct SectionEntry {
    uint32_t id;           // SectionId, each at most once
    uint32_t elementSize;  // bytes per record; the record's sizeof for core sections
    uint64_t offset;       // bytes from the start of the file, multiple of 8, after the table
    uint64_t size;         // bytes, == count * elementSize, offset + size <= fileSize
    uint32_t count;        // records
    uint32_t crc32;        // CRC32 of the section's size bytes
};
static_assert(sizeof(SectionEntry) == 32);

struct StringRef {
    uint32_t offset;  // bytes into the strings section
    uint32_t length;  // bytes; offset + length <= strings size
};
static_assert(sizeof(StringRef) == 8);

struct DiskLevel {
    float exposureEv100;   // default exposure, EV100; valid when hasExposure
    uint32_t hasExposure;  // 0 or 1
    float texelsPerMetre;  // requested lightmap density, > 0
    float boundsMin[3];    // metres, static geometry (0 when there is none)
    float boundsMax[3];    // metres, >= boundsMin
    float probeSpacing;    // metres between automatic probes, >= 0; 0 = the baker's default
    float skyRadiance[3];  // cd/m^2, RGB, finite, >= 0: the uniform sky (0 = none), or the scale
                           // of skyImage's texels
    uint32_t skyImage;     // into images: an equirectangular Radiance .hdr sky, or kNoIndex
    uint8_t diffuseModel;  // world::DiffuseModel: 0 Lambert, 1 multiscatter
    uint8_t glossMips;     // world::GlossMipMethod: 0 blit, 1 Black Ops, 2 WWII
    uint16_t reserved;     // 0
};
static_assert(sizeof(DiskLevel) == 60);

struct DiskMaterial {
    StringRef name;
    float baseColor[4];                 // linear RGBA factor, [0,1]
    float metallic;                     // [0,1]
    float roughness;                    // perceptual, [0,1]
    float albedo[3];                    // baseColor * (1 - metallic)
    float specularColor[3];             // mix(0.04, baseColor, metallic)
    float gloss;                        // [0,1], log2(2 / roughness^4 - 1) / 18
    float emissive[3];                  // linear, >= 0
    float alphaCutoff;                  // [0,1]
    float normalScale;                  // glTF normalTexture.scale
    float occlusionStrength;            // [0,1]
    uint32_t baseColorTexture;          // into textures or kNoIndex
    uint32_t metallicRoughnessTexture;  // into textures or kNoIndex
    uint32_t normalTexture;             // into textures or kNoIndex
    uint32_t occlusionTexture;          // into textures or kNoIndex
    uint32_t emissiveTexture;           // into textures or kNoIndex
    uint8_t alphaMode;                  // 0 opaque, 1 mask, 2 blend
    uint8_t doubleSided;                // 0 or 1
    uint8_t materialClass;              // 0 metal, 1 dielectric, 2 full, 3 lambert
    uint8_t flags;                      // kMaterialFlag* bits, the others 0
};
static_assert(sizeof(DiskMaterial) == 108);
/// DiskMaterial::flags: the surface casts no shadow (world::Material::castsShadows false).
inline constexpr uint8_t kMaterialFlagNoShadows = 1;

struct DiskTexture {
    uint32_t image;      // into images or kNoIndex
    uint16_t magFilter;  // glTF/GL enum, 0 = unspecified
    uint16_t minFilter;  // glTF/GL enum, 0 = unspecified
    uint16_t wrapS;      // 33071 clamp, 33648 mirrored, 10497 repeat
    uint16_t wrapT;      // as wrapS
};
static_assert(sizeof(DiskTexture) == 12);

struct DiskImage {
    StringRef name;
    StringRef uri;       // file reference relative to the package's folder; empty if embedded
    StringRef mimeType;  // may be empty for file references
    uint32_t firstByte;  // into image_bytes
    uint32_t byteCount;  // 0 for file references
};
static_assert(sizeof(DiskImage) == 32);

struct DiskLight {
    StringRef name;
    uint8_t type;         // 0 directional, 1 point, 2 spot
    uint8_t role;         // 0 primary, 1 baked (secondary only), 2 effect (runtime only)
    uint8_t reserved[2];  // 0
    float color[3];       // linear RGB, >= 0
    float intensity;      // lux (directional) or candela (point, spot), >= 0
    float range;          // metres, 0 = unlimited
    float innerCone;      // radians, spot: 0 <= inner < outer
    float outerCone;      // radians, spot: <= pi/2
    float position[3];    // metres, world
    float direction[3];   // unit, world, the way light travels
};
static_assert(sizeof(DiskLight) == 64);

struct DiskCamera {
    StringRef name;         // node name, what --camera NAME matches
    uint32_t orthographic;  // 0 or 1
    float yfov;             // radians (perspective)
    float aspectRatio;      // 0 = the window's
    float znear;            // metres, > 0 for perspective
    float zfar;             // metres, 0 = infinite
    float xmag, ymag;       // metres (orthographic)
    float position[3];      // metres, world
    float rotation[4];      // unit quaternion x, y, z, w: world from camera (looks down -Z)
    float exposureEv100;    // valid when hasExposure
    uint32_t hasExposure;   // 0 or 1
};
static_assert(sizeof(DiskCamera) == 72);

struct DiskVertex {
    float position[3];  // metres
    float normal[3];    // unit
    float tangent[4];   // xyz unit, w = +-1 bitangent sign
    float uv0[2];       // material coordinates
    float uv1[2];       // lightmap coordinates over the surface's atlas, [0,1]
};
static_assert(sizeof(DiskVertex) == 56);

struct DiskSurface {
    uint32_t firstIndex;      // into indices, multiple of 3
    uint32_t indexCount;      // > 0, multiple of 3
    uint32_t material;        // into materials
    uint32_t primaryLight;    // into lights (role primary) or kNoIndex when the level has none
    uint32_t chart;           // into charts
    uint32_t atlas;           // into atlases, == charts[chart].atlas
    uint32_t lightmapX;       // texels, == charts[chart].x
    uint32_t lightmapY;       // texels
    uint32_t lightmapWidth;   // texels, padding included
    uint32_t lightmapHeight;  // texels
    uint32_t firstGivenUp;    // into given_up_lights
    uint32_t givenUpCount;    // primaries reaching the surface it bakes as secondary
    uint32_t leaf;            // into bsp_leaves; the leaf's surface range holds this surface
    float boundsMin[3];       // metres, world
    float boundsMax[3];       // metres, world
};
static_assert(sizeof(DiskSurface) == 76);

struct DiskChart {
    uint32_t atlas;          // into atlases
    uint32_t x, y;           // texels, top-left of the rectangle
    uint32_t width, height;  // texels, padding included; x + width <= atlas width
    uint32_t padding;        // texels kept free inside the rectangle on each side
    float texelsPerMetre;    // density used, > 0 for generated charts
    uint32_t authored;       // 1 when coordinates came from TEXCOORD_1
    float origin[3];         // world point of texel (x + padding, y + padding)
    float axisU[3];          // unit, world direction of +x texels
    float axisV[3];          // unit, world direction of +y texels
};
static_assert(sizeof(DiskChart) == 68);

struct DiskAtlas {
    uint32_t width;   // texels, > 0
    uint32_t height;  // texels, > 0
};
static_assert(sizeof(DiskAtlas) == 8);

struct DiskBspPlane {
    double normal[3];  // unit
    double distance;   // metres: dot(normal, p) == distance on the plane
};
static_assert(sizeof(DiskBspPlane) == 32);

struct DiskBspNode {
    uint32_t plane;      // into bsp_planes
    int32_t front;       // >= 0: node index greater than this node's; < 0: leaf -(front + 1)
    int32_t back;        // as front
    float boundsMin[3];  // metres, of every triangle below
    float boundsMax[3];
};
static_assert(sizeof(DiskBspNode) == 36);

struct DiskBspLeaf {
    uint32_t firstTriangle;  // index triples: indices[3 * firstTriangle ...]
    uint32_t triangleCount;
    uint32_t firstSurface;  // into surfaces
    uint32_t surfaceCount;
    float boundsMin[3];  // metres
    float boundsMax[3];
};
static_assert(sizeof(DiskBspLeaf) == 40);

struct DiskDynamicMesh {
    StringRef name;        // "node/mesh"
    uint32_t material;     // into materials
    uint32_t firstVertex;  // into dynamic_vertices
    uint32_t vertexCount;
    uint32_t firstIndex;  // into dynamic_indices, multiple of 3
    uint32_t indexCount;  // multiple of 3; each index < vertexCount
};
static_assert(sizeof(DiskDynamicMesh) == 28);

struct DiskEntity {
    StringRef name;  // node name
    uint32_t flags;  // bit 0 dynamic, 1 mover, 2 spawn, 3 probe, 4 item, 5 suspended; no other
    uint32_t firstDynamicMesh;  // into dynamic_meshes
    uint32_t dynamicMeshCount;
    float position[3];  // metres, world
    float rotation[4];  // unit quaternion x, y, z, w
    float scale[3];
    float probeBoxMin[3];  // metres, world; empty box = no box projection
    float probeBoxMax[3];
    float itemRespawn;  // items: seconds taken before it comes back; < 0 never
};
static_assert(sizeof(DiskEntity) == 88);

// A mover (world/movers.hpp, where each field's meaning per kind is). Metres, seconds, radians.
struct DiskMover {
    uint32_t entity;      // into entities, one with the mover flag (bit 1), one mover each
    uint32_t kind;        // world::MoverKind: 0 shuttle, 1 door, 2 plat, 3 button, 4 bobbing,
                          // 5 rotating, 6 pendulum, 7 train
    uint32_t flags;       // world::MoverFlags: bit 0 crusher; no other
    float pos1[3];        // finite
    float pos2[3];        // finite
    float amplitude[3];   // finite
    float axis[3];        // unit (length within 1e-3 of 1)
    float speed;          // finite
    float period;         // seconds: > 0 for shuttle, bobbing, pendulum
    float phase;          // finite
    float travelSeconds;  // > 0 for door, plat, button
    float wait;           // finite
    uint32_t teamMaster;  // into movers, a mover that is its own master (kNoIndex), or kNoIndex
    uint32_t name;        // an id of the level's, or kNoIndex
    uint32_t target;      // an id of the level's, or kNoIndex
    uint32_t firstPoint;  // into mover_points; a train's >= 2, others none
    uint32_t pointCount;
    uint32_t reserved;  // 0
};
static_assert(sizeof(DiskMover) == 104);

struct DiskMoverPoint {
    float position[3];  // metres, world, finite
    float wait;         // seconds, finite, >= 0
    float legSeconds;   // seconds to the next point, finite, > 0
};
static_assert(sizeof(DiskMoverPoint) == 20);

struct DiskFeatures {
    uint32_t flags;              // world::FeatureFlags
    uint32_t materialClasses;    // bit (1 << class)
    uint32_t primaryLightTypes;  // bit (1 << type)
    uint32_t bakedLightTypes;    // bit (1 << type)
    uint32_t primaryCount;
    uint32_t bakedLightCount;
    uint32_t effectOmniCount;
    uint32_t effectSpotCount;
    uint32_t probeCount;  // authored probes
    float gridMin[3];     // metres, light grid extent
    float gridMax[3];
};
static_assert(sizeof(DiskFeatures) == 60);

// ---------------------------------------------------------------------------------------------
// Baked lighting (ids 32..34), written by `onelight-bake`.
//
// kSectionLightmapTexels: DiskLightmapTexel[], every atlas in order, each row-major
//   (texel (x, y) of atlas a at sum_{b<a} width_b height_b + y width_a + x); count == the sum
//   of the atlases' areas. Secondary diffuse irradiance (docs/lighting.md): direct
//   light of every light but the surface's own primary, plus every bounce of every light. A
//   per-pixel normal n' reconstructs it as
//       E(n') = irradiance * max(0, 0.5 + dot(n', direction)) / normalWeight
//   which returns `irradiance` exactly at the surface normal (a rebalanced half-Lambert
//   directional lightmap). Two parts of it are kept apart for the specular (docs/lighting.md
//   "Normalisation"): the baked punctual lights' shadowed direct light as one light of
//   irradiance directIrradiance from directLight (directIrradiance max(0, n'.directLight) at a
//   normal n'), and the rest at the surface normal, the pixel's side of the probes' statistic.
// kSectionImportedLightmap (optional, only with 32..34): DiskImportedTexel[], the same texel
//   order and count as kSectionLightmapTexels: the light the source format baked itself (a Quake
//   3 map's q3map2 lightmaps, bake/lightmap/imported_lightmap.hpp), all of it (no primary is
//   left out), non-directional: read back as a LightmapTexel with direction 0, normalWeight 0.5
//   and the engine texel's flags. `onelight --view q3map2` shows it in place of the engine's.
// kSectionShadowMasks: uint8_t[], same texel order and count: the baked visibility of the
//   surface's own primary, 0 (umbra) .. 255 (fully lit), softened by the light's size.
// kSectionLightGrid: uint8_t[]: one DiskLightGridHeader, then DiskLightGridCell[cellCount]
//   in x-fastest order (cell (i, j, k) at i + dims[0] (j + dims[1] k)).

enum LightmapTexelFlags : uint32_t {
    kLightmapTexelSampled = 1u << 0,  // baked at a point of its own surface
    kLightmapTexelDilated = 1u << 1,  // padding, copied from sampled neighbours
};
inline constexpr uint32_t kAllLightmapTexelFlags = kLightmapTexelSampled | kLightmapTexelDilated;

struct DiskLightmapTexel {
    float irradiance[3];  // lux, RGB, at the surface normal; finite, >= 0
    float direction[3];   // world; half the irradiance-weighted mean incident direction, |d| <= 0.5
    float normalWeight;   // 0.5 + dot(surface normal, direction), in [0.5, 1]; 1 for empty texels
    uint32_t flags;       // LightmapTexelFlags; 0 = outside every chart (all zero)
    float directIrradiance[3];    // lux, RGB, facing directLight; finite, >= 0
    float directLight[3];         // world, unit (to 1e-3) towards the light; all 0 iff no direct
    float indirectIrradiance[3];  // lux, RGB: the rest at the surface normal; finite, >= 0
    // The direct light's shadow edge (world::LightmapTexel): its visibility in [0, 1]; the signed
    // distance to its half-way line, texels in [-kDirectEdgeReach, kDirectEdgeReach]; the
    // penumbra's width, texels in [0, kDirectEdgeMaxWidth]; its two levels; the edge's share in
    // [0, 1].
    float directVisibility;
    float directEdgeDistance;
    float directEdgeWidth;
    float directEdgeLow;   // [0, directEdgeHigh]: the edge's dark side's visibility
    float directEdgeHigh;  // [directEdgeLow, 1]: its lit side's
    float directEdgeSharpness;
};
static_assert(sizeof(DiskLightmapTexel) == 92);

struct DiskImportedTexel {
    float irradiance[3];  // lux, RGB; finite, >= 0
};
static_assert(sizeof(DiskImportedTexel) == 12);

enum LightGridCellFlags : uint32_t {
    kLightGridCellInsideSolid = 1u << 0,  // centre inside geometry: skip when interpolating
};
inline constexpr uint32_t kAllLightGridCellFlags = kLightGridCellInsideSolid;

struct DiskLightGridHeader {
    float origin[3];      // metres, world: the grid's minimum corner
    float cellSize[3];    // metres, > 0; cell (i, j, k) is centred at origin + (i + 0.5) size
    uint32_t dims[3];     // cells per axis, >= 1 each
    uint32_t cellCount;   // dims[0] dims[1] dims[2]
    uint32_t shardIndex;  // < shardCount: which part of a sharded bake this package holds
    uint32_t shardCount;  // 1 for a complete bake; > 1: an unmerged part (see `merge`)
    uint32_t samples;     // sample directions per cell
    uint32_t reserved;    // 0
};
static_assert(sizeof(DiskLightGridHeader) == 56);

struct DiskLightGridCell {
    float ambientCube[6][3];   // lux, RGB irradiance on surfaces facing +x -x +y -y +z -z; >= 0
                               // (secondary: everything but dominant_primary's direct light)
    uint32_t dominantPrimary;  // into lights (role primary) or kNoIndex when none reaches
    float primaryVisibility;   // [0, 1]: fraction of dominant_primary seen from the centre
    uint32_t flags;            // LightGridCellFlags
};
static_assert(sizeof(DiskLightGridCell) == 84);

// ---------------------------------------------------------------------------------------------
// Environment probes (id 35), written by `onelight-bake` (bake/probes/probe_capture.hpp).
//
// kSectionProbes: uint8_t[]: one DiskProbeHeader, then DiskProbe[probeCount], then
//   uint32_t[texelCount] texels in RGB9E5 (encodeRgb9e5 in package/probe_section.hpp; red in
//   bits 0..8, green 9..17, blue 18..26, exponent 27..31, as Vulkan's
//   VK_FORMAT_E5B9G9R9_UFLOAT_PACK32). Probe p owns texels [firstTexel, firstTexel +
//   texelCount), the probes' ranges contiguous and in order: its mips from the largest, each
//   6 faces (+X -X +Y -Y +Z -Z, shaders/probe.glsl) of face_size >> mip squared texels, rows
//   from the top. Texels hold the GGX-prefiltered radiance (mip m for the gloss
//   probeGlossOfMip(m)) divided per channel by irradianceAverage (probeNormalize); the shader
//   scales what it reads by the pixel's irradiance over the capture's (irradianceCube), both of
//   the light the probes hold, at the pixel's normal (probeDenormalize; shaders/probe.glsl). Bytes
//   per probe: sizeof(DiskProbe) + 4 * 6 * sum_m (face_size >> m)^2, about 72 + 32 face_size^2.

enum ProbeTexelFormat : uint32_t {
    kProbeTexelRgb9e5 = 1,  // uint32_t per texel, shared exponent
};

struct DiskProbeHeader {
    uint32_t probeCount;   // DiskProbe records that follow
    uint32_t texelCount;   // texels after the records; == the sum of the probes' counts
    uint32_t texelFormat;  // ProbeTexelFormat
    uint32_t reserved;     // 0
};
static_assert(sizeof(DiskProbeHeader) == 16);

struct DiskProbe {
    float position[3];           // metres, world: the capture point
    float boxMin[3];             // metres, world: box projection when min < max on every
    float boxMax[3];             //   axis; all zero = no box projection
    float irradianceAverage[3];  // lux, RGB: E_avg, finite, > 0 (floored by the baker)
    uint32_t faceSize;           // texels per face edge of mip 0, a power of two <= 4096
    uint32_t mipCount;           // log2(face_size) + 1: down to 1x1
    uint32_t firstTexel;         // into the section's texels
    uint32_t texelCount;         // 6 * sum_m (face_size >> m)^2
    uint32_t entity;             // the probe entity it came from, kNoIndex when placed
    uint32_t reserved;           // 0
    float irradianceCube[6][3];  // lux, RGB on surfaces facing +x -x +y -y +z -z at the capture
                                 // point, of the light the probe holds (the grid's without the
                                 // punctual lights' direct light); finite, >= 0; its mean is
                                 // irradianceAverage
};
static_assert(sizeof(DiskProbe) == 144);

// ---------------------------------------------------------------------------------------------
// Visibility (id 37, optional, only with 32..34), written by `onelight-bake`
// (bake/visibility/visibility_bake.hpp; world/visibility.hpp in memory).
//
// uint8_t[]: one DiskVisibilityHeader, then
//   uint32_t surfaceCluster[surfaceCount]
//                                     cluster of each static surface, < clusterCount
//   uint32_t cellRow[cellCount]       per view cell, x fastest: a row < rowCount, or kNoIndex
//                                     (everything may be visible from the cell)
//   uint32_t rows[rowCount][(clusterCount + 31) / 32]
//                                     bit c % 32 of word c / 32: cluster c may be visible; bits
//                                     past clusterCount are 0
// Cell (i, j, k) is the cube origin + [i, i + 1) x [j, j + 1) x [k, k + 1) times cellSize.
// A point outside every cell culls nothing.

struct DiskVisibilityHeader {
    float origin[3];        // metres, world: the grid's minimum corner; finite
    float cellSize;         // metres, finite, > 0
    uint32_t dims[3];       // cells per axis, 1..world::kMaxVisibilityCellsPerAxis each
    uint32_t cellCount;     // dims[0] dims[1] dims[2] <= world::kMaxVisibilityCells
    uint32_t surfaceCount;  // == the level's static surfaces, >= 1
    uint32_t clusterCount;  // 1..surfaceCount
    uint32_t rowCount;      // <= cellCount
    uint32_t reserved;      // 0
};
static_assert(sizeof(DiskVisibilityHeader) == 48);

// ---------------------------------------------------------------------------------------------
// Processed textures (id 38, optional), written by the texture stage (bake/textures/
// texture_stage; world/processed_textures.hpp in memory, package/texture_section.hpp reads it).
//
// uint8_t[]: one DiskProcessedTexturesHeader, then
//   DiskProcessedTexture[textureCount]
//   DiskMaterialTextureSlots[materialCount]   one per level material, in order
//   char names[nameBytes]                     the textures' names in order, no terminators
//   zero padding to a multiple of kProcessedTexelAlignment (counted from the section's start)
//   texels[texelBytes]                        the textures' mip chains in texture order, each
//                                             followed by zero padding to a multiple of
//                                             kProcessedTexelAlignment
// A chain holds every mip of its texture, the largest first, each mip's rows top to bottom,
// tightly packed (world::mipChainBytes). Nothing follows the last chain's padding: the section
// is exactly its records, names and texels.

inline constexpr uint32_t kProcessedTexelAlignment = 8;         // bytes; where each chain starts
inline constexpr uint32_t kMaxProcessedTextureNameBytes = 256;  // per texture name

struct DiskProcessedTexturesHeader {
    uint32_t textureCount;   // DiskProcessedTexture records after the header
    uint32_t materialCount;  // DiskMaterialTextureSlots records after them; == level materials
    uint32_t nameBytes;      // bytes of names after the slots; == the sum of the name lengths
    uint8_t method;          // world::GlossMipMethod the normal and gloss mips were made by:
                             // 0 blit, 1 Black Ops, 2 WWII
    uint8_t reserved[3];     // 0
    uint64_t texelBytes;     // bytes from the first chain to the section's end, padding
                             // included; <= world::kMaxDecodedImageBytes
};
static_assert(sizeof(DiskProcessedTexturesHeader) == 24);

struct DiskProcessedTexture {
    uint32_t nameOffset;  // bytes into the section's names, == the previous names' lengths
    uint32_t nameLength;  // bytes, <= kMaxProcessedTextureNameBytes; what it was made from
    uint8_t format;       // world::TexelFormat: 0 RGBA8 sRGB, 1 RGBA8 UNORM, 2 R8 UNORM,
                          // 3 R16 float (every texel finite and >= 0)
    uint8_t reserved[3];  // 0
    uint32_t width;       // texels of mip 0, 1..world::kMaxImageExtent (16384)
    uint32_t height;      // texels of mip 0, 1..world::kMaxImageExtent
    uint32_t mipCount;    // world::fullMipCount(width, height): down to 1x1
    uint16_t magFilter;   // glTF/GL enum: 0 unset, 9728, 9729, 9984..9987
    uint16_t minFilter;   // as magFilter
    uint16_t wrapS;       // 10497 repeat, 33071 clamp, 33648 mirrored
    uint16_t wrapT;       // as wrapS
    uint64_t firstByte;   // from the section's start: after the names' padding and the previous
                          // chain's, a multiple of kProcessedTexelAlignment
    uint64_t byteCount;   // world::mipChainBytes(format, width, height, mipCount)
};
static_assert(sizeof(DiskProcessedTexture) == 48);

struct DiskMaterialTextureSlots {
    uint32_t baseColor;            // into the section's textures (RGBA8 sRGB) or kNoIndex
    uint32_t metallicRoughness;    // RGBA8 UNORM (G roughness, B metallic) or kNoIndex
    uint32_t normal;               // RGBA8 UNORM (tangent space) or kNoIndex
    uint32_t occlusion;            // RGBA8 UNORM (R) or kNoIndex
    uint32_t emissive;             // RGBA8 sRGB or kNoIndex
    uint32_t cavity;               // R8 UNORM (made from the normal map) or kNoIndex
    uint32_t facets;               // R16 float, the normal map's facet table
                                   // (bake/textures/facet_table.hpp), or kNoIndex
    uint8_t factorsFolded;         // 0 or 1: the material's metallic and roughness factors and
                                   // normal scale are already in its textures
    uint8_t baseRoughnessInAlpha;  // 0 or 1: A of its metallic-roughness texture is the
                                   // roughness of the texels' own lobes under each mip texel
                                   // (G also holds the spread of the normals there)
    uint8_t slopeKurtosisInNormalAlpha;  // 0 or 1: A of its normal texture is the kurtosis k of
                                         // the slopes under each mip texel, as (k - 1) / 2
    uint8_t reserved[1];                 // 0
};
static_assert(sizeof(DiskMaterialTextureSlots) == 32);

// ---------------------------------------------------------------------------------------------
// Error budget (id 39, optional, only with 32..34), written by `onelight-bake --error-budget E`
// (bake/budget/; world::ErrorBudgetChoices in memory). One record. Errors are mean relative
// errors of 8x8-pixel blocks (docs/level-report.md), finite and >= 0.

struct DiskErrorBudget {
    float budget;            // E, in (0, 1]
    uint32_t flags;          // world::ErrorBudgetFlags; no other bits
    float probeError;        // predicted cost of dropping the probes
    uint32_t probesPlaced;   // probes the level would have had
    float densityTolerance;  // chart density's curvature tolerance, in (0, 8]
    float lightmapError;     // predicted cost of the coarser charts
    uint32_t texelsRequested;
    uint32_t texelsSampled;   // <= texelsRequested
    uint32_t gridCellsFull;   // >= gridCells
    uint32_t gridCells;       // == the light grid section's cells
    uint32_t viewsPredicted;  // views the predictions come from
    float predictedError;     // probeError (when dropped) + lightmapError
};
static_assert(sizeof(DiskErrorBudget) == 48);

// ---------------------------------------------------------------------------------------------
// Shard range (id 40), in an unmerged part of a sharded bake only (light_grid's shardCount > 1;
// never in a whole package; world::ShardRange in memory). One record: the lightmap charts (the
// texels of their rectangles; positions in the level's space order of charts,
// bake::chartSpaceOrder), light grid cells and probes the part baked, each [begin, end), cut by
// estimated cost (bake/shard_plan.hpp). chartEnd <= the level's charts, cellEnd <= the
// grid's cells, probeEnd <= probeTotal, and the part's probe section holds exactly
// probeEnd - probeBegin probes. The merge checks that its parts tile [0, total) of each.

struct DiskShardRange {
    uint64_t chartBegin, chartEnd;
    uint64_t cellBegin, cellEnd;
    uint64_t probeBegin, probeEnd;
    uint64_t probeTotal;
    uint64_t reserved;  // 0
};
static_assert(sizeof(DiskShardRange) == 64);

// ---------------------------------------------------------------------------------------------
// Collision (ids 41 and 42, optional, written by `compile` from a Quake 3 map's brushes and
// trigger entities; world/collision.hpp in memory, package/collision_section.hpp reads them).
// Metres, Y up, as the rest of the level.
//
// kSectionCollision: uint8_t[]: one DiskCollisionHeader, then
//   DiskCollisionPlane planes[planeCount]
//   uint32_t sidePlanes[sideCount]        each < planeCount
//   DiskCollisionBrush brushes[brushCount] their [firstSide, firstSide + sideCount) inside
//                                          sidePlanes
// and nothing else: the section is exactly that size.
// kSectionTriggers: DiskTrigger[]; elementSize == sizeof(DiskTrigger).

inline constexpr uint32_t kMaxCollisionPlanes = 1u << 22;  // each count, a bound on hostile input
inline constexpr uint32_t kMaxCollisionSides = 1u << 24;
inline constexpr uint32_t kMaxCollisionBrushes = 1u << 22;
inline constexpr uint32_t kMaxTriggers = 1u << 16;

struct DiskCollisionHeader {
    uint32_t planeCount;  // <= kMaxCollisionPlanes
    uint32_t sideCount;   // <= kMaxCollisionSides
    uint32_t brushCount;  // <= kMaxCollisionBrushes
    uint32_t reserved;    // 0
};
static_assert(sizeof(DiskCollisionHeader) == 16);

struct DiskCollisionPlane {
    float normal[3];  // unit (length within 1e-3 of 1), finite
    float distance;   // metres, finite: dot(normal, p) == distance on the plane
};
static_assert(sizeof(DiskCollisionPlane) == 16);

struct DiskCollisionBrush {
    uint32_t firstSide;  // into the side planes
    uint32_t sideCount;  // >= 1; firstSide + sideCount <= sideCount of the header
    uint32_t contents;   // world::kContentsSolid | world::kContentsPlayerClip, no other bit, != 0
    uint32_t mover;      // into movers: its planes in the mover's object space; kNoIndex: fixed
};
static_assert(sizeof(DiskCollisionBrush) == 16);

struct DiskTrigger {
    uint32_t kind;       // world::TriggerKind: 1 push, 2 teleport, 3 hurt, 4 use a mover,
                         // 5 raise a plat
    float boundsMin[3];  // metres, world, finite
    float boundsMax[3];  // metres, world, finite, >= boundsMin
    float target[3];     // metres, world, finite: push, the apex; teleport, the feet; hurt, 0
    float targetYaw;     // teleport: radians about +y (0 looks down -z), finite; else 0
    uint32_t mover;      // kinds 4 and 5: into movers; others kNoIndex
};
static_assert(sizeof(DiskTrigger) == 48);

}  // namespace onelight::package
