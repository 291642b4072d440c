#include <cmath>

#include <gtest/gtest.h>

#include "tests/world/level_generator.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/bsp/bsp_query.hpp"
#include "world/error.hpp"
#include "world/package/package_reader.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::test {
namespace {

using namespace onelight::world;

void expect_round_trip(const CompiledLevel& level) {
    const std::vector<uint8_t> bytes = package::serialize_package(level);
    const package::PackageContents read = package::parse_package(bytes, "round-trip");
    EXPECT_EQ(package::serialize_package(read.level), bytes);
}

TEST(Compile, EmptyScene) {
    GltfBuilder gltf;
    const CompileResult result = compile_file(gltf.write(fresh_folder("empty"), "empty"));
    EXPECT_EQ(result.stats.triangles, 0u);
    EXPECT_EQ(result.level.surfaces.size(), 0u);
    EXPECT_EQ(result.level.bsp_leaves.size(), 1u);
    expect_round_trip(result.level);
}

TEST(Compile, LevelWithoutLights) {
    const CompileResult result = compile_file(write_two_lamp_floor("dark", 4, 8.0, false));
    EXPECT_GT(result.level.surfaces.size(), 0u);
    for (const Surface& s : result.level.surfaces) EXPECT_EQ(s.primary_light, kNoIndex);
    EXPECT_EQ(result.level.features.primary_count, 0u);
    expect_round_trip(result.level);
}

TEST(Compile, EverySurfaceHasOnePrimaryWhenLit) {
    const CompileResult result = compile_file(write_two_lamp_floor("lit", 9, 20.0, true));
    EXPECT_EQ(result.stats.primaries_used, 2u);
    for (const Surface& s : result.level.surfaces) {
        ASSERT_LT(s.primary_light, result.level.lights.size());
        EXPECT_EQ(result.level.lights[s.primary_light].role, LightRole::primary);
        for (uint32_t g = s.first_given_up; g < s.first_given_up + s.given_up_count; ++g)
            EXPECT_NE(result.level.given_up_lights[g], s.primary_light);
    }
    expect_round_trip(result.level);
}

TEST(Compile, DegenerateZeroAreaAndDuplicateTrianglesAreDropped) {
    GltfBuilder gltf;
    MeshData mesh;
    mesh.name = "junk";
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {3, 0, 0}};
    mesh.indices = {0, 1, 2,   // fine
                    0, 1, 2,   // duplicate
                    1, 2, 0,   // the same triangle rotated: duplicate
                    0, 0, 2,   // repeated index
                    0, 3, 4,   // collinear: zero area
                    0, 2, 1};  // the back face: kept
    gltf.add_node({{"name", "junk"}, {"mesh", gltf.add_mesh(mesh)}});
    const CompileResult result = compile_file(gltf.write(fresh_folder("junk"), "junk"));
    EXPECT_EQ(result.stats.degenerate_removed, 2u);
    EXPECT_EQ(result.stats.duplicates_removed, 2u);
    EXPECT_EQ(result.stats.triangles, 2u);
    expect_round_trip(result.level);
}

TEST(Compile, CoordinatesOfOneHundredKilometres) {
    GltfBuilder gltf;
    gltf.add_node(
        {{"name", "far"}, {"mesh", gltf.add_mesh(grid_mesh("far", 12, 50.0, 1e5, 1e5, -1e5))}});
    const int light = gltf.add_light({{"type", "point"}, {"intensity", 1e6}});
    gltf.add_node({{"name", "lamp"},
                   {"translation", {1e5, 1e5 + 10.0, -1e5}},
                   {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
    const CompileResult result = compile_file(gltf.write(fresh_folder("far"), "far"));
    EXPECT_EQ(result.stats.triangles, 288u);
    const BspView view = bsp_view(result.level);
    const RayHit hit =
        raycast(view, glm::dvec3(1e5 + 0.3, 1e5 + 5.0, -1e5 + 0.7), glm::dvec3(0, -1, 0), 100.0);
    ASSERT_TRUE(hit.hit);
    EXPECT_NEAR(hit.t, 5.0, 1e-2);
    expect_round_trip(result.level);
}

TEST(Compile, FlatteningAndMirroringTransformsGiveFiniteNormals) {
    GltfBuilder gltf;
    const int box = gltf.add_mesh(box_mesh("box", glm::vec3(0.0f), glm::vec3(1.0f), 1, false));
    gltf.add_node({{"name", "flat"}, {"mesh", box}, {"scale", {1.0, 1.0, 0.0}}});
    gltf.add_node({{"name", "mirror"},
                   {"mesh", box},
                   {"scale", {-1.0, 1.0, 1.0}},
                   {"translation", {5.0, 0.0, 0.0}}});
    const CompileResult result = compile_file(gltf.write(fresh_folder("flatten"), "flatten"));
    for (const Vertex& v : result.level.vertices) ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
    // The mirrored box (x in [4, 5]) keeps its normals pointing outwards.
    for (const Surface& s : result.level.surfaces) {
        for (uint32_t i = s.first_index; i < s.first_index + s.index_count; ++i) {
            const Vertex& v = result.level.vertices[result.level.indices[i]];
            if (v.position.x < 3.0f) continue;  // only the mirrored box
            const glm::vec3 centre(4.5f, 0.5f, 0.5f);
            ASSERT_GE(glm::dot(v.normal, v.position - centre), 0.0f);
        }
    }
    expect_round_trip(result.level);
}

TEST(Compile, DynamicNodeWithZeroScaleIsAnError) {
    GltfBuilder gltf;
    const int box = gltf.add_mesh(box_mesh("box", glm::vec3(0.0f), glm::vec3(1.0f), 1, false));
    gltf.add_node({{"name", "ghost"},
                   {"mesh", box},
                   {"scale", {0.0, 0.0, 0.0}},
                   {"extras", {{"onelight", {{"dynamic", true}}}}}});
    try {
        compile_file(gltf.write(fresh_folder("ghost"), "ghost"));
        FAIL() << "expected a Error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("ghost"), std::string::npos) << e.what();
    }
}

TEST(Compile, GeneratedLevelFeatures) {
    GeneratedLevelOptions options = options_for_triangles(3000);
    options.buildings = 10;
    const CompileResult result =
        compile_file(write_generated_level(fresh_folder("features"), "features", options));
    const CompiledLevel& level = result.level;
    const Features& f = level.features;
    EXPECT_EQ(f.material_classes,
              (1u << uint32_t(MaterialClass::metal)) | (1u << uint32_t(MaterialClass::dielectric)));
    EXPECT_EQ(f.effect_omni_count, 1u);
    EXPECT_EQ(f.effect_spot_count, 1u);
    EXPECT_EQ(f.baked_light_count, 1u);
    EXPECT_EQ(f.probe_count, 1u);
    EXPECT_TRUE(f.flags & feature_authored_grid);
    EXPECT_TRUE(f.flags & feature_light_grid);
    EXPECT_TRUE(f.flags & feature_lightmaps);
    EXPECT_EQ(f.grid_max, glm::vec3(100.0f, 40.0f, 100.0f));
    EXPECT_TRUE(level.settings.has_exposure);
    EXPECT_FLOAT_EQ(level.settings.exposure_ev100, 11.0f);
    ASSERT_EQ(level.cameras.size(), 1u);
    EXPECT_EQ(level.cameras[0].name, "overview");
    size_t movers = 0, dynamic = 0;
    for (const Entity& e : level.entities) {
        movers += (e.flags & entity_mover) != 0;
        if (e.flags & entity_dynamic) {
            ++dynamic;
            EXPECT_EQ(e.dynamic_mesh_count, 1u);
        }
    }
    EXPECT_EQ(dynamic, 8u);
    EXPECT_EQ(movers, 4u);
    EXPECT_EQ(result.stats.dynamic_triangles, 8u * 6u * 8u);
    expect_round_trip(level);
}

TEST(CompileAssets, NormalTangentTestCompilesAndRoundTrips) {
    const std::string path = shared_asset("NormalTangentTest/glTF/NormalTangentTest.gltf");
    if (path.empty()) GTEST_SKIP() << "shared assets absent";
    const CompileResult result = compile_file(path);
    EXPECT_GE(result.stats.triangles, 7774u);
    EXPECT_EQ(result.stats.source_triangles, 7774u);
    expect_round_trip(result.level);
}

TEST(CompileAssets, TextureSettingsTestCompilesAndRoundTrips) {
    const std::string path = shared_asset("TextureSettingsTest/glTF/TextureSettingsTest.gltf");
    if (path.empty()) GTEST_SKIP() << "shared assets absent";
    const CompileResult result = compile_file(path);
    EXPECT_EQ(result.stats.source_triangles, 72u);
    EXPECT_EQ(result.level.materials.size(), 10u);
    expect_round_trip(result.level);
}

}  // namespace
}  // namespace onelight::test
