// The Quake 3 BSP file (IBSP version 46, as q3map2 writes it for Quake 3 and OpenArena),
// declared once: the header's lump directory and the records of the lumps the importer reads.
// Little-endian, packed as stored (every record is a multiple of 4 bytes, no padding).
// Reference: the id Tech 3 source release, code/qcommon/qfiles.h (GPL-2+).
#pragma once

#include <cstdint>

namespace onelight::world::q3 {

inline constexpr char kBspMagic[4] = {'I', 'B', 'S', 'P'};
inline constexpr int32_t kBspVersion = 46;

/// Lump numbers (qfiles.h LUMP_*).
enum Lump : int {
    kLumpEntities = 0,
    kLumpShaders = 1,
    kLumpPlanes = 2,
    kLumpNodes = 3,
    kLumpLeafs = 4,
    kLumpLeafSurfaces = 5,
    kLumpLeafBrushes = 6,
    kLumpModels = 7,
    kLumpBrushes = 8,
    kLumpBrushSides = 9,
    kLumpDrawVerts = 10,
    kLumpDrawIndexes = 11,
    kLumpFogs = 12,
    kLumpSurfaces = 13,
    kLumpLightmaps = 14,
    kLumpLightGrid = 15,
    kLumpVisibility = 16,
    kLumpCount = 17
};

struct BspLump {
    int32_t offset;  // bytes from the file's start
    int32_t length;  // bytes
};

struct BspHeader {
    char magic[4];  // kBspMagic
    int32_t version;
    BspLump lumps[kLumpCount];
};
static_assert(sizeof(BspHeader) == 144);

/// A shader reference (qfiles.h dshader_t): its name and the compiler's flags.
struct BspShader {
    char name[64];         // e.g. "textures/base_wall/concrete", NUL-padded
    int32_t surfaceFlags;  // SURF_*
    int32_t contentFlags;  // CONTENTS_*
};
static_assert(sizeof(BspShader) == 72);

/// Surface flags the importer reads (surfaceflags.h).
inline constexpr int32_t kSurfNoDraw = 0x80;          // SURF_NODRAW: never drawn (clip, triggers)
inline constexpr int32_t kSurfSky = 0x4;              // SURF_SKY: the sky, drawn as the background
inline constexpr int32_t kSurfHint = 0x100;           // SURF_HINT
inline constexpr int32_t kSurfSkip = 0x200;           // SURF_SKIP
inline constexpr int32_t kSurfLightFilter = 0x8000;   // SURF_LIGHTFILTER: q3map2 filters light
inline constexpr int32_t kSurfAlphaShadow = 0x10000;  // SURF_ALPHASHADOW: q3map2 shadows by alpha
/// Content flags the importer reads.
inline constexpr int32_t kContentsSolid = 0x1;               // CONTENTS_SOLID
inline constexpr int32_t kContentsLava = 0x8;                // CONTENTS_LAVA
inline constexpr int32_t kContentsSlime = 0x10;              // CONTENTS_SLIME
inline constexpr int32_t kContentsWater = 0x20;              // CONTENTS_WATER
inline constexpr int32_t kContentsFog = 0x40;                // CONTENTS_FOG: a fog volume's faces
inline constexpr int32_t kContentsPlayerClip = 0x10000;      // CONTENTS_PLAYERCLIP: clip brushes
inline constexpr int32_t kContentsTranslucent = 0x20000000;  // CONTENTS_TRANSLUCENT
inline constexpr int32_t kContentsTrigger = 0x40000000;      // CONTENTS_TRIGGER

/// A plane (qfiles.h dplane_t), in map units, Z up: dot(normal, p) == dist on it.
struct BspBrushPlane {
    float normal[3];
    float dist;
};
static_assert(sizeof(BspBrushPlane) == 16);

/// A node of the world's BSP tree (qfiles.h dnode_t): a point in front of its plane goes to
/// children[0], else children[1]; a child >= 0 is a node, one < 0 the leaf -(child + 1).
struct BspNode {
    int32_t plane;  // into the plane lump
    int32_t children[2];
    int32_t mins[3], maxs[3];  // map units, for culling
};
static_assert(sizeof(BspNode) == 36);

/// A leaf of the world's BSP tree (qfiles.h dleaf_t): a convex region of one visibility cluster
/// (-1: inside solid, no cluster).
struct BspLeaf {
    int32_t cluster, area;
    int32_t mins[3], maxs[3];  // map units
    int32_t firstLeafSurface, leafSurfaceCount;
    int32_t firstLeafBrush, leafBrushCount;
};
static_assert(sizeof(BspLeaf) == 48);

/// The visibility lump's header: clusterCount rows of bytesPerCluster bytes follow, bit c of
/// row r set when cluster c may be seen from cluster r (q3map2 -vis's potentially visible set).
struct BspVisibilityHeader {
    int32_t clusterCount, bytesPerCluster;
};

/// A brush model (qfiles.h dmodel_t): model 0 is the world, model N is "*N" of an entity.
struct BspModel {
    float mins[3], maxs[3];  // map units, Z up
    int32_t firstSurface, surfaceCount;
    int32_t firstBrush, brushCount;
};
static_assert(sizeof(BspModel) == 40);

/// A convex brush (qfiles.h dbrush_t): the intersection of its sides' back half-spaces.
struct BspBrush {
    int32_t firstSide, sideCount;  // into the brush side lump
    int32_t shader;                // into the shader lump: its contentFlags are the brush's
};
static_assert(sizeof(BspBrush) == 12);

/// A brush side (qfiles.h dbrushside_t).
struct BspBrushSide {
    int32_t plane;   // into the plane lump
    int32_t shader;  // into the shader lump
};
static_assert(sizeof(BspBrushSide) == 8);

/// The lightmap lump: pages of kLightmapPageSize^2 RGB8 texels, row-major (q3map2's light as
/// bytes: clamped to 255 keeping the hue).
inline constexpr uint32_t kLightmapPageSize = 128;
inline constexpr uint32_t kLightmapPageBytes = kLightmapPageSize * kLightmapPageSize * 3;

/// A vertex (qfiles.h drawVert_t), in map units, Z up.
struct BspVertex {
    float position[3];
    float texcoord[2];  // the shader's texture coordinates (texels / size, may exceed 1)
    float lightmap[2];  // q3map2's lightmap coordinates
    float normal[3];
    uint8_t color[4];  // q3map2's vertex light (RGBA)
};
static_assert(sizeof(BspVertex) == 44);

/// Surface types (qfiles.h mapSurfaceType_t).
enum SurfaceType : int32_t {
    kSurfaceBad = 0,
    kSurfacePlanar = 1,     // a polygon, triangulated in the index lump
    kSurfacePatch = 2,      // a biquadratic Bezier patch: patchWidth x patchHeight controls
    kSurfaceTriangles = 3,  // a triangle soup (models), in the index lump
    kSurfaceFlare = 4       // a billboard flare
};

/// A drawn surface (qfiles.h dsurface_t).
struct BspSurface {
    int32_t shader;  // into the shader lump
    int32_t fog;     // into the fog lump, or -1
    int32_t type;    // SurfaceType
    int32_t firstVertex, vertexCount;
    int32_t firstIndex, indexCount;  // indices are relative to firstVertex
    int32_t lightmap;                // q3map2's lightmap page, or < 0
    int32_t lightmapX, lightmapY, lightmapWidth, lightmapHeight;
    float lightmapOrigin[3];
    float lightmapVectors[3][3];  // S, T and the plane normal for planar surfaces
    int32_t patchWidth, patchHeight;
};
static_assert(sizeof(BspSurface) == 104);

}  // namespace onelight::world::q3
