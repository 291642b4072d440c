// A Quake 3 model (MD3) read from its bytes and checked before anything is allocated: the magic
// and version, every count within the game's limits, every block (frames, tags, each surface and
// its shaders, triangles, texture coordinates and vertices) inside the file and its surface,
// every triangle's indices inside its surface, every surface with the model's frame count, and
// every float finite. Positions are decoded to game units and normals to unit vectors.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace onelight::world::q3 {

struct Md3FrameInfo {
    std::string name;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // game units, the model's space
    glm::vec3 localOrigin{0.0f};
    float radius = 0.0f;
};

struct Md3TagPose {
    std::string name;
    glm::vec3 origin{0.0f};
    glm::mat3 axes{1.0f};  // columns: the tag's x, y, z axes
};

struct Md3Surface {
    std::string name;
    std::vector<std::string> shaders;  // the skins' shader or image names, first the default
    std::vector<uint32_t> indices;     // three a triangle, each < vertexCount
    std::vector<glm::vec2> texCoords;  // per vertex, every frame's
    uint32_t vertexCount = 0;
    std::vector<glm::vec3> positions;  // frame-major: frame f's vertex v at f * vertexCount + v
    std::vector<glm::vec3> normals;    // the same layout, unit
};

struct Md3Model {
    std::string name;
    std::vector<Md3FrameInfo> frames;  // at least one
    uint32_t tagCount = 0;
    std::vector<Md3TagPose> tags;  // frame-major: frame f's tag t at f * tagCount + t
    std::vector<Md3Surface> surfaces;
};

/// Throws world::Error naming `where` (the file), the block or surface, and what was expected.
[[nodiscard]] Md3Model parseMd3(std::span<const uint8_t> bytes, const std::string& where);

/// Frame `frame`'s index into a model's frames; throws world::Error naming `where` when the
/// model has no such frame (an entity asking for an animation frame past the model's).
[[nodiscard]] uint32_t checkedMd3Frame(const Md3Model& model, int64_t frame,
                                       const std::string& where);

/// The unit normal an MD3 vertex stores as two angles (qfiles.h's encoding): latitude a (high
/// byte) and longitude b (low byte), each 2 pi / 256 a step: (cos a sin b, sin a sin b, cos b).
[[nodiscard]] glm::vec3 md3Normal(int16_t encoded);

}  // namespace onelight::world::q3
