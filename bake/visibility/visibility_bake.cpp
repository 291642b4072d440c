#include "bake/visibility/visibility_bake.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <tbb/enumerable_thread_specific.h>

#include "bake/lighting/sampling.hpp"
#include "bake/parallel_for.hpp"
#include "bake/report/progress.hpp"

namespace onelight::bake {
namespace {

using world::kNoIndex;

struct Cluster {
    glm::vec3 boundsMin{1e30f}, boundsMax{-1e30f};
    std::vector<glm::vec3> targets;  // points on its triangles, spread by area
    std::vector<glm::vec3> normals;  // their triangles' unit normals
};

// Triangles per subtree, bottom-up (child < 0 is a leaf).
uint64_t subtreeTriangles(const world::CompiledLevel& level, int32_t child,
                          std::vector<uint64_t>& nodeTriangles) {
    if (child < 0) return level.bspLeaves[size_t(-(child + 1))].triangleCount;
    const world::BspNode& n = level.bspNodes[size_t(child)];
    const uint64_t count = subtreeTriangles(level, n.front, nodeTriangles) +
                           subtreeTriangles(level, n.back, nodeTriangles);
    nodeTriangles[size_t(child)] = count;
    return count;
}

// Gives every surface under `child` a cluster: one for a whole subtree that is small enough,
// else, in a leaf, one per cube of maxClusterExtent (by the surface's centre) that holds any.
void assignClusters(const world::CompiledLevel& level, const VisibilitySettings& settings,
                    const std::vector<uint64_t>& nodeTriangles, int32_t child, uint32_t inherited,
                    std::vector<uint32_t>& surfaceCluster, uint32_t& count) {
    if (child < 0) {
        const world::BspLeaf& leaf = level.bspLeaves[size_t(-(child + 1))];
        std::map<std::tuple<int64_t, int64_t, int64_t>, uint32_t> byCube;
        for (uint32_t i = leaf.firstSurface; i < leaf.firstSurface + leaf.surfaceCount; ++i) {
            if (inherited != kNoIndex) {
                surfaceCluster[i] = inherited;
                continue;
            }
            const world::Surface& surface = level.surfaces[i];
            const glm::vec3 centre =
                0.5f * (surface.boundsMin + surface.boundsMax) / settings.maxClusterExtent;
            const auto key =
                std::make_tuple(int64_t(std::floor(centre.x)), int64_t(std::floor(centre.y)),
                                int64_t(std::floor(centre.z)));
            const auto [it, inserted] = byCube.try_emplace(key, count);
            if (inserted) ++count;
            surfaceCluster[i] = it->second;
        }
        return;
    }
    const world::BspNode& n = level.bspNodes[size_t(child)];
    uint32_t cluster = inherited;
    if (cluster == kNoIndex) {
        const glm::vec3 extent = n.boundsMax - n.boundsMin;
        if (nodeTriangles[size_t(child)] <= settings.maxClusterTriangles &&
            std::max({extent.x, extent.y, extent.z}) <= settings.maxClusterExtent)
            cluster = count++;
    }
    assignClusters(level, settings, nodeTriangles, n.front, cluster, surfaceCluster, count);
    assignClusters(level, settings, nodeTriangles, n.back, cluster, surfaceCluster, count);
}

bool isAlpha(const BakeScene& scene, uint32_t triangle) {
    return scene.materialOf(triangle).alphaMode != world::AlphaMode::kOpaque;
}

// The closest opaque triangle along the ray, stepping through alpha ones; kNoIndex for none.
// Calls mark(hit) for every triangle hit on the way, alpha or not.
template <typename Mark>
void sweep(const BakeScene& scene, glm::vec3 origin, glm::vec3 dir, float maxDistance,
           uint64_t& rays, Mark&& mark) {
    for (int step = 0; step < 16; ++step) {
        const SurfaceHit hit = scene.intersect(origin, dir, maxDistance, rays);
        if (!hit.found) return;
        mark(hit);
        if (!isAlpha(scene, hit.triangle)) return;
        const float advance = hit.distance + scene.rayOffset();
        origin += dir * advance;
        maxDistance -= advance;
        if (maxDistance <= 0.0f) return;
    }
}

// Whether an opaque triangle lies on the segment from a to b.
bool segmentBlocked(const BakeScene& scene, bool levelHasAlpha, glm::vec3 a, glm::vec3 b,
                    uint64_t& rays) {
    const glm::vec3 d = b - a;
    const float length = glm::length(d);
    if (!(length > 0.0f)) return false;
    const glm::vec3 dir = d / length;
    if (!levelHasAlpha) return scene.occluded(a, dir, length, rays);
    bool blocked = false;
    sweep(scene, a, dir, length, rays,
          [&](const SurfaceHit& hit) { blocked = blocked || !isAlpha(scene, hit.triangle); });
    return blocked;
}

// Cluster bounds, and targetsPerCluster points spread by area over its triangles.
std::vector<Cluster> makeClusters(const BakeScene& scene, const world::CompiledLevel& level,
                                  const std::vector<uint32_t>& surfaceCluster, uint32_t count,
                                  const VisibilitySettings& settings) {
    std::vector<Cluster> clusters(count);
    std::vector<std::vector<uint32_t>> triangles(count);
    for (size_t i = 0; i < level.surfaces.size(); ++i) {
        const world::Surface& surface = level.surfaces[i];
        for (uint32_t t = surface.firstIndex / 3; t < (surface.firstIndex + surface.indexCount) / 3;
             ++t)
            triangles[surfaceCluster[i]].push_back(t);
    }
    for (uint32_t c = 0; c < count; ++c) {
        Cluster& cluster = clusters[c];
        std::vector<double> cumulative;
        double total = 0.0;
        for (uint32_t t : triangles[c]) {
            const std::array<glm::vec3, 3> v = scene.triangleVertices(t);
            for (const glm::vec3& p : v) {
                cluster.boundsMin = glm::min(cluster.boundsMin, p);
                cluster.boundsMax = glm::max(cluster.boundsMax, p);
            }
            total +=
                0.5 * glm::length(glm::cross(glm::dvec3(v[1] - v[0]), glm::dvec3(v[2] - v[0])));
            cumulative.push_back(total);
        }
        if (triangles[c].empty() || !(total > 0.0)) continue;
        for (uint32_t k = 0; k < settings.targetsPerCluster; ++k) {
            Rng rng{seedFrom(c, k, 0x5653u)};
            const double u = (double(k) + double(rng.next())) / settings.targetsPerCluster * total;
            const size_t i =
                std::min(size_t(std::lower_bound(cumulative.begin(), cumulative.end(), u) -
                                cumulative.begin()),
                         cumulative.size() - 1);
            const uint32_t t = triangles[c][i];
            const std::array<glm::vec3, 3> v = scene.triangleVertices(t);
            float b1 = rng.next(), b2 = rng.next();
            if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
            cluster.targets.push_back(v[0] + b1 * (v[1] - v[0]) + b2 * (v[2] - v[0]));
            cluster.normals.push_back(scene.triangleNormal(t));
        }
    }
    return clusters;
}

bool boxesOverlap(glm::vec3 aMin, glm::vec3 aMax, glm::vec3 bMin, glm::vec3 bMax) {
    return glm::all(glm::lessThanEqual(aMin, bMax)) && glm::all(glm::lessThanEqual(bMin, aMax));
}

// The source's clusters (sorted, unique, solid left out) of the leaves the box [lo, hi] reaches.
std::vector<uint32_t> importedClustersIn(const world::ImportedVisibility& v, glm::vec3 lo,
                                         glm::vec3 hi) {
    std::vector<uint32_t> leaves, out;
    world::importedLeavesIn(v, lo, hi, leaves);
    for (uint32_t leaf : leaves)
        if (v.leafs[leaf].cluster >= 0) out.push_back(uint32_t(v.leafs[leaf].cluster));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

// Step 3 from the source's own set for the cell [cellMin, cellMax]: the clusters of the leaves
// the cell reaches see the union of their rows; each of our clusters one of whose source
// clusters is in it is marked, and so is one whose bounds reach into the cell or its
// neighbours. A cell that reaches no leaf of a cluster (inside solid) is not open.
template <typename Mark>
bool markFromImported(const world::ImportedVisibility& v,
                      const std::vector<std::vector<uint32_t>>& importedClusters, glm::vec3 cellMin,
                      glm::vec3 cellMax, const std::vector<Cluster>& clusters, float cellSize,
                      Mark&& mark) {
    const std::vector<uint32_t> from = importedClustersIn(v, cellMin, cellMax);
    if (from.empty()) return false;
    std::vector<uint8_t> seen(v.clusterCount, 0);
    for (uint32_t a : from)
        for (uint32_t b = 0; b < v.clusterCount; ++b)
            seen[b] |= world::importedClusterSees(v, a, b);
    const glm::vec3 nearMin = cellMin - cellSize, nearMax = cellMax + cellSize;
    for (uint32_t c = 0; c < clusters.size(); ++c) {
        bool visible = boxesOverlap(clusters[c].boundsMin, clusters[c].boundsMax, nearMin, nearMax);
        for (uint32_t s : importedClusters[c]) visible = visible || seen[s] != 0;
        if (visible) mark(c);
    }
    return true;
}

// Step 1: per static surface its cluster, and the cluster count.
std::vector<uint32_t> clusterSurfaces(const world::CompiledLevel& level,
                                      const VisibilitySettings& settings, uint32_t& clusterCount) {
    std::vector<uint32_t> surfaceCluster(level.surfaces.size(), 0u);
    clusterCount = 0;
    if (level.bspLeaves.empty()) return surfaceCluster;
    std::vector<uint64_t> nodeTriangles(level.bspNodes.size(), 0);
    if (!level.bspNodes.empty()) subtreeTriangles(level, 0, nodeTriangles);
    assignClusters(level, settings, nodeTriangles, level.bspNodes.empty() ? -1 : 0, kNoIndex,
                   surfaceCluster, clusterCount);
    return surfaceCluster;
}

}  // namespace

world::Visibility bakeVisibility(const BakeScene& scene, const world::CompiledLevel& level,
                                 const VisibilitySettings& settings, bool showProgress,
                                 VisibilityStats* stats, uint32_t part, uint32_t parts,
                                 const world::ImportedVisibility* imported,
                                 ImportedVisibilityUse use) {
    parts = std::max(parts, 1u);
    world::Visibility v;
    if (level.indices.empty() || level.surfaces.empty() || level.bspLeaves.empty()) return v;
    v.surfaceCluster = clusterSurfaces(level, settings, v.clusterCount);
    const std::vector<Cluster> clusters =
        makeClusters(scene, level, v.surfaceCluster, v.clusterCount, settings);
    std::vector<uint32_t> triangleCluster(level.indices.size() / 3, 0u);
    for (size_t i = 0; i < level.surfaces.size(); ++i) {
        const world::Surface& surface = level.surfaces[i];
        for (uint32_t t = surface.firstIndex / 3; t < (surface.firstIndex + surface.indexCount) / 3;
             ++t)
            triangleCluster[t] = v.surfaceCluster[i];
    }
    bool levelHasAlpha = false;
    for (uint32_t t = 0; t < scene.triangleCount() && !levelHasAlpha; ++t)
        levelHasAlpha = isAlpha(scene, t);

    const glm::vec3 lo = level.settings.boundsMin, hi = level.settings.boundsMax;
    const glm::vec3 extent = hi - lo;
    const float longest = std::max({extent.x, extent.y, extent.z});
    v.cellSize = std::max(longest / float(settings.cellsPerAxis), settings.minCellSize);
    v.origin = lo - 0.5f * v.cellSize;
    v.dims = glm::min(glm::uvec3(glm::ceil((extent + v.cellSize) / v.cellSize)),
                      glm::uvec3(world::kMaxVisibilityCellsPerAxis));
    v.dims = glm::max(v.dims, glm::uvec3(1u));
    const uint32_t cellCount = v.dims.x * v.dims.y * v.dims.z;
    const uint32_t words = v.wordsPerRow();
    std::vector<uint32_t> raw(size_t(cellCount) * words, 0u);
    std::vector<uint8_t> openCell(cellCount, 0);

    const float reach = scene.sceneDiameter();
    // With the source's own set: each of our clusters' clusters of it (the leaves its bounds
    // reach), to bound the rays or to replace them.
    if (imported && imported->empty()) imported = nullptr;
    const bool replaced = imported && use == ImportedVisibilityUse::kReplacesTheRays;
    std::vector<std::vector<uint32_t>> importedClusters;
    if (imported)
        for (const Cluster& c : clusters)
            // Grown by 2 cm: a face lying on a splitting plane reaches only the side in front
            // of it, which can be the solid behind the face when the tree split there with the
            // plane turned the other way.
            importedClusters.push_back(
                importedClustersIn(*imported, c.boundsMin - 0.02f, c.boundsMax + 0.02f));
    tbb::enumerable_thread_specific<RayCounts> rays;
    // Part `part` of `parts` bakes every parts-th cell from `part` (interleaved: solid and open
    // cells spread evenly over the parts).
    const uint32_t owned = cellCount > part ? (cellCount - part + parts - 1) / parts : 0;
    Progress progress("visibility", owned, showProgress);
    bake::parallelFor(tbb::blocked_range<uint32_t>(0, owned, 1), [&](const auto& range) {
        RayCounts& local = rays.local();
        for (uint32_t nth = range.begin(); nth != range.end(); ++nth) {
            const uint32_t cell = part + nth * parts;
            const glm::uvec3 c(cell % v.dims.x, (cell / v.dims.x) % v.dims.y,
                               cell / (v.dims.x * v.dims.y));
            const glm::vec3 cellMin = v.origin + glm::vec3(c) * v.cellSize;
            uint32_t* row = &raw[size_t(cell) * words];
            auto mark = [&](uint32_t cluster) { row[cluster / 32] |= 1u << (cluster % 32); };
            auto marked = [&](uint32_t cluster) {
                return (row[cluster / 32] >> (cluster % 32)) & 1u;
            };
            if (replaced) {
                openCell[cell] = markFromImported(*imported, importedClusters, cellMin,
                                                  cellMin + v.cellSize, clusters, v.cellSize, mark);
                progress.advance(1);
                continue;
            }
            std::vector<glm::vec3> points;
            for (uint32_t k = 0; k < settings.pointsPerCell; ++k) {
                Rng rng{seedFrom(cell, k, 0x5650u)};
                const glm::vec3 octant(float(k & 1), float((k >> 1) & 1), float((k >> 2) & 1));
                const glm::vec3 jitter(0.1f + 0.8f * rng.next(), 0.1f + 0.8f * rng.next(),
                                       0.1f + 0.8f * rng.next());
                points.push_back(cellMin + (octant + jitter) * (0.5f * v.cellSize));
            }
            // A point is open when at most a tenth of the surfaces its rays reach first show it
            // the back of a one-sided surface (inside a solid, under a floor or in the void
            // around a sealed map, most do; rays that leave the level count for neither). Only
            // open points mark clusters and aim segments; a cell with none culls nothing.
            std::vector<glm::vec3> open;
            std::vector<uint32_t> seen;
            for (uint32_t k = 0; k < points.size(); ++k) {
                Rng rng{seedFrom(cell, k, 0x5651u)};
                const float s0 = rng.next(), s1 = rng.next();
                seen.clear();
                uint32_t backFaces = 0, hits = 0;
                for (uint32_t i = 0; i < settings.sweepRays; ++i) {
                    const glm::vec2 u = rotatedHammersley(i, settings.sweepRays, s0, s1);
                    const float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z));
                    const float phi = 2.0f * glsl::PI * u.y;
                    const glm::vec3 dir(r * std::cos(phi), r * std::sin(phi), z);
                    bool first = true;
                    sweep(scene, points[k], dir, reach, local.probe, [&](const SurfaceHit& hit) {
                        seen.push_back(triangleCluster[hit.triangle]);
                        hits += first;
                        if (first && hit.backFace && !scene.materialOf(hit.triangle).doubleSided)
                            ++backFaces;
                        first = false;
                    });
                }
                if (10 * backFaces > hits) continue;
                open.push_back(points[k]);
                for (uint32_t cluster : seen) mark(cluster);
            }
            openCell[cell] = !open.empty();
            if (open.empty()) {
                progress.advance(1);
                continue;
            }
            // The clusters the source's set lets this cell see (none known: every cluster).
            std::vector<uint32_t> allowed;
            if (imported) {
                allowed.assign(words, 0u);
                if (!markFromImported(*imported, importedClusters, cellMin, cellMin + v.cellSize,
                                      clusters, v.cellSize, [&](uint32_t cluster) {
                                          allowed[cluster / 32] |= 1u << (cluster % 32);
                                      }))
                    allowed.clear();
            }
            auto hidden = [&](uint32_t cluster) {
                return !allowed.empty() && !((allowed[cluster / 32] >> (cluster % 32)) & 1u);
            };
            const glm::vec3 nearMin = cellMin - v.cellSize, nearMax = cellMin + 2.0f * v.cellSize;
            for (uint32_t cluster = 0; cluster < v.clusterCount; ++cluster) {
                if (marked(cluster)) continue;
                const Cluster& target = clusters[cluster];
                if (boxesOverlap(target.boundsMin, target.boundsMax, nearMin, nearMax)) {
                    mark(cluster);
                    continue;
                }
                if (target.targets.empty() || hidden(cluster)) continue;
                const uint32_t shift = seedFrom(cell, cluster, 0x5652u);
                for (uint32_t j = 0; j < settings.raysPerPair; ++j) {
                    const glm::vec3 eye = open[j % open.size()];
                    const uint32_t t = (j * 2654435761u + shift) % uint32_t(target.targets.size());
                    const glm::vec3 n = target.normals[t];
                    const float side = glm::dot(eye - target.targets[t], n) >= 0.0f ? 1.0f : -1.0f;
                    const glm::vec3 end = target.targets[t] + side * 4.0f * scene.rayOffset() * n;
                    if (!segmentBlocked(scene, levelHasAlpha, eye, end, local.shadow)) {
                        mark(cluster);
                        break;
                    }
                }
            }
            progress.advance(1);
        }
    });
    progress.finish();

    if (stats) {
        for (const RayCounts& r : rays) stats->rays += r;
        stats->cells = owned;
        stats->clusters = v.clusterCount;
    }
    if (parts > 1) {
        // A part: its cells' own sets, rows deduplicated, kNoIndex for the rest; the merge
        // joins the parts' and finishes them (finishVisibility).
        std::map<std::vector<uint32_t>, uint32_t> rowOf;
        v.cellRow.assign(cellCount, kNoIndex);
        for (uint32_t nth = 0; nth < owned; ++nth) {
            const uint32_t cell = part + nth * parts;
            if (!openCell[cell]) continue;
            const std::vector<uint32_t> row(raw.begin() + long(size_t(cell) * words),
                                            raw.begin() + long(size_t(cell + 1) * words));
            const auto [it, inserted] = rowOf.try_emplace(row, uint32_t(rowOf.size()));
            if (inserted) v.rows.insert(v.rows.end(), row.begin(), row.end());
            v.cellRow[cell] = it->second;
        }
        if (stats) stats->rows = v.rowCount();
        return v;
    }
    v = finishVisibility(std::move(v), raw, openCell, stats);
    return v;
}

world::Visibility finishVisibility(world::Visibility v, const std::vector<uint32_t>& raw,
                                   const std::vector<uint8_t>& openCell, VisibilityStats* stats) {
    // 4. Each cell's set: the union over it and its 26 neighbours; rows deduplicated.
    const uint32_t cellCount = v.dims.x * v.dims.y * v.dims.z;
    const uint32_t words = v.wordsPerRow();
    std::map<std::vector<uint32_t>, uint32_t> rowOf;
    v.rows.clear();
    v.cellRow.assign(cellCount, 0u);
    std::vector<uint32_t> merged(words);
    double visible = 0.0;
    uint32_t openCells = 0;
    for (uint32_t cell = 0; cell < cellCount; ++cell) {
        if (!openCell[cell]) {
            v.cellRow[cell] = kNoIndex;
            continue;
        }
        ++openCells;
        const glm::ivec3 c(cell % v.dims.x, (cell / v.dims.x) % v.dims.y,
                           cell / (v.dims.x * v.dims.y));
        std::fill(merged.begin(), merged.end(), 0u);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const glm::ivec3 n = c + glm::ivec3(dx, dy, dz);
                    if (glm::any(glm::lessThan(n, glm::ivec3(0))) ||
                        glm::any(glm::greaterThanEqual(n, glm::ivec3(v.dims))))
                        continue;
                    const size_t other =
                        size_t(n.x) + v.dims.x * (size_t(n.y) + v.dims.y * size_t(n.z));
                    for (uint32_t w = 0; w < words; ++w) merged[w] |= raw[other * words + w];
                }
        uint32_t bits = 0;
        for (uint32_t w : merged) bits += uint32_t(__builtin_popcount(w));
        visible += double(bits) / double(v.clusterCount);
        const auto [it, inserted] = rowOf.try_emplace(merged, uint32_t(rowOf.size()));
        if (inserted) v.rows.insert(v.rows.end(), merged.begin(), merged.end());
        v.cellRow[cell] = it->second;
    }
    if (stats) {
        stats->rows = v.rowCount();
        stats->openCells = openCells;
        stats->meanVisibleFraction = openCells ? visible / double(openCells) : 1.0;
    }
    return v;
}

world::Visibility mergeVisibilityParts(const std::vector<const world::Visibility*>& parts) {
    const uint32_t count = uint32_t(parts.size());
    if (count == 0 || parts[0]->empty()) return count ? *parts[0] : world::Visibility{};
    world::Visibility v = *parts[0];
    const uint32_t cellCount = v.dims.x * v.dims.y * v.dims.z;
    const uint32_t words = v.wordsPerRow();
    std::vector<uint32_t> raw(size_t(cellCount) * words, 0u);
    std::vector<uint8_t> openCell(cellCount, 0);
    for (uint32_t cell = 0; cell < cellCount; ++cell) {
        const world::Visibility& p = *parts[cell % count];
        const uint32_t row = p.cellRow[cell];
        if (row == kNoIndex) continue;
        openCell[cell] = 1;
        std::copy(p.rows.begin() + long(size_t(row) * words),
                  p.rows.begin() + long(size_t(row + 1) * words),
                  raw.begin() + long(size_t(cell) * words));
    }
    return finishVisibility(std::move(v), raw, openCell, nullptr);
}

}  // namespace onelight::bake
