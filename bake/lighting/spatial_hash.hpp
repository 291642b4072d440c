// The hash of a 3D grid cell that the bake's point lookups share (the radiance cache, the
// lightmap denoiser): cells of a given size, hashed into a power-of-two bucket count.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace onelight::bake {

[[nodiscard]] inline glm::ivec3 cellOfPoint(const glm::vec3& p, float size) {
    return glm::ivec3(glm::floor(p / size));
}

/// Teschner et al. 2003's spatial hash, masked to the bucket count.
[[nodiscard]] inline uint32_t bucketOf(const glm::ivec3& c, uint32_t mask) {
    uint32_t h = static_cast<uint32_t>(c.x) * 73856093u;
    h ^= static_cast<uint32_t>(c.y) * 19349663u;
    h ^= static_cast<uint32_t>(c.z) * 83492791u;
    return h & mask;
}

}  // namespace onelight::bake
