#include <gtest/gtest.h>

#include "tests/world/level_generator.hpp"
#include "tests/world/world_test_support.hpp"

namespace onelight::test {
namespace {

using namespace onelight::world;

void expect_no_overlap_and_padding(const CompiledLevel& level) {
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
        for (uint32_t i = s.first_index; i < s.first_index + s.index_count; ++i) {
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
    GeneratedLevelOptions options = options_for_triangles(6000);
    options.buildings = 30;
    const auto folder = fresh_folder("charts");
    CompileOptions compile;
    compile.charts.atlas_size = 256;  // small atlases: several pages, many shelves
    const CompileResult result =
        compile_file(write_generated_level(folder, "charts", options), compile);
    EXPECT_GT(result.stats.atlases, 1u);
    EXPECT_GT(result.stats.fill_ratio, 0.05);
    EXPECT_LE(result.stats.fill_ratio, 1.0);
    expect_no_overlap_and_padding(result.level);
}

TEST(Charts, ChartsFollowDensity) {
    GltfBuilder gltf;
    gltf.add_node({{"name", "floor"}, {"mesh", gltf.add_mesh(grid_mesh("floor", 4, 10.0, 0.0))}});
    CompileOptions compile;
    compile.charts.texels_per_metre = 8.0;
    const CompileResult result =
        compile_file(gltf.write(fresh_folder("density"), "density"), compile);
    ASSERT_EQ(result.level.charts.size(), 1u) << "a flat connected floor is one chart";
    const Chart& c = result.level.charts[0];
    EXPECT_EQ(c.width, 80u + 2 * c.padding);
    EXPECT_FLOAT_EQ(c.texels_per_metre, 8.0f);
    expect_no_overlap_and_padding(result.level);
}

TEST(Charts, HugeTriangleGetsALowerDensityNotAnOverflow) {
    GltfBuilder gltf;
    gltf.add_node({{"name", "plain"}, {"mesh", gltf.add_mesh(grid_mesh("plain", 1, 1e4, 0.0))}});
    const CompileResult result = compile_file(gltf.write(fresh_folder("huge"), "huge"));
    for (const Chart& c : result.level.charts) EXPECT_LT(c.texels_per_metre, 16.0f);
    expect_no_overlap_and_padding(result.level);
}

TEST(Charts, Texcoord1IsUsedWhenPresent) {
    GltfBuilder gltf;
    MeshData mesh = grid_mesh("floor", 2, 4.0, 0.0);
    for (const glm::vec2& uv : mesh.uv0) mesh.uv1.push_back(uv * 0.5f + glm::vec2(0.25f));
    gltf.add_node({{"name", "floor"}, {"mesh", gltf.add_mesh(mesh)}});
    const CompileResult result = compile_file(gltf.write(fresh_folder("uv1"), "uv1"));
    ASSERT_EQ(result.level.charts.size(), 1u);
    EXPECT_TRUE(result.level.charts[0].authored);
    for (const Vertex& v : result.level.vertices) {
        EXPECT_GE(v.uv1.x, 0.25f - 1e-6f);
        EXPECT_LE(v.uv1.x, 0.75f + 1e-6f);
    }
}

}  // namespace
}  // namespace onelight::test
