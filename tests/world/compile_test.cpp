#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include "tests/world/level_generator.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/bsp/bsp_query.hpp"
#include "world/error.hpp"
#include "world/features/feature_analysis.hpp"
#include "world/package/package_reader.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::test {
namespace {

using namespace onelight::world;

void expectRoundTrip(CompiledLevel level) {
    // As `compile` writes it: images beside a package in a fresh folder are embedded.
    package::placeImagesForPackage(level, (freshFolder("round-trip") / "level.olpak").string());
    const std::vector<uint8_t> bytes = package::serializePackage(level);
    const package::PackageContents read = package::parsePackage(bytes, "round-trip");
    EXPECT_EQ(package::serializePackage(read.level), bytes);
}

TEST(Compile, EmptyScene) {
    GltfBuilder gltf;
    const CompileResult result = compileFile(gltf.write(freshFolder("empty"), "empty"));
    EXPECT_EQ(result.stats.triangles, 0u);
    EXPECT_EQ(result.level.surfaces.size(), 0u);
    EXPECT_EQ(result.level.bspLeaves.size(), 1u);
    expectRoundTrip(result.level);
}

TEST(Compile, LevelWithoutLights) {
    const CompileResult result = compileFile(writeTwoLampFloor("dark", 4, 8.0, false));
    EXPECT_GT(result.level.surfaces.size(), 0u);
    for (const Surface& s : result.level.surfaces) EXPECT_EQ(s.primaryLight, kNoIndex);
    EXPECT_EQ(result.level.features.primaryCount, 0u);
    expectRoundTrip(result.level);
}

TEST(Compile, EverySurfaceHasOnePrimaryWhenLit) {
    const CompileResult result = compileFile(writeTwoLampFloor("lit", 9, 20.0, true));
    EXPECT_EQ(result.stats.primariesUsed, 2u);
    for (const Surface& s : result.level.surfaces) {
        ASSERT_LT(s.primaryLight, result.level.lights.size());
        EXPECT_EQ(result.level.lights[s.primaryLight].role, LightRole::kPrimary);
        for (uint32_t g = s.firstGivenUp; g < s.firstGivenUp + s.givenUpCount; ++g)
            EXPECT_NE(result.level.givenUpLights[g], s.primaryLight);
    }
    expectRoundTrip(result.level);
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
    gltf.addNode({{"name", "junk"}, {"mesh", gltf.addMesh(mesh)}});
    const CompileResult result = compileFile(gltf.write(freshFolder("junk"), "junk"));
    EXPECT_EQ(result.stats.degenerateRemoved, 2u);
    EXPECT_EQ(result.stats.duplicatesRemoved, 2u);
    EXPECT_EQ(result.stats.triangles, 2u);
    expectRoundTrip(result.level);
}

TEST(Compile, CoordinatesOfOneHundredKilometres) {
    GltfBuilder gltf;
    gltf.addNode(
        {{"name", "far"}, {"mesh", gltf.addMesh(gridMesh("far", 12, 50.0, 1e5, 1e5, -1e5))}});
    const int light = gltf.addLight({{"type", "point"}, {"intensity", 1e6}});
    gltf.addNode({{"name", "lamp"},
                  {"translation", {1e5, 1e5 + 10.0, -1e5}},
                  {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
    const CompileResult result = compileFile(gltf.write(freshFolder("far"), "far"));
    EXPECT_EQ(result.stats.triangles, 288u);
    const BspView view = bspView(result.level);
    const RayHit hit =
        raycast(view, glm::dvec3(1e5 + 0.3, 1e5 + 5.0, -1e5 + 0.7), glm::dvec3(0, -1, 0), 100.0);
    ASSERT_TRUE(hit.hit);
    EXPECT_NEAR(hit.t, 5.0, 1e-2);
    expectRoundTrip(result.level);
}

TEST(Compile, FlatteningAndMirroringTransformsGiveFiniteNormals) {
    GltfBuilder gltf;
    const int box = gltf.addMesh(boxMesh("box", glm::vec3(0.0f), glm::vec3(1.0f), 1, false));
    gltf.addNode({{"name", "flat"}, {"mesh", box}, {"scale", {1.0, 1.0, 0.0}}});
    gltf.addNode({{"name", "mirror"},
                  {"mesh", box},
                  {"scale", {-1.0, 1.0, 1.0}},
                  {"translation", {5.0, 0.0, 0.0}}});
    const CompileResult result = compileFile(gltf.write(freshFolder("flatten"), "flatten"));
    for (const Vertex& v : result.level.vertices) ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
    // The mirrored box (x in [4, 5]) keeps its normals pointing outwards.
    for (const Surface& s : result.level.surfaces) {
        for (uint32_t i = s.firstIndex; i < s.firstIndex + s.indexCount; ++i) {
            const Vertex& v = result.level.vertices[result.level.indices[i]];
            if (v.position.x < 3.0f) continue;  // only the mirrored box
            const glm::vec3 centre(4.5f, 0.5f, 0.5f);
            ASSERT_GE(glm::dot(v.normal, v.position - centre), 0.0f);
        }
    }
    expectRoundTrip(result.level);
}

TEST(Compile, DynamicNodeWithZeroScaleIsAnError) {
    GltfBuilder gltf;
    const int box = gltf.addMesh(boxMesh("box", glm::vec3(0.0f), glm::vec3(1.0f), 1, false));
    gltf.addNode({{"name", "ghost"},
                  {"mesh", box},
                  {"scale", {0.0, 0.0, 0.0}},
                  {"extras", {{"onelight", {{"dynamic", true}}}}}});
    try {
        compileFile(gltf.write(freshFolder("ghost"), "ghost"));
        FAIL() << "expected a Error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("ghost"), std::string::npos) << e.what();
    }
}

// Dynamic nodes whose meshes are the same in their own space (one box placed three times, at
// different places and turns) draw from one copy of its vertices and indices; a mirrored one
// (its winding flipped) and a box of another size keep their own; each still draws its whole
// box, and the package round-trips.
TEST(Compile, IdenticalDynamicMeshesShareOneCopy) {
    GltfBuilder gltf;
    const int box = gltf.addMesh(boxMesh("box", glm::vec3(0.0f), glm::vec3(1.0f), 1, false));
    const int big = gltf.addMesh(boxMesh("big", glm::vec3(0.0f), glm::vec3(2.0f), 1, false));
    const nlohmann::json dynamic = {{"onelight", {{"dynamic", true}}}};
    gltf.addNode({{"name", "a"}, {"mesh", box}, {"extras", dynamic}});
    gltf.addNode(
        {{"name", "b"}, {"mesh", box}, {"translation", {5.0, 0.0, 0.0}}, {"extras", dynamic}});
    gltf.addNode({{"name", "c"},
                  {"mesh", box},
                  {"rotation", {0.0, 0.7071068, 0.0, 0.7071068}},
                  {"extras", dynamic}});
    gltf.addNode(
        {{"name", "mirrored"}, {"mesh", box}, {"scale", {-1.0, 1.0, 1.0}}, {"extras", dynamic}});
    gltf.addNode({{"name", "big"}, {"mesh", big}, {"extras", dynamic}});
    const CompileResult result = compileFile(gltf.write(freshFolder("shared"), "shared"));
    const CompiledLevel& level = result.level;
    ASSERT_EQ(level.dynamicMeshes.size(), 5u);
    std::map<std::string, DynamicMesh> byNode;
    for (const DynamicMesh& m : level.dynamicMeshes) byNode[m.name.substr(0, m.name.find('/'))] = m;
    ASSERT_EQ(byNode.size(), 5u);
    for (const char* name : {"b", "c"}) {
        EXPECT_EQ(byNode[name].firstVertex, byNode["a"].firstVertex) << name;
        EXPECT_EQ(byNode[name].firstIndex, byNode["a"].firstIndex) << name;
    }
    EXPECT_NE(byNode["mirrored"].firstIndex, byNode["a"].firstIndex);
    EXPECT_NE(byNode["big"].firstVertex, byNode["a"].firstVertex);
    for (const auto& [name, mesh] : byNode) EXPECT_EQ(mesh.indexCount, 36u) << name;
    EXPECT_EQ(result.stats.dynamicTriangles, 5u * 12u);
    EXPECT_EQ(result.stats.dynamicTrianglesShared, 2u * 12u);
    EXPECT_EQ(level.dynamicIndices.size(), 3u * 36u);
    expectRoundTrip(level);
}

TEST(Compile, GeneratedLevelFeatures) {
    GeneratedLevelOptions options = optionsForTriangles(3000);
    options.buildings = 10;
    const CompileResult result =
        compileFile(writeGeneratedLevel(freshFolder("features"), "features", options));
    const CompiledLevel& level = result.level;
    const Features& f = level.features;
    EXPECT_EQ(f.materialClasses, (1u << uint32_t(MaterialClass::kMetal)) |
                                     (1u << uint32_t(MaterialClass::kDielectric)));
    EXPECT_EQ(f.effectOmniCount, 1u);
    EXPECT_EQ(f.effectSpotCount, 1u);
    EXPECT_EQ(f.bakedLightCount, 1u);
    EXPECT_EQ(f.probeCount, 1u);
    EXPECT_TRUE(f.flags & kFeatureAuthoredGrid);
    EXPECT_TRUE(f.flags & kFeatureLightGrid);
    EXPECT_TRUE(f.flags & kFeatureLightmaps);
    EXPECT_EQ(f.gridMax, glm::vec3(100.0f, 40.0f, 100.0f));
    EXPECT_TRUE(level.settings.hasExposure);
    EXPECT_FLOAT_EQ(level.settings.exposureEv100, 11.0f);
    ASSERT_EQ(level.cameras.size(), 1u);
    EXPECT_EQ(level.cameras[0].name, "overview");
    size_t movers = 0, dynamic = 0;
    for (const Entity& e : level.entities) {
        movers += (e.flags & kEntityMover) != 0;
        if (e.flags & kEntityDynamic) {
            ++dynamic;
            EXPECT_EQ(e.dynamicMeshCount, 1u);
        }
    }
    EXPECT_EQ(dynamic, 8u);
    EXPECT_EQ(movers, 4u);
    EXPECT_EQ(result.stats.dynamicTriangles, 8u * 6u * 8u);
    expectRoundTrip(level);
}

// Where dynamic objects can go (an error budget's grid): a scaled, turned mover's mesh at both
// ends of its path, a still one at its place; non-dynamic entities and bad indices ignored.
TEST(Compile, DynamicObjectReachCoversEveryMoversPath) {
    CompiledLevel level;
    glm::vec3 lo, hi;
    EXPECT_FALSE(dynamicObjectReach(level, lo, hi)) << "no dynamic entity";
    for (glm::vec3 p : {glm::vec3(-1.0f, 0.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f)}) {
        Vertex v;
        v.position = p;
        level.dynamicVertices.push_back(v);
    }
    DynamicMesh mesh;
    mesh.vertexCount = 2;
    level.dynamicMeshes = {mesh};
    Entity mover;
    mover.flags = kEntityDynamic | kEntityMover;
    mover.position = glm::vec3(10.0f, 2.0f, 0.0f);
    mover.scale = glm::vec3(2.0f);
    mover.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0.0f, 0.0f, 1.0f));  // x -> y
    mover.dynamicMeshCount = 1;
    Entity still = mover;
    still.flags = kEntityDynamic;
    still.position = glm::vec3(-3.0f, 0.0f, 0.0f);
    still.rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    Entity spawn = still;
    spawn.flags = kEntitySpawn;
    spawn.position = glm::vec3(100.0f);
    Entity broken = still;
    broken.firstDynamicMesh = 7;  // past the meshes: nothing
    level.entities = {mover, still, spawn, broken};
    Mover shuttle;
    shuttle.entity = 0;
    shuttle.pos1 = mover.position;
    shuttle.pos2 = mover.position + glm::vec3(0.0f, 0.0f, -6.0f);
    shuttle.period = 1.0f;
    level.movers.movers = {shuttle};
    ASSERT_TRUE(dynamicObjectReach(level, lo, hi));
    // The mover's mesh spans y 0..4 at x 10, z 0 and z -6; the still one x -5..-1 at y 0, z 0.
    const glm::vec3 wantLo(-5.0f, 0.0f, -6.0f), wantHi(10.0f, 4.0f, 0.0f);
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(lo[a], wantLo[a], 1e-5f) << a;
        EXPECT_NEAR(hi[a], wantHi[a], 1e-5f) << a;
    }
}

TEST(CompileAssets, NormalTangentTestCompilesAndRoundTrips) {
    const std::string path = sharedAsset("NormalTangentTest/glTF/NormalTangentTest.gltf");
    if (path.empty()) GTEST_SKIP() << "shared assets absent";
    const CompileResult result = compileFile(path);
    EXPECT_GE(result.stats.triangles, 7774u);
    EXPECT_EQ(result.stats.sourceTriangles, 7774u);
    expectRoundTrip(result.level);
}

TEST(CompileAssets, TextureSettingsTestCompilesAndRoundTrips) {
    const std::string path = sharedAsset("TextureSettingsTest/glTF/TextureSettingsTest.gltf");
    if (path.empty()) GTEST_SKIP() << "shared assets absent";
    const CompileResult result = compileFile(path);
    EXPECT_EQ(result.stats.sourceTriangles, 72u);
    EXPECT_EQ(result.level.materials.size(), 10u);
    expectRoundTrip(result.level);
}

}  // namespace
}  // namespace onelight::test
