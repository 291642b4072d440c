// What tinygltf would hide: it replaces a value of the wrong type, a negative count or a short
// array by its default, and its recursive parser overflows the stack on deep nesting. This
// reads a .gltf or .glb (a regular file), bounds the JSON's nesting before any parser sees it,
// then checks the types, lengths and ranges of every field the importer reads, so that a wrong
// value is an error naming the file and the place ("nodes[3].matrix: 15 elements; expected 16
// numbers") rather than a silent default.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace onelight::world {

/// The deepest nesting of arrays and objects a glTF's JSON may have.
inline constexpr uint32_t kMaxGltfJsonDepth = 64;

/// The glTF extensions onelight reads; any other in extensionsRequired is an error.
inline constexpr const char* kSupportedGltfExtensions[] = {"KHR_lights_punctual",
                                                           "KHR_materials_emissive_strength"};

struct GltfFile {
    std::vector<uint8_t> bytes;  // the whole file, as read
    bool binary = false;         // a glb (version 2, checked)
};

/// Reads and checks `path`. Throws world::Error naming the file, the place and what was expected.
[[nodiscard]] GltfFile readCheckedGltf(const std::string& path);

/// The checks of readCheckedGltf on a file's bytes already in memory.
[[nodiscard]] GltfFile checkGltfBytes(std::vector<uint8_t> bytes, const std::string& path);

/// The JSON checks alone, on a .gltf's text or a glb's JSON chunk.
void checkGltfJson(const char* text, size_t size, const std::string& path);

}  // namespace onelight::world
