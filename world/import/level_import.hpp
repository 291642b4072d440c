// A level from whatever names it (world/level_names.hpp): a glTF (.gltf, .glb) or a Quake 3
// map (q3/q3_import.hpp: NAME.bsp, PAK.pk3:maps/NAME.bsp, or NAME).
#pragma once

#include <string>

#include "world/import/q3/q3_import.hpp"
#include "world/level_names.hpp"
#include "world/source_level.hpp"

namespace onelight::world {

/// Throws Error with a one-line message naming the file and the place on bad input.
[[nodiscard]] SourceLevel importLevel(const std::string& spec, const Quake3Options& quake3 = {});

}  // namespace onelight::world
