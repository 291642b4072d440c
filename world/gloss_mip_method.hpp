// How the texture stage makes normal and gloss mips: the one enumeration, stored in the level
// settings and the processed-texture section and read by bake/textures.
#pragma once

#include <cstdint>

namespace onelight::world {

/// How the texture stage makes normal and gloss mips (bake/textures, docs/materials.md): a plain
/// box filter of each texture, Black Ops' variance to gloss, WWII's average normal length, or
/// the slopes' second moments (CLEAN mapping).
enum class GlossMipMethod : uint8_t { kBlit = 0, kBlackOps = 1, kWwii = 2, kClean = 3 };

}  // namespace onelight::world
