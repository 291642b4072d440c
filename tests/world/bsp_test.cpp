#include <algorithm>
#include <functional>
#include <random>

#include <gtest/gtest.h>

#include "world/bsp/bsp_build.hpp"
#include "world/bsp/bsp_query.hpp"
#include "world/compile/compile_level.hpp"

namespace onelight::test {
namespace {

using namespace onelight::world;

/// A level made of one static mesh instance holding the given triangle corners.
SourceLevel soupLevel(const std::vector<glm::vec3>& corners) {
    SourceLevel level;
    level.sourcePath = "soup";
    level.materials.push_back(Material{});
    MeshInstance instance;
    instance.nodeName = "soup";
    instance.meshName = "soup";
    instance.material = 0;
    for (size_t i = 0; i < corners.size(); ++i) {
        Vertex v;
        v.position = corners[i];
        instance.vertices.push_back(v);
        instance.indices.push_back(static_cast<uint32_t>(i));
    }
    // Face normals so the regions stage sees sensible orientations.
    for (size_t t = 0; t + 2 < corners.size(); t += 3) {
        const glm::vec3 n = glm::cross(corners[t + 1] - corners[t], corners[t + 2] - corners[t]);
        const float length = glm::length(n);
        for (size_t k = 0; k < 3; ++k)
            instance.vertices[t + k].normal = length > 0.0f ? n / length : glm::vec3(0, 0, 1);
    }
    level.instances.push_back(instance);
    return level;
}

/// Random triangles of about `size` metres in a cube of `extent` metres around `centre`, plus the
/// hard cases: coplanar grids, duplicated faces, slivers and T-junctions.
std::vector<glm::vec3> hardSoup(uint32_t seed, int count, float extent, float size,
                                glm::vec3 centre) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<glm::vec3> c;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 p = centre + extent * glm::vec3(unit(random), unit(random), unit(random));
        c.push_back(p);
        c.push_back(p + size * glm::vec3(unit(random), unit(random), unit(random)));
        c.push_back(p + size * glm::vec3(unit(random), unit(random), unit(random)));
    }
    // Coplanar floor of quads at y = centre.y, plus duplicates of its first row.
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            const glm::vec3 o = centre + glm::vec3(i - 4.0f, 0.0f, j - 4.0f) * (extent / 4.0f);
            const float s = extent / 4.0f;
            c.insert(c.end(), {o, o + glm::vec3(0, 0, s), o + glm::vec3(s, 0, s)});
            c.insert(c.end(), {o, o + glm::vec3(s, 0, s), o + glm::vec3(s, 0, 0)});
            if (i == 0) c.insert(c.end(), {o, o + glm::vec3(0, 0, s), o + glm::vec3(s, 0, s)});
        }
    }
    // A nearly coplanar copy one micrometre above, slivers, and a T-junction fan.
    const glm::vec3 up = centre + glm::vec3(0, 1e-6f * extent, 0);
    c.insert(c.end(), {up, up + glm::vec3(0, 0, 1), up + glm::vec3(1, 0, 1)});
    c.insert(c.end(), {centre, centre + glm::vec3(extent, 0, 0),
                       centre + glm::vec3(extent / 2, 1e-4f, 0.0f)});
    c.insert(c.end(), {centre, centre + glm::vec3(0, extent, 0),
                       centre + glm::vec3(1e-4f, extent / 2, 1e-4f)});
    const glm::vec3 t = centre + glm::vec3(0, extent / 2, 0);
    c.insert(c.end(), {t, t + glm::vec3(2, 0, 0), t + glm::vec3(1, 1, 0)});
    c.insert(c.end(), {t, t + glm::vec3(1, 0, 0), t + glm::vec3(1, -1, 0)});
    c.insert(c.end(), {t + glm::vec3(1, 0, 0), t + glm::vec3(2, 0, 0), t + glm::vec3(1, -1, 0)});
    return c;
}

/// For each leaf, the planes on its path and the side taken (+1 front, -1 back).
std::vector<std::vector<std::pair<uint32_t, int>>> leafPaths(const CompiledLevel& level) {
    std::vector<std::vector<std::pair<uint32_t, int>>> paths(level.bspLeaves.size());
    std::function<void(int32_t, std::vector<std::pair<uint32_t, int>>&)> walk =
        [&](int32_t child, std::vector<std::pair<uint32_t, int>>& path) {
            if (child < 0) {
                paths[static_cast<size_t>(-child - 1)] = path;
                return;
            }
            const BspNode& n = level.bspNodes[static_cast<size_t>(child)];
            path.push_back({n.plane, 1});
            walk(n.front, path);
            path.back().second = -1;
            walk(n.back, path);
            path.pop_back();
        };
    std::vector<std::pair<uint32_t, int>> path;
    if (!level.bspNodes.empty()) walk(0, path);
    return paths;
}

double signedDistance(const CompiledLevel& level, uint32_t plane, const glm::dvec3& p) {
    return glm::dot(level.bspPlanes[plane].normal, p) - level.bspPlanes[plane].distance;
}

struct BspCase {
    const char* name;
    float extent;
    glm::vec3 centre;
};

class BspInvariants : public ::testing::TestWithParam<BspCase> {
protected:
    void SetUp() override {
        const BspCase& c = GetParam();
        CompileOptions options;
        options.bsp.maxLeafTriangles = 8;
        level_ =
            compileLevel(soupLevel(hardSoup(7, 600, c.extent, c.extent / 5, c.centre)), options)
                .level;
        view_ = bspView(level_);
    }
    glm::dvec3 randomPoint(std::mt19937& random) const {
        std::uniform_real_distribution<double> unit(-1.3, 1.3);
        return glm::dvec3(GetParam().centre) +
               double(GetParam().extent) * glm::dvec3(unit(random), unit(random), unit(random));
    }
    CompiledLevel level_;
    BspView view_;
};

TEST_P(BspInvariants, EveryTriangleLiesInExactlyOneLeaf) {
    const size_t triangles = level_.indices.size() / 3;
    ASSERT_GT(level_.bspNodes.size(), 10u);
    std::vector<int> owners(triangles, 0);
    for (const BspLeaf& leaf : level_.bspLeaves)
        for (uint32_t t = leaf.firstTriangle; t < leaf.firstTriangle + leaf.triangleCount; ++t)
            ++owners[t];
    for (size_t t = 0; t < triangles; ++t) ASSERT_EQ(owners[t], 1) << "triangle " << t;
    const auto paths = leafPaths(level_);
    for (size_t l = 0; l < level_.bspLeaves.size(); ++l) {
        const BspLeaf& leaf = level_.bspLeaves[l];
        for (uint32_t i = 3 * leaf.firstTriangle; i < 3 * (leaf.firstTriangle + leaf.triangleCount);
             ++i) {
            const glm::dvec3 p(level_.vertices[level_.indices[i]].position);
            for (const auto& [plane, side] : paths[l])
                ASSERT_GE(side * signedDistance(level_, plane, p), -view_.epsilon)
                    << "leaf " << l << " index " << i << " is outside its leaf";
        }
    }
}

TEST_P(BspInvariants, PointLocationAgreesWithBruteForce) {
    const auto paths = leafPaths(level_);
    std::mt19937 random(11);
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 p = randomPoint(random);
        std::vector<uint32_t> containing;
        for (size_t l = 0; l < paths.size(); ++l) {
            bool inside = true;
            for (const auto& [plane, side] : paths[l])
                inside &= (signedDistance(level_, plane, p) >= 0.0) == (side > 0);
            if (inside) containing.push_back(static_cast<uint32_t>(l));
        }
        ASSERT_EQ(containing.size(), 1u);
        ASSERT_EQ(findLeaf(view_, p), containing[0]);
    }
}

TEST_P(BspInvariants, RayQueriesAgreeWithBruteForce) {
    std::mt19937 random(13);
    int hits = 0;
    for (int i = 0; i < 1500; ++i) {
        const glm::dvec3 origin = randomPoint(random);
        const glm::dvec3 direction = glm::normalize(randomPoint(random) - origin);
        const double tMax = 3.0 * double(GetParam().extent);
        const RayHit fast = raycast(view_, origin, direction, tMax);
        const RayHit slow = raycastBruteForce(view_, origin, direction, tMax);
        ASSERT_EQ(fast.hit, slow.hit) << "ray " << i;
        if (fast.hit) {
            ++hits;
            ASSERT_EQ(fast.t, slow.t) << "ray " << i;
        }
    }
    EXPECT_GT(hits, 500);
}

TEST_P(BspInvariants, SweptSphereAgreesWithBruteForce) {
    std::mt19937 random(17);
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
        const glm::dvec3 start = randomPoint(random);
        const glm::dvec3 end = start + (randomPoint(random) - glm::dvec3(GetParam().centre)) * 0.5;
        const double radius = 0.02 * double(GetParam().extent);
        const SweepHit fast = sweepSphere(view_, start, end, radius);
        const SweepHit slow = sweepSphereBruteForce(view_, start, end, radius);
        ASSERT_EQ(fast.hit, slow.hit) << "sweep " << i;
        if (fast.hit) {
            ++hits;
            ASSERT_EQ(fast.fraction, slow.fraction) << "sweep " << i;
            ASSERT_NEAR(glm::length(fast.normal), 1.0, 1e-9);
        }
    }
    EXPECT_GT(hits, 50);
}

TEST_P(BspInvariants, FrontToBackVisitsEveryLeafOnceNearSideFirst) {
    std::mt19937 random(19);
    for (int i = 0; i < 20; ++i) {
        const glm::dvec3 eye = randomPoint(random);
        std::vector<int> rank(level_.bspLeaves.size(), -1);
        int next = 0;
        leavesFrontToBack(view_, eye, [&](uint32_t leaf) {
            ASSERT_EQ(rank[leaf], -1);
            rank[leaf] = next++;
        });
        ASSERT_EQ(static_cast<size_t>(next), level_.bspLeaves.size());
        ASSERT_EQ(rank[findLeaf(view_, eye)], 0);
        // For every node, each leaf on the eye's side comes before each leaf on the other.
        std::function<std::pair<int, int>(int32_t)> span =
            [&](int32_t child) -> std::pair<int, int> {
            if (child < 0)
                return {rank[static_cast<size_t>(-child - 1)],
                        rank[static_cast<size_t>(-child - 1)]};
            const BspNode& n = level_.bspNodes[static_cast<size_t>(child)];
            const auto f = span(n.front), b = span(n.back);
            const bool frontNear = signedDistance(level_, n.plane, eye) >= 0.0;
            EXPECT_LT(frontNear ? f.second : b.second, frontNear ? b.first : f.first);
            return {std::min(f.first, b.first), std::max(f.second, b.second)};
        };
        span(0);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Scales, BspInvariants,
    ::testing::Values(BspCase{"metres", 10.0f, glm::vec3(0.0f)},
                      BspCase{"far_from_origin", 50.0f, glm::vec3(1e5f, -1e5f, 1e5f)}),
    [](const ::testing::TestParamInfo<BspCase>& paramInfo) { return paramInfo.param.name; });

TEST(Bsp, SplittingKeepsAreaAndCountsSplits) {
    SourceLevel source = soupLevel(hardSoup(3, 400, 10.0f, 2.0f, glm::vec3(0.0f)));
    CompileOptions options;
    options.bsp.maxLeafTriangles = 4;
    const CompileResult result = compileLevel(source, options);
    EXPECT_GT(result.stats.bspSplits, 0u);
    double before = 0.0, after = 0.0;
    const MeshInstance& instance = source.instances[0];
    for (size_t t = 0; t < instance.indices.size(); t += 3) {
        const glm::dvec3 a(instance.vertices[instance.indices[t]].position);
        const glm::dvec3 b(instance.vertices[instance.indices[t + 1]].position);
        const glm::dvec3 c(instance.vertices[instance.indices[t + 2]].position);
        before += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    // The duplicated first row of the floor (8 quads' first triangles) is removed by the split
    // stage.
    before -= 8 * 0.5 * (10.0 / 4) * (10.0 / 4);
    const CompiledLevel& level = result.level;
    for (size_t t = 0; t < level.indices.size(); t += 3) {
        const glm::dvec3 a(level.vertices[level.indices[t]].position);
        const glm::dvec3 b(level.vertices[level.indices[t + 1]].position);
        const glm::dvec3 c(level.vertices[level.indices[t + 2]].position);
        after += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    EXPECT_NEAR(after, before, 1e-5 * before);  // float vertices in the package
}

TEST(Bsp, EmptyLevelHasOneEmptyLeafAndQueriesWork) {
    const CompiledLevel level = compileLevel(soupLevel({}), {}).level;
    ASSERT_EQ(level.bspLeaves.size(), 1u);
    EXPECT_TRUE(level.bspNodes.empty());
    const BspView view = bspView(level);
    EXPECT_EQ(findLeaf(view, glm::dvec3(1, 2, 3)), 0u);
    EXPECT_FALSE(raycast(view, glm::dvec3(0), glm::dvec3(0, 0, 1), 10.0).hit);
    EXPECT_FALSE(sweepSphere(view, glm::dvec3(0), glm::dvec3(0, 0, 1), 0.5).hit);
    int visited = 0;
    leavesFrontToBack(view, glm::dvec3(0), [&](uint32_t) { ++visited; });
    EXPECT_EQ(visited, 1);
}

TEST(Bsp, SphereStopsAgainstAFloor) {
    const CompiledLevel level =
        compileLevel(
            soupLevel({{-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {-5, 0, -5}, {5, 0, 5}, {5, 0, -5}}), {})
            .level;
    const SweepHit hit =
        sweepSphere(bspView(level), glm::dvec3(0, 2, 0), glm::dvec3(0, -2, 0), 0.5);
    ASSERT_TRUE(hit.hit);
    EXPECT_NEAR(hit.fraction, 1.5 / 4.0, 1e-12);
    EXPECT_NEAR(hit.normal.y, 1.0, 1e-12);
}

}  // namespace
}  // namespace onelight::test
