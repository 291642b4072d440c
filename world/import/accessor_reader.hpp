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

/// Reads accessor `accessor_index` as `components` floats per element (FLOAT, or a normalized
/// integer type). `where` names the place for errors, e.g. "file.gltf: mesh 'crate' POSITION".
std::vector<float> read_float_accessor(const tinygltf::Model& model, int accessor_index,
                                       int components, const std::string& where);

/// Reads an index accessor (UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, SCALAR).
std::vector<uint32_t> read_index_accessor(const tinygltf::Model& model, int accessor_index,
                                          const std::string& where);

/// Number of elements of accessor `accessor_index`, after checking the index.
size_t accessor_count(const tinygltf::Model& model, int accessor_index, const std::string& where);

}  // namespace onelight::world
