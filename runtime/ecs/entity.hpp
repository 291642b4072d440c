// Entity handles: an index into the registry's slots plus a generation that changes each time
// the slot is reused, so a stale handle never reaches the components of a newer entity.
#pragma once

#include <cstdint>

namespace onelight::ecs {

enum class Entity : uint32_t {};

inline constexpr uint32_t kIndexBits = 22;  // up to 4,194,303 live entities
inline constexpr uint32_t kIndexMask = (1u << kIndexBits) - 1u;
inline constexpr uint32_t kGenerationMask = (1u << (32 - kIndexBits)) - 1u;  // wraps at 1024
inline constexpr Entity kNullEntity = Entity{0xFFFFFFFFu};

[[nodiscard]] constexpr uint32_t indexOf(Entity e) {
    return uint32_t(e) & kIndexMask;
}
[[nodiscard]] constexpr uint32_t generationOf(Entity e) {
    return uint32_t(e) >> kIndexBits;
}
[[nodiscard]] constexpr Entity makeEntity(uint32_t index, uint32_t generation) {
    return Entity{(generation & kGenerationMask) << kIndexBits | (index & kIndexMask)};
}

}  // namespace onelight::ecs
