// The potentially visible set (bake/visibility/visibility_bake.hpp) against from-point truth:
// at camera positions in the open, every cluster that dense rays from the point hit must be in
// the set of the point's cell (the sampled method's conservativeness, measured). A hall split by
// two walls into three rooms joined by a chicane must cull the far room; the bake gives the same
// set on any thread count; the section round-trips and rejects lying indices.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "bake/lighting/sampling.hpp"
#include "bake/visibility/visibility_bake.hpp"
#include "bake_scenes.hpp"
#include "world/compile/compile_level.hpp"
#include "world/error.hpp"
#include "world/import/level_import.hpp"
#include "world/package/visibility_section.hpp"

namespace onelight::bake {
namespace {

// Quad p0 p1 p2 p3 (counter-clockwise seen from the side it faces) as n x m tiles.
void addTiles(world::SourceLevel& level, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3,
              int n, int m, uint32_t material) {
    const auto at = [&](float u, float v) {
        return glm::mix(glm::mix(p0, p1, u), glm::mix(p3, p2, u), v);
    };
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < n; ++i) {
            const float u0 = float(i) / float(n), u1 = float(i + 1) / float(n);
            const float v0 = float(j) / float(m), v1 = float(j + 1) / float(m);
            test::addQuad(level, at(u0, v0), at(u1, v0), at(u1, v1), at(u0, v1), material, "tile");
        }
}

// A 40 x 10 x 4 m hall (z up, its shell in 2 m tiles) cut into rooms A (x < -7), B and C
// (x > 7) by two 2 m walls: the first open at y 8..10, the second at y 0..2. A 0.5 m crate
// stands in each room.
world::SourceLevel chicaneHall() {
    world::SourceLevel level;
    const uint32_t m = test::addLambertMaterial(level, 0.5f);
    const float x0 = -20, x1 = 20, y0 = 0, y1 = 10, h = 4;
    addTiles(level, {x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}, 20, 5, m);  // floor
    addTiles(level, {x0, y0, h}, {x0, y1, h}, {x1, y1, h}, {x1, y0, h}, 5, 20, m);  // ceiling
    addTiles(level, {x0, y0, 0}, {x0, y0, h}, {x1, y0, h}, {x1, y0, 0}, 2, 20, m);  // y0, +y
    addTiles(level, {x0, y1, 0}, {x1, y1, 0}, {x1, y1, h}, {x0, y1, h}, 20, 2, m);  // y1, -y
    addTiles(level, {x0, y0, 0}, {x0, y1, 0}, {x0, y1, h}, {x0, y0, h}, 5, 2, m);   // x0, +x
    addTiles(level, {x1, y0, 0}, {x1, y0, h}, {x1, y1, h}, {x1, y1, 0}, 2, 5, m);   // x1, -x
    test::addBox(level, {-7, 0, 0}, {-5, 8, 4}, m, false, "wall_ab");
    test::addBox(level, {5, 2, 0}, {7, 10, 4}, m, false, "wall_bc");
    for (float x : {-15.0f, 0.0f, 15.0f})
        test::addBox(level, {x, 4.75f, 0}, {x + 0.5f, 5.25f, 0.5f}, m, false, "crate");
    level.lights.push_back(test::pointLight({0, 5, 3}, 100.0f, world::LightRole::kPrimary));
    return level;
}

bool insideAnyBox(glm::vec3 p, const std::vector<std::pair<glm::vec3, glm::vec3>>& boxes) {
    for (const auto& [lo, hi] : boxes)
        if (glm::all(glm::greaterThan(p, lo)) && glm::all(glm::lessThan(p, hi))) return true;
    return false;
}

struct Baked {
    world::CompiledLevel level;
    world::Visibility visibility;
    VisibilityStats stats;
};

// How a Quake 3 map's own set is used: not at all, bounding the rays, or instead of them.
enum class OwnSet { kIgnored, kBounds, kReplaces };

Baked bake(const world::SourceLevel& source, const EmbreeDevice& device,
           const VisibilitySettings& settings = {}, OwnSet ownSet = OwnSet::kIgnored) {
    Baked b;
    b.level = world::compileLevel(source, test::testOptions(2.0f).compile).level;
    const BakeScene scene(device, b.level);
    b.visibility =
        bakeVisibility(scene, b.level, settings, false, &b.stats, 0, 1,
                       ownSet == OwnSet::kIgnored ? nullptr : &source.importedVisibility,
                       ownSet == OwnSet::kReplaces ? ImportedVisibilityUse::kReplacesTheRays
                                                   : ImportedVisibilityUse::kBoundsTheRays);
    return b;
}

// The cluster that the ray from `eye` along `dir` shows (through alpha triangles, as the bake
// sees them), or kNoIndex. `alsoHidden` collects every cluster met on the way.
uint32_t clusterSeen(const BakeScene& scene, const std::vector<uint32_t>& triangleCluster,
                     glm::vec3 eye, glm::vec3 dir, std::vector<uint32_t>* alsoMet = nullptr) {
    uint64_t rays = 0;
    glm::vec3 origin = eye;
    float reach = scene.sceneDiameter();
    for (int step = 0; step < 16; ++step) {
        const SurfaceHit hit = scene.intersect(origin, dir, reach, rays);
        if (!hit.found) return world::kNoIndex;
        if (scene.materialOf(hit.triangle).alphaMode == world::AlphaMode::kOpaque)
            return triangleCluster[hit.triangle];
        if (alsoMet) alsoMet->push_back(triangleCluster[hit.triangle]);
        origin += dir * (hit.distance + scene.rayOffset());
        reach -= hit.distance + scene.rayOffset();
    }
    return world::kNoIndex;
}

// Clusters that `directions` rays from `eye` show and that the set of eye's cell lacks, where
// they cover at least a pixel: the four rays 1.5 mrad around the ray (a pixel of a 1280-wide
// 90-degree view is 1.2 mrad) show the same cluster. Narrower slivers (a crack between two
// surfaces) are counted in `slivers`.
uint32_t missedFrom(const BakeScene& scene, const Baked& b, glm::vec3 eye, uint32_t directions,
                    std::vector<uint32_t>& triangleCluster, uint32_t& slivers) {
    if (triangleCluster.empty()) {
        triangleCluster.assign(b.level.indices.size() / 3, 0u);
        for (size_t i = 0; i < b.level.surfaces.size(); ++i) {
            const world::Surface& s = b.level.surfaces[i];
            for (uint32_t t = s.firstIndex / 3; t < (s.firstIndex + s.indexCount) / 3; ++t)
                triangleCluster[t] = b.visibility.surfaceCluster[i];
        }
    }
    const uint32_t row = world::visibilityRowAt(b.visibility, eye);
    std::vector<uint32_t> missed(b.visibility.clusterCount, 0);
    std::vector<uint32_t> met;
    for (uint32_t i = 0; i < directions; ++i) {  // a Fibonacci sphere
        const float z = 1.0f - 2.0f * (float(i) + 0.5f) / float(directions);
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const float phi = float(i) * 2.39996323f;
        const glm::vec3 dir(r * std::cos(phi), r * std::sin(phi), z);
        met.clear();
        const uint32_t c = clusterSeen(scene, triangleCluster, eye, dir, &met);
        if (c != world::kNoIndex) met.push_back(c);
        for (uint32_t m : met) {
            if (world::clusterInRow(b.visibility, row, m)) continue;
            const glm::vec3 u = glm::normalize(
                glm::cross(dir, std::abs(dir.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0)));
            const glm::vec3 v = glm::cross(dir, u);
            bool wide = true;
            for (const glm::vec3 offset : {u, -u, v, -v}) {
                std::vector<uint32_t> around;
                const uint32_t seen = clusterSeen(scene, triangleCluster, eye,
                                                  glm::normalize(dir + 1.5e-3f * offset), &around);
                wide = wide &&
                       (seen == m || std::find(around.begin(), around.end(), m) != around.end());
            }
            if (wide) {
                ++missed[m];
            } else {
                ++slivers;
            }
        }
    }
    uint32_t count = 0;
    for (uint32_t c = 0; c < missed.size(); ++c) {
        if (missed[c] == 0) continue;
        std::printf("  missed: cluster %u from (%.2f %.2f %.2f) by %u of %u rays\n", c,
                    double(eye.x), double(eye.y), double(eye.z), missed[c], directions);
        ++count;
    }
    return count;
}

// In the open in a sealed map and where a player's camera can be: of 1024 rays, none hits the
// back of a one-sided surface first (inside a wall, or in the void around the map, most do),
// and none hits anything nearer than 0.2 m (a player's collision keeps its camera that far from
// walls; the sampled sets are not promised nearer).
bool inTheOpen(const BakeScene& scene, glm::vec3 eye) {
    uint64_t rays = 0;
    for (uint32_t i = 0; i < 1024; ++i) {
        const float z = 1.0f - 2.0f * (float(i) + 0.5f) / 1024.0f;
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const float phi = float(i) * 2.39996323f;
        const SurfaceHit h =
            scene.intersect(eye, {r * std::cos(phi), r * std::sin(phi), z}, 1e4f, rays);
        if (h.found && h.distance < 0.2f) return false;
        if (h.found && h.backFace && !scene.materialOf(h.triangle).doubleSided) return false;
    }
    return true;
}

// From 300 points in the open, 16k rays each: no cluster they see is missing from the set.
TEST(Visibility, EveryClusterSeenFromAnOpenPointIsInItsCellsSet) {
    const EmbreeDevice device;
    const Baked b = bake(chicaneHall(), device);
    ASSERT_FALSE(b.visibility.empty());
    const BakeScene scene(device, b.level);
    const std::vector<std::pair<glm::vec3, glm::vec3>> solid = {{{-7, 0, 0}, {-5, 8, 4}},
                                                                {{5, 2, 0}, {7, 10, 4}}};
    std::vector<uint32_t> triangleCluster;
    Rng rng{seedFrom(7u)};
    uint32_t eyes = 0, missed = 0, slivers = 0;
    while (eyes < 300) {
        const glm::vec3 eye(-19.9f + 39.8f * rng.next(), 0.1f + 9.8f * rng.next(),
                            0.1f + 3.8f * rng.next());
        if (insideAnyBox(eye, solid) || !inTheOpen(scene, eye)) continue;
        ++eyes;
        missed += missedFrom(scene, b, eye, 16384, triangleCluster, slivers);
    }
    std::printf(
        "chicane hall: %u clusters, %u cells, %u sets, a cell sees %.0f%%; %u misses "
        "(and %u rays on slivers) from %u points\n",
        b.stats.clusters, b.stats.cells, b.stats.rows, 100.0 * b.stats.meanVisibleFraction, missed,
        slivers, eyes);
    EXPECT_EQ(missed, 0u);
}

// The far room is hidden from the first: from room A's middle, neither room C's crate nor most
// of its walls are in the set, while everything in room A is.
TEST(Visibility, TheChicaneHidesTheFarRoom) {
    const EmbreeDevice device;
    const Baked b = bake(chicaneHall(), device);
    const uint32_t row = world::visibilityRowAt(b.visibility, {-14.0f, 3.0f, 1.7f});
    ASSERT_NE(row, world::kNoIndex);
    uint32_t farClusters = 0, farVisible = 0;
    for (size_t i = 0; i < b.level.surfaces.size(); ++i) {
        const world::Surface& s = b.level.surfaces[i];
        const uint32_t c = b.visibility.surfaceCluster[i];
        const bool visible = world::clusterInRow(b.visibility, row, c);
        if (s.boundsMax.x < -8.0f) {
            EXPECT_TRUE(visible) << "a surface of room A is culled";
        }
        if (s.boundsMin.x > 9.0f) {
            ++farClusters;
            farVisible += visible;
        }
    }
    std::printf("room C: %u of %u surfaces in room A's set\n", farVisible, farClusters);
    ASSERT_GT(farClusters, 0u);
    EXPECT_EQ(farVisible, 0u);
}

// The same set, byte for byte, on one thread and on two.
TEST(Visibility, TheSetDoesNotDependOnThreads) {
    const EmbreeDevice device;
    world::Visibility one, two;
    {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
        one = bake(chicaneHall(), device).visibility;
    }
    {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
        two = bake(chicaneHall(), device).visibility;
    }
    EXPECT_TRUE(one == two);
}

// Parts of a sharded bake sample every N-th view cell; joined in shard order they equal the
// whole set byte for byte, and each part samples its share of the cells.
TEST(Visibility, PartsJoinedEqualTheWholeSet) {
    const EmbreeDevice device;
    const Baked whole = bake(chicaneHall(), device);
    const BakeScene scene(device, whole.level);
    for (const uint32_t count : {2u, 3u, 7u}) {
        std::vector<world::Visibility> parts(count);
        std::vector<const world::Visibility*> pointers;
        uint32_t sampled = 0;
        for (uint32_t i = 0; i < count; ++i) {
            VisibilityStats stats;
            parts[i] = bakeVisibility(scene, whole.level, {}, false, &stats, i, count);
            sampled += stats.cells;
            EXPECT_LE(stats.cells, whole.stats.cells / count + 1) << i << "/" << count;
            pointers.push_back(&parts[i]);
        }
        EXPECT_EQ(sampled, whole.stats.cells) << count;
        EXPECT_TRUE(mergeVisibilityParts(pointers) == whole.visibility) << count;
        // A part holds only its own cells' sets: not the whole.
        EXPECT_FALSE(parts[0] == whole.visibility) << count;
    }
}

// The section round-trips, and the reader rejects a cluster or row index out of range, bits
// past the cluster count, a surface count that is not the level's and a truncated section.
TEST(Visibility, TheSectionRoundTripsAndRejectsLyingIndices) {
    const EmbreeDevice device;
    const Baked b = bake(chicaneHall(), device);
    const package::RawSection good = package::encodeVisibilitySection(b.visibility);
    EXPECT_TRUE(package::decodeVisibilitySection(good, b.level, "hall.olpak") == b.visibility);
    const size_t header = 48, surfaceCount = b.level.surfaces.size();
    const size_t cells = b.visibility.cellRow.size();
    const auto rejects = [&](package::RawSection s, const char* expected) {
        try {
            (void)package::decodeVisibilitySection(s, b.level, "hall.olpak");
            ADD_FAILURE() << "accepted; expected an error with '" << expected << "'";
        } catch (const world::Error& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("hall.olpak: section visibility"),
                      std::string::npos)
                << e.what();
        }
    };
    auto word = [](package::RawSection& s, size_t index, uint32_t value) {
        std::memcpy(s.bytes.data() + index * 4, &value, 4);
    };
    package::RawSection bad = good;
    word(bad, header / 4, b.visibility.clusterCount);  // surface 0's cluster
    rejects(bad, "surface 0 has cluster");
    bad = good;
    word(bad, header / 4 + surfaceCount + 3, b.visibility.rowCount());  // cell 3's row
    rejects(bad, "cell 3 has row");
    bad = good;
    word(bad, 8, uint32_t(surfaceCount + 1));  // header.surfaceCount
    rejects(bad, "surfaceCount");
    bad = good;
    bad.bytes.resize(bad.bytes.size() - 4);
    bad.count = uint32_t(bad.bytes.size());
    rejects(bad, "bytes; expected");
    if (b.visibility.clusterCount % 32 != 0) {
        bad = good;
        const size_t lastWord =
            (header + (surfaceCount + cells) * 4) / 4 + b.visibility.wordsPerRow() - 1;
        word(bad, lastWord, 0xFFFFFFFFu);
        rejects(bad, "past clusterCount");
    }
}

// A map we did not make: OpenArena's aggressor, from points around its spawns, with the set
// sampled by rays, by rays bounded by the map's own set (q3map2 -vis), and the map's own, which
// takes no ray.
const char* const kAggressorPk3 = "/usr/share/games/openarena/baseoa/pak1-maps.pk3";

Baked checkAggressorFromItsSpawns(OwnSet ownSet) {
    const std::string pk3 = kAggressorPk3;
    const EmbreeDevice device;
    const world::SourceLevel source = world::importLevel(pk3 + ":maps/aggressor.bsp");
    EXPECT_FALSE(source.importedVisibility.empty());
    const auto start = std::chrono::steady_clock::now();
    Baked b = bake(source, device, {}, ownSet);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const BakeScene scene(device, b.level);
    std::vector<uint32_t> triangleCluster;
    uint32_t eyes = 0, missed = 0, slivers = 0;
    for (const world::Entity& e : b.level.entities) {
        if (!(e.flags & world::kEntitySpawn)) continue;
        Rng rng{seedFrom(eyes, 11u)};
        for (int k = 0; k < 12; ++k) {
            const glm::vec3 eye =
                e.position + 4.0f * glm::vec3(rng.next(), rng.next(), rng.next()) - 2.0f;
            if (!inTheOpen(scene, eye)) continue;
            ++eyes;
            missed += missedFrom(scene, b, eye, 16384, triangleCluster, slivers);
        }
    }
    static const char* const kNames[3] = {"sampled", "sampled within its own", "its own"};
    std::printf(
        "aggressor (%s set): %u clusters, %u cells, a cell sees %.0f%%, %llu rays, compile and "
        "set %.1f s; %u misses (and %u rays on slivers) from %u points\n",
        kNames[int(ownSet)], b.stats.clusters, b.stats.cells, 100.0 * b.stats.meanVisibleFraction,
        static_cast<unsigned long long>(b.stats.rays.total()), seconds, missed, slivers, eyes);
    if (ownSet == OwnSet::kReplaces) {
        EXPECT_EQ(b.stats.rays.total(), 0u);
    }
    EXPECT_GT(eyes, 20u);
    EXPECT_EQ(missed, 0u);
    return b;
}

// Bounded by the map's own set (q3map2's portals, which the game itself culls by), the rays find
// a subset of the unbounded rays' set with fewer segments: a cell's set loses only the pairs
// q3map2's portals close and a segment found open (through a crack, or from a point in a wall).
TEST(Visibility, AQuake3MapsSetsHoldWhatItsSpawnsSee) {
    if (!std::filesystem::exists(kAggressorPk3))
        GTEST_SKIP() << kAggressorPk3 << " is missing: install openarena-data";
    const Baked rays = checkAggressorFromItsSpawns(OwnSet::kIgnored);
    const Baked bounded = checkAggressorFromItsSpawns(OwnSet::kBounds);
    ASSERT_EQ(rays.visibility.cellRow.size(), bounded.visibility.cellRow.size());
    const uint32_t words = rays.visibility.wordsPerRow();
    ASSERT_EQ(words, bounded.visibility.wordsPerRow());
    uint64_t pairs = 0, lost = 0, gained = 0;
    uint32_t cellsDiffering = 0;
    for (size_t cell = 0; cell < rays.visibility.cellRow.size(); ++cell) {
        const uint32_t a = rays.visibility.cellRow[cell], b = bounded.visibility.cellRow[cell];
        ASSERT_EQ(a == world::kNoIndex, b == world::kNoIndex) << "cell " << cell;
        if (a == world::kNoIndex) continue;
        uint64_t here = 0;
        for (uint32_t w = 0; w < words; ++w) {
            const uint32_t x = rays.visibility.rows[size_t(a) * words + w];
            const uint32_t y = bounded.visibility.rows[size_t(b) * words + w];
            pairs += uint32_t(__builtin_popcount(x));
            here += uint32_t(__builtin_popcount(x & ~y));
            gained += uint32_t(__builtin_popcount(y & ~x));
        }
        lost += here;
        cellsDiffering += here > 0;
    }
    std::printf(
        "bounded by its own set: %llu of the rays' %llu visible (cell, cluster) pairs "
        "lost, in %u cells\n",
        static_cast<unsigned long long>(lost), static_cast<unsigned long long>(pairs),
        cellsDiffering);
    EXPECT_EQ(gained, 0u);  // a subset: the bound only skips segments
    EXPECT_LE(lost, pairs / 100);
    EXPECT_LT(bounded.stats.rays.total(), rays.stats.rays.total() * 3 / 4);
}

TEST(Visibility, AQuake3MapsOwnSetHoldsWhatItsSpawnsSee) {
    if (!std::filesystem::exists(kAggressorPk3))
        GTEST_SKIP() << kAggressorPk3 << " is missing: install openarena-data";
    (void)checkAggressorFromItsSpawns(OwnSet::kReplaces);
}

}  // namespace
}  // namespace onelight::bake
