// Cached bounces: the irradiance at points of the static surfaces (the lightmap texels), found
// by position and normal, so that a path can end at its first diffuse hit and read the light
// that leaves it there instead of being continued (bake/lightmap/bounce_passes.hpp fills it,
// pass after pass; traceRadiance reads it when TransportSettings::cache is set).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace onelight::bake {

/// A point the cache holds light at.
struct CachePoint {
    glm::vec3 position{0.0f};  // metres, on (or just off) the surface
    float reach = 0.0f;        // metres: a hit this close may read the point
    glm::vec3 normal{0.0f};    // unit, the side that receives
    uint32_t index = 0;        // into RadianceCache::direct and indirect
};

struct RadianceCache {
    std::vector<glm::vec3> direct;    // lux from the lights, shadowed, per point
    std::vector<glm::vec3> indirect;  // lux from everything else (bounces, sky, emitters)
    std::vector<float> reach;         // metres, per point: its (clamped) reach
    // Spatial hash over the points: cells of `cellSize` (twice the largest reach), hashed into
    // buckets of `slots` (the points in increasing index order within a bucket, side by side so
    // that a lookup reads them in sequence).
    float cellSize = 1.0f;
    uint32_t bucketMask = 0;
    std::vector<uint32_t> bucketFirst;  // bucketMask + 2 offsets into slots
    std::vector<CachePoint> slots;
    [[nodiscard]] bool empty() const { return slots.empty(); }
};

/// A cache of `points` (point i at index i; their `index` is set here), its light zero.
/// Reaches above the 95th percentile are clamped so that one coarse chart does not make every
/// cell large. A point of reach 0 holds light but is never found.
[[nodiscard]] RadianceCache makeRadianceCache(std::vector<CachePoint> points);

inline constexpr uint32_t kNoCachePoint = ~0u;

/// The nearest point within its reach of `position` whose normal agrees with `normal` (within
/// 37 degrees) and whose plane passes within a quarter reach: the texel of the same surface.
/// kNoCachePoint when none (another surface, a back side, a texel-less triangle).
[[nodiscard]] uint32_t findCachePoint(const RadianceCache& cache, const glm::vec3& position,
                                      const glm::vec3& normal);

}  // namespace onelight::bake
