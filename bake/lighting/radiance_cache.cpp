#include "bake/lighting/radiance_cache.hpp"

#include <algorithm>
#include <cmath>

#include "bake/lighting/spatial_hash.hpp"

namespace onelight::bake {
namespace {

constexpr float kNormalAgreement = 0.8f;  // cos 37 degrees
constexpr float kPlaneTolerance = 0.25f;  // of the point's reach

}  // namespace

RadianceCache makeRadianceCache(std::vector<CachePoint> points) {
    RadianceCache cache;
    const size_t n = points.size();
    cache.direct.assign(n, glm::vec3(0.0f));
    cache.indirect.assign(n, glm::vec3(0.0f));
    cache.reach.assign(n, 0.0f);
    if (n == 0) return cache;
    std::vector<float> sorted;
    for (const CachePoint& p : points)
        if (p.reach > 0.0f) sorted.push_back(p.reach);
    if (sorted.empty()) return cache;
    const size_t at = std::min(sorted.size() - 1, sorted.size() * 95 / 100);
    std::nth_element(sorted.begin(), sorted.begin() + long(at), sorted.end());
    const float maxReach = std::max(sorted[at], 1e-6f);
    cache.cellSize = 2.0f * maxReach;
    uint32_t buckets = 1;
    while (buckets < 2 * n && buckets < (1u << 30)) buckets <<= 1;
    cache.bucketMask = buckets - 1;
    cache.bucketFirst.assign(size_t(buckets) + 1, 0);
    std::vector<uint32_t> bucket(n);
    for (size_t i = 0; i < n; ++i) {
        points[i].index = static_cast<uint32_t>(i);
        if (!(points[i].reach > 0.0f)) continue;
        points[i].reach = std::min(points[i].reach, maxReach);
        cache.reach[i] = points[i].reach;
        bucket[i] = bucketOf(cellOfPoint(points[i].position, cache.cellSize), cache.bucketMask);
        ++cache.bucketFirst[bucket[i] + 1];
    }
    for (size_t b = 0; b < buckets; ++b) cache.bucketFirst[b + 1] += cache.bucketFirst[b];
    cache.slots.resize(cache.bucketFirst.back());
    std::vector<uint32_t> fill(cache.bucketFirst.begin(), cache.bucketFirst.end() - 1);
    for (size_t i = 0; i < n; ++i)
        if (points[i].reach > 0.0f) cache.slots[fill[bucket[i]]++] = points[i];
    return cache;
}

uint32_t findCachePoint(const RadianceCache& cache, const glm::vec3& position,
                        const glm::vec3& normal) {
    if (cache.empty()) return kNoCachePoint;
    // The sphere of radius cellSize / 2 around the point lies in these 2 x 2 x 2 cells.
    const glm::ivec3 base = cellOfPoint(position - 0.5f * cache.cellSize, cache.cellSize);
    uint32_t best = kNoCachePoint;
    float bestDistance2 = 0.0f;
    uint32_t visited[8];
    int visitedCount = 0;
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                const uint32_t b = bucketOf(base + glm::ivec3(dx, dy, dz), cache.bucketMask);
                if (std::find(visited, visited + visitedCount, b) != visited + visitedCount)
                    continue;
                visited[visitedCount++] = b;
                const CachePoint* slot = cache.slots.data() + cache.bucketFirst[b];
                const CachePoint* end = cache.slots.data() + cache.bucketFirst[b + 1];
                for (; slot != end; ++slot) {
                    const glm::vec3 d = position - slot->position;
                    const float d2 = glm::dot(d, d);
                    const float r = slot->reach;
                    if (d2 > r * r) continue;
                    if (best != kNoCachePoint &&
                        (d2 > bestDistance2 || (d2 == bestDistance2 && slot->index > best)))
                        continue;
                    if (glm::dot(normal, slot->normal) < kNormalAgreement ||
                        std::fabs(glm::dot(d, slot->normal)) > kPlaneTolerance * r)
                        continue;
                    best = slot->index;
                    bestDistance2 = d2;
                }
            }
    return best;
}

}  // namespace onelight::bake
