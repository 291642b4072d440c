// One glTF mesh primitive into engine vertices and triangle indices: POSITION, NORMAL (flat
// normals when missing, as glTF requires), TANGENT (generated when missing), TEXCOORD_0 and
// TEXCOORD_1. Strips and fans become lists; points and lines are not surfaces.
#pragma once

#include <string>

#include "world/source_level.hpp"

namespace tinygltf {
class Model;
}

namespace onelight::world {

struct ImportedPrimitive {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;  // triangle list
    bool hasUv1 = false;
    bool isTriangles = true;  // false for points and lines: the caller skips them
};

/// Reads primitive `primitiveIndex` of mesh `meshIndex`. Throws Error naming the mesh
/// on malformed data, NaN or Inf.
[[nodiscard]] ImportedPrimitive importPrimitive(const tinygltf::Model& model, int meshIndex,
                                                int primitiveIndex, const std::string& file);

}  // namespace onelight::world
