// Reads a glTF 2.0 level (.gltf or .glb) through tinygltf into a SourceLevel: the active
// scene's node hierarchy flattened to world transforms, its mesh primitives, the materials,
// textures, samplers and images they use, KHR_lights_punctual lights with their roles, cameras,
// and the `extras.onelight` markers. Anything the scene does not use is left out.
#pragma once

#include <string>

#include "world/source_level.hpp"

namespace onelight::world {

/// Throws Error with a one-line message naming the file and the place on bad input.
[[nodiscard]] SourceLevel importGltf(const std::string& path);

}  // namespace onelight::world
