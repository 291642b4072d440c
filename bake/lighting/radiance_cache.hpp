// Cached bounces: the irradiance at points of the static surfaces (the lightmap texels), found
// by position and normal, so that a path can end at its first diffuse hit and read the light
// that leaves it there instead of being continued (bake/lightmap/bounce_passes.hpp fills it,
// pass after pass; traceRadiance reads it when TransportSettings::cache is set).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace onelight::bake {

struct RadianceCache {
    std::vector<glm::vec3> position;  // metres, on (or just off) the surface
    std::vector<glm::vec3> normal;    // unit, the side that receives
    std::vector<float> reach;         // metres: a hit this close may read the point
    std::vector<glm::vec3> direct;    // lux from the lights, shadowed
    std::vector<glm::vec3> indirect;  // lux from everything else (bounces, sky, emitters)
    // Spatial hash over `position`: cells of `cellSize` (twice the largest reach), hashed into
    // buckets of `slots` (copies of the points' geometry, in increasing point order within a
    // bucket, side by side so that a lookup reads them in sequence).
    struct Slot {
        glm::vec3 position{0.0f};
        float reach = 0.0f;
        glm::vec3 normal{0.0f};
        uint32_t point = 0;
    };
    float cellSize = 1.0f;
    uint32_t bucketMask = 0;
    std::vector<uint32_t> bucketFirst;  // bucketMask + 2 offsets into slots
    std::vector<Slot> slots;
    [[nodiscard]] bool empty() const { return slots.empty(); }
};

/// Builds the spatial hash of `cache` from its positions and reaches (call after filling
/// them; irradiance may change afterwards). Reaches above the 95th percentile are clamped so
/// that one coarse chart does not make every cell large.
void indexRadianceCache(RadianceCache& cache);

inline constexpr uint32_t kNoCachePoint = ~0u;

/// The nearest point within its reach of `position` whose normal agrees with `normal` (within
/// 37 degrees) and whose plane passes within a quarter reach: the texel of the same surface.
/// kNoCachePoint when none (another surface, a back side, a texel-less triangle).
[[nodiscard]] uint32_t findCachePoint(const RadianceCache& cache, const glm::vec3& position,
                                      const glm::vec3& normal);

}  // namespace onelight::bake
