// The Quake 3 model file (MD3, IDP3 version 15), declared once: the header, frames, tags,
// surfaces and their records, as stored. Little-endian, packed (every record a multiple of 4
// bytes, no padding). Reference: the id Tech 3 source release, code/qcommon/qfiles.h (GPL-2+).
#pragma once

#include <cstdint>

namespace onelight::world::q3 {

inline constexpr char kMd3Magic[4] = {'I', 'D', 'P', '3'};
inline constexpr int32_t kMd3Version = 15;

// The games' limits: Quake 3's own (qfiles.h MD3_MAX_*), but per surface Nexuiz's engine
// (DarkPlaces) loads 16-bit vertex counts, and Nexuiz's models use them (its tuba item has 4832
// vertices in one surface).
inline constexpr int32_t kMd3MaxFrames = 1024;       // per model
inline constexpr int32_t kMd3MaxTags = 16;           // per frame
inline constexpr int32_t kMd3MaxSurfaces = 32;       // per model
inline constexpr int32_t kMd3MaxShaders = 256;       // per surface
inline constexpr int32_t kMd3MaxVertices = 65536;    // per surface
inline constexpr int32_t kMd3MaxTriangles = 131072;  // per surface

inline constexpr float kMd3PositionScale = 1.0f / 64.0f;  // a stored position unit, game units

struct Md3Header {
    char magic[4];
    int32_t version;
    char name[64];
    int32_t flags;
    int32_t frameCount, tagCount, surfaceCount, skinCount;
    int32_t framesOffset;    // frameCount records
    int32_t tagsOffset;      // frameCount x tagCount records, frame-major
    int32_t surfacesOffset;  // the first surface; each surface's endOffset leads to the next
    int32_t endOffset;       // the file's length
};
static_assert(sizeof(Md3Header) == 108);

struct Md3Frame {
    float boundsMin[3], boundsMax[3];
    float localOrigin[3];
    float radius;
    char name[16];
};
static_assert(sizeof(Md3Frame) == 56);

struct Md3Tag {
    char name[64];
    float origin[3];
    float axis[3][3];  // rows: the tag's x, y, z axes in the model's space
};
static_assert(sizeof(Md3Tag) == 112);

// Offsets in a surface are from the surface's own start.
struct Md3SurfaceHeader {
    char magic[4];  // "IDP3"
    char name[64];
    int32_t flags;
    int32_t frameCount;  // the model's
    int32_t shaderCount, vertexCount, triangleCount;
    int32_t trianglesOffset, shadersOffset, texCoordsOffset, verticesOffset;
    int32_t endOffset;  // the next surface, from this one's start
};
static_assert(sizeof(Md3SurfaceHeader) == 108);

struct Md3Shader {
    char name[64];
    int32_t index;  // the game's, at run time
};
static_assert(sizeof(Md3Shader) == 68);

struct Md3Triangle {
    int32_t indices[3];  // into the surface's vertices
};

struct Md3TexCoord {
    float st[2];
};

// A vertex of one frame: the position in 1/64 game units, the normal as two angles of 2 pi / 256
// each (high byte latitude, low byte longitude).
struct Md3Vertex {
    int16_t position[3];
    int16_t normal;
};
static_assert(sizeof(Md3Vertex) == 8);

}  // namespace onelight::world::q3
