// Reads glTF accessors into plain arrays, checking every index, offset, stride and size first,
// so a malformed file gives a Error naming the place instead of reading out of bounds.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace onelight::world {

/// Reads accessor `accessorIndex` as `components` floats per element (FLOAT, or a normalized
/// integer type). `where` names the place for errors, e.g. "file.gltf: mesh 'crate' POSITION".
[[nodiscard]] std::vector<float> readFloatAccessor(const tinygltf::Model& model, int accessorIndex,
                                                   int components, const std::string& where);

/// Reads an index accessor (UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, SCALAR).
[[nodiscard]] std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model,
                                                      int accessorIndex, const std::string& where);

/// Number of elements of accessor `accessorIndex`, after checking the index.
[[nodiscard]] size_t accessorCount(const tinygltf::Model& model, int accessorIndex,
                                   const std::string& where);

}  // namespace onelight::world
