// A Quake 3 map's own potentially visible set (q3map2 -vis): the world's BSP tree, its leaves'
// clusters and the clusters' rows, converted to the level's space (map_axes.hpp). Empty for a map
// compiled without -vis.
#pragma once

#include <string>

#include "world/import/q3/bsp_file.hpp"
#include "world/imported_visibility.hpp"

namespace onelight::world::q3 {

/// Throws world::Error naming `where` and the node for a plane whose normal is not unit.
[[nodiscard]] ImportedVisibility importVisibility(const BspFile& bsp, const std::string& where);

}  // namespace onelight::world::q3
