// Reads a glTF 2.0 level (.gltf or .glb) through tinygltf into a SourceLevel: the active
// scene's node hierarchy flattened to world transforms, its mesh primitives, the materials,
// textures, samplers and images they use, KHR_lights_punctual lights with their roles, cameras,
// and the `extras.onelight` markers. Anything the scene does not use is left out.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "world/source_level.hpp"

namespace onelight::world {

/// Throws Error with a one-line message naming the file and the place on bad input.
[[nodiscard]] SourceLevel importGltf(const std::string& path);

/// The same on the bytes of a .gltf or .glb already read; `path` names it in messages, and its
/// folder is where external buffers and images are looked for.
[[nodiscard]] SourceLevel importGltfBytes(std::vector<uint8_t> bytes, const std::string& path);

}  // namespace onelight::world
