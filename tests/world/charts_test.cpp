#include <gtest/gtest.h>

#include "tests/world/level_generator.hpp"
#include "tests/world/world_test_support.hpp"

namespace onelight::test {
namespace {

using namespace onelight::world;

void expectNoOverlapAndPadding(const CompiledLevel& level) {
    ASSERT_FALSE(level.charts.empty());
    for (size_t a = 0; a < level.charts.size(); ++a) {
        const Chart& c = level.charts[a];
        ASSERT_LT(c.atlas, level.atlases.size());
        ASSERT_LE(c.x + c.width, level.atlases[c.atlas].width);
        ASSERT_LE(c.y + c.height, level.atlases[c.atlas].height);
        if (!c.authored) {
            ASSERT_GE(c.padding, 2u);
        }
        for (size_t b = a + 1; b < level.charts.size(); ++b) {
            const Chart& d = level.charts[b];
            if (d.atlas != c.atlas) continue;
            const bool apart = c.x + c.width <= d.x || d.x + d.width <= c.x ||
                               c.y + c.height <= d.y || d.y + d.height <= c.y;
            ASSERT_TRUE(apart) << "charts " << a << " and " << b << " overlap";
        }
    }
    // Every triangle's texels stay inside its chart, padding kept.
    for (const Surface& s : level.surfaces) {
        const Chart& c = level.charts[s.chart];
        if (c.authored) continue;
        const Atlas& atlas = level.atlases[c.atlas];
        for (uint32_t i = s.firstIndex; i < s.firstIndex + s.indexCount; ++i) {
            const glm::vec2 uv = level.vertices[level.indices[i]].uv1;
            const double x = double(uv.x) * atlas.width, y = double(uv.y) * atlas.height;
            ASSERT_GE(x, c.x + c.padding - 1e-3);
            ASSERT_LE(x, c.x + c.width - c.padding + 1e-3);
            ASSERT_GE(y, c.y + c.padding - 1e-3);
            ASSERT_LE(y, c.y + c.height - c.padding + 1e-3);
        }
    }
}

TEST(Charts, NeverOverlapAndAlwaysKeepPadding) {
    GeneratedLevelOptions options = optionsForTriangles(6000);
    options.buildings = 30;
    const auto folder = freshFolder("charts");
    CompileOptions compile;
    compile.charts.atlasSize = 256;  // small atlases: several pages, many shelves
    const CompileResult result =
        compileFile(writeGeneratedLevel(folder, "charts", options), compile);
    EXPECT_GT(result.stats.atlases, 1u);
    EXPECT_GT(result.stats.fillRatio, 0.05);
    EXPECT_LE(result.stats.fillRatio, 1.0);
    expectNoOverlapAndPadding(result.level);
}

TEST(Charts, ChartsFollowDensity) {
    GltfBuilder gltf;
    gltf.addNode({{"name", "floor"}, {"mesh", gltf.addMesh(gridMesh("floor", 4, 10.0, 0.0))}});
    CompileOptions compile;
    compile.charts.texelsPerMetre = 8.0;
    const CompileResult result =
        compileFile(gltf.write(freshFolder("density"), "density"), compile);
    ASSERT_EQ(result.level.charts.size(), 1u) << "a flat connected floor is one chart";
    const Chart& c = result.level.charts[0];
    EXPECT_EQ(c.width, 80u + 2 * c.padding);
    EXPECT_FLOAT_EQ(c.texelsPerMetre, 8.0f);
    expectNoOverlapAndPadding(result.level);
}

TEST(Charts, HugeTriangleGetsALowerDensityNotAnOverflow) {
    GltfBuilder gltf;
    gltf.addNode({{"name", "plain"}, {"mesh", gltf.addMesh(gridMesh("plain", 1, 1e4, 0.0))}});
    const CompileResult result = compileFile(gltf.write(freshFolder("huge"), "huge"));
    for (const Chart& c : result.level.charts) EXPECT_LT(c.texelsPerMetre, 16.0f);
    expectNoOverlapAndPadding(result.level);
}

TEST(Charts, Texcoord1IsUsedWhenPresent) {
    GltfBuilder gltf;
    MeshData mesh = gridMesh("floor", 2, 4.0, 0.0);
    for (const glm::vec2& uv : mesh.uv0) mesh.uv1.push_back(uv * 0.5f + glm::vec2(0.25f));
    gltf.addNode({{"name", "floor"}, {"mesh", gltf.addMesh(mesh)}});
    const CompileResult result = compileFile(gltf.write(freshFolder("uv1"), "uv1"));
    ASSERT_EQ(result.level.charts.size(), 1u);
    EXPECT_TRUE(result.level.charts[0].authored);
    for (const Vertex& v : result.level.vertices) {
        EXPECT_GE(v.uv1.x, 0.25f - 1e-6f);
        EXPECT_LE(v.uv1.x, 0.75f + 1e-6f);
    }
}

}  // namespace
}  // namespace onelight::test
