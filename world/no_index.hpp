// "No index": the one marker for an absent index in every index field, in memory and on disk
// (world, package, render and game; the shaders' NO_INDEX is checked equal to it).
#pragma once

#include <cstdint>

namespace onelight::world {

inline constexpr uint32_t kNoIndex = 0xFFFFFFFFu;

}  // namespace onelight::world
