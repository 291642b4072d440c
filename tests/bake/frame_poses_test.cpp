// The reference's --poses (bake/reference/frame_poses.hpp): a frame capture's dynamic objects
// are read with every field checked, and each posed entity's meshes land in world space where
// the frame drew them, normals and tangents turned with them; the reference draws the items as
// the frame does, without shadows.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "bake/materials/scene_materials.hpp"
#include "bake/reference/frame_poses.hpp"
#include "bake/reference/path_tracer.hpp"
#include "bake/reference/seen_only.hpp"
#include "tests/bake/bake_scenes.hpp"
#include "world/compile/static_split.hpp"
#include "world/error.hpp"

namespace onelight::bake {
namespace {

std::string writeFile(const std::string& name, const std::string& text) {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / "onelight-frame-poses-test";
    std::filesystem::create_directories(folder);
    const std::string path = (folder / name).string();
    std::ofstream(path) << text;
    return path;
}

// What readFramePoses throws for `text`, or "" when it reads.
std::string errorOf(const std::string& text) {
    const std::string path = writeFile("capture.json", text);
    try {
        (void)readFramePoses(path);
    } catch (const world::Error& e) {
        return e.what();
    }
    return "";
}

const char* kIdentity = "[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]";

// One entity "item" with one triangle in its own space: normal +z, tangent +x.
world::SplitLevel oneItem() {
    world::SplitLevel split;
    world::Vertex v;
    v.normal = {0.0f, 0.0f, 1.0f};
    v.tangent = {1.0f, 0.0f, 0.0f, 1.0f};
    for (glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)}) {
        v.position = p;
        split.dynamicVertices.push_back(v);
    }
    split.dynamicIndices = {0, 1, 2};
    world::DynamicMesh mesh;
    mesh.name = "item/mesh";
    mesh.material = 3;
    mesh.vertexCount = 3;
    mesh.indexCount = 3;
    split.dynamicMeshes.push_back(mesh);
    world::Entity entity;
    entity.name = "item";
    entity.flags = world::kEntityDynamic | world::kEntityItem;
    entity.dynamicMeshCount = 1;
    split.entities.push_back(entity);
    return split;
}

TEST(FramePoses, ACapturesObjectsAreReadWithTheirMatrices) {
    const std::string path = writeFile(
        "good.json",
        R"({"level": "x", "dynamic_objects": [{"entity": 0, "name": "item", "world_from_object":
            [1,0,0,0, 0,1,0,0, 0,0,1,0, 5,6,7,1]}]})");
    const std::vector<FramePose> poses = readFramePoses(path);
    ASSERT_EQ(poses.size(), 1u);
    EXPECT_EQ(poses[0].entity, 0u);
    EXPECT_EQ(poses[0].name, "item");
    // Column-major, as the capture writes glm's columns: the translation is column 3.
    EXPECT_EQ(poses[0].worldFromObject[3], glm::vec4(5, 6, 7, 1));
}

TEST(FramePoses, EachMalformedEntryIsNamed) {
    const std::string notCapture = "not a frame capture's JSON";
    for (const char* text : {"", "[]", "{\"dynamic_objects\": 3}", "{\"level\": \"x\"}", "{"})
        EXPECT_NE(errorOf(text).find(notCapture), std::string::npos) << text;
    const std::string shape = "dynamic_objects[1]: expected {\"entity\": index";
    for (const std::string& entry :
         {std::string("7"),
          std::string(R"({"entity": -1, "name": "a", "world_from_object": )") + kIdentity + "}",
          std::string(R"({"entity": 0, "world_from_object": )") + kIdentity + "}",
          std::string(R"({"entity": 0, "name": "a", "world_from_object": [1,2,3]})")}) {
        const std::string good =
            std::string(R"({"entity": 0, "name": "a", "world_from_object": )") + kIdentity + "}";
        const std::string message = errorOf("{\"dynamic_objects\": [" + good + ", " + entry + "]}");
        EXPECT_NE(message.find("capture.json: " + shape), std::string::npos)
            << entry << ": " << message;
    }
    EXPECT_NE(errorOf(R"({"dynamic_objects": [{"entity": 0, "name": "a", "world_from_object":
                          [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,"x",1]}]})")
                  .find("dynamic_objects[0]: world_from_object[14] is not a finite number"),
              std::string::npos);
    EXPECT_NE(
        errorOf(
            R"({"dynamic_objects": [{"entity": 5000000000, "name": "a", "world_from_object": )" +
            std::string(kIdentity) + "}]}")
            .find("entity 5000000000 is out of range"),
        std::string::npos);
    EXPECT_EQ(errorOf(R"({"dynamic_objects": []})"), "");
}

// What appendPosedDynamicMeshes throws for `pose` of `split`, or "" when it places it.
std::string placementErrorOf(const world::SplitLevel& split, const FramePose& pose,
                             world::StaticGeometry& geometry) {
    try {
        appendPosedDynamicMeshes(split, {pose}, "f.json", geometry);
    } catch (const world::Error& e) {
        return e.what();
    }
    return "";
}

TEST(FramePoses, AnEntityOfAnotherLevelIsRefused) {
    const world::SplitLevel split = oneItem();
    world::StaticGeometry geometry;
    FramePose pose;
    pose.entity = 1;
    pose.name = "item";
    EXPECT_NE(placementErrorOf(split, pose, geometry)
                  .find("f.json: dynamic_objects[0]: entity 1 is not in the level"),
              std::string::npos);
    pose.entity = 0;
    pose.name = "door";
    EXPECT_NE(
        placementErrorOf(split, pose, geometry).find("entity 0 is 'item' in the level, not 'door'"),
        std::string::npos);
    EXPECT_TRUE(geometry.triangles.empty());
}

TEST(FramePoses, AnEntitysMeshesLandWhereTheFrameDrewThem) {
    const world::SplitLevel split = oneItem();
    world::StaticGeometry geometry;
    geometry.vertices.resize(2);  // a level's own vertices come first
    // A quarter turn about +y, then 10 m along x: object +z becomes world +x, +x becomes -z.
    FramePose pose;
    pose.entity = 0;
    pose.name = "item";
    pose.worldFromObject = glm::mat4(glm::vec4(0, 0, -1, 0), glm::vec4(0, 1, 0, 0),
                                     glm::vec4(1, 0, 0, 0), glm::vec4(10, 0, 0, 1));
    appendPosedDynamicMeshes(split, {pose}, "f.json", geometry);
    ASSERT_EQ(geometry.vertices.size(), 5u);
    ASSERT_EQ(geometry.triangles.size(), 1u);
    const world::StaticTriangle& t = geometry.triangles[0];
    EXPECT_EQ(t.v, (std::array<uint32_t, 3>{2, 3, 4}));
    EXPECT_EQ(t.material, 3u);
    auto near = [](glm::dvec3 a, glm::dvec3 b) { return glm::length(a - b) < 1e-6; };
    EXPECT_TRUE(near(geometry.vertices[2].position, {10, 0, 0}));
    EXPECT_TRUE(near(geometry.vertices[3].position, {10, 0, -1}));
    EXPECT_TRUE(near(geometry.vertices[4].position, {10, 1, 0}));
    EXPECT_TRUE(near(glm::dvec3(geometry.vertices[2].normal), {1, 0, 0}));
    EXPECT_TRUE(near(glm::dvec3(glm::vec3(geometry.vertices[2].tangent)), {0, 0, -1}));
    EXPECT_EQ(geometry.vertices[2].tangent.w, 1.0f);

    // A mirror carries the normal by the cofactor matrix and flips the bitangent's sign ...
    world::StaticGeometry mirrored;
    pose.worldFromObject = glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0),
                                     glm::vec4(0, 0, -2, 0), glm::vec4(0, 0, 0, 1));
    appendPosedDynamicMeshes(split, {pose}, "f.json", mirrored);
    EXPECT_TRUE(near(glm::dvec3(mirrored.vertices[0].normal), {0, 0, -1}));
    EXPECT_EQ(mirrored.vertices[0].tangent.w, -1.0f);
    // ... and the winding turns with it, so that the front by winding is the normal's side.
    ASSERT_EQ(mirrored.triangles.size(), 1u);
    EXPECT_EQ(mirrored.triangles[0].v, (std::array<uint32_t, 3>{0, 2, 1}));
}

// The scenes of the two tests below: a 6 x 6 m floor (albedo 0.5) under a 1000 lux sun at 45
// degrees, travelling along (1, -1, 0), seen from 3 m straight above (fov 1.2), 64 x 64 pixels.
constexpr uint32_t kPixels = 64;
const float kOpenFloor = 0.5f / 3.14159265f * 1000.0f * std::sqrt(0.5f);  // its lit radiance

world::SourceLevel sunlitFloor() {
    world::SourceLevel level;
    const uint32_t floor = test::addLambertMaterial(level, 0.5f);
    test::addQuad(level, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, {-3, 0, -3}, floor, "floor");
    level.lights.push_back(test::sunLight({1.0f, -1.0f, 0.0f}, 1000.0f));
    world::Camera camera;
    camera.name = "down";
    camera.position = {0.0f, 3.0f, 0.0f};
    camera.rotation = glm::angleAxis(-0.5f * 3.14159265f, glm::vec3(1.0f, 0.0f, 0.0f));
    camera.yfov = 1.2f;
    level.cameras.push_back(camera);
    return level;
}

// The green channel of the pixel that sees floor point (x, 0, z), or a surface h metres
// under the camera over it: the camera looks down -y, its up is world -z, and a point h below it
// lies h tan(fov / 2) off centre at the image's edge.
float floorPixel(const ReferenceImage& image, float x, float z, float h) {
    const float extent = h * std::tan(0.5f * 1.2f);
    const uint32_t px = uint32_t((x / extent + 1.0f) * 0.5f * float(kPixels));
    const uint32_t py = uint32_t((1.0f + z / extent) * 0.5f * float(kPixels));
    return image.rgb[(size_t(py) * kPixels + px) * 3 + 1];
}

// The frame draws items without shadows (runtime/render/scene.cpp, as Quake 3 does), and the
// reference with --poses draws them so (the default; --item-shadows traces them solid): a 1 m
// triangle 1 m over a floor under a sun at 45 degrees, seen from 3 m above. Camera rays see it
// (albedo 0.8 in the sun: 0.8 / pi x 1000 cos 45 = 180 cd/m^2), the floor where its shadow
// would fall keeps the open floor's radiance (0.5 / pi x 707 = 112.5) as if it were not there,
// and the solid triangle's shadow takes the sun off that floor (the sky is black: no light).
TEST(FramePoses, ItemsAreSeenByCameraRaysAloneUnlessTheyCastShadows) {
    world::SourceLevel level = sunlitFloor();
    const uint32_t itemMaterial = test::addLambertMaterial(level, 0.8f);
    const world::Camera& camera = level.cameras[0];
    world::SplitLevel split = world::splitStaticDynamic(level);
    const world::SplitLevel item = oneItem();
    split.dynamicVertices = item.dynamicVertices;
    split.dynamicIndices = item.dynamicIndices;
    split.dynamicMeshes = item.dynamicMeshes;
    split.dynamicMeshes[0].material = itemMaterial;
    split.entities = item.entities;
    // Object +z (its normal) up, 1 m over the floor: world x in [0, 1], z in [-1, 0].
    FramePose pose;
    pose.name = "item";
    pose.worldFromObject = glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 0, -1, 0),
                                     glm::vec4(0, 1, 0, 0), glm::vec4(0, 1, 0, 1));

    const EmbreeDevice device;
    const SceneMaterials materials = loadSceneMaterials(level);
    const BakeScene open(device, split.staticGeometry, materials);
    const BakeLights lights = makeLevelLights(open, level, {}, std::nullopt);
    world::StaticGeometry solidGeometry = split.staticGeometry, seenGeometry = split.staticGeometry,
                          items;
    appendPosedDynamicMeshes(split, {pose}, "f.json", solidGeometry);
    appendPosedDynamicMeshes(split, {pose}, "f.json", seenGeometry, &items);
    EXPECT_EQ(seenGeometry.triangles.size(), split.staticGeometry.triangles.size());
    ASSERT_EQ(items.triangles.size(), 1u);
    const BakeScene solid(device, solidGeometry, materials);
    const BakeScene seen(device, items, materials);

    RayCounts rays;
    const auto render = [&](const BakeScene& scene, const BakeScene* seenOnly) {
        return renderReference(scene, lights, camera, kPixels, kPixels, 16, {}, nullptr, rays, 0,
                               seenOnly);
    };
    const ReferenceImage withoutIt = render(open, nullptr), shadowless = render(open, &seen),
                         shadowing = render(solid, nullptr);
    const auto at = floorPixel;
    const float kItem = 0.8f / 3.14159265f * 1000.0f * std::sqrt(0.5f);
    // The triangle's corners are (0, 1, 0), (1, 1, 0), (0, 1, -1); under the sun travelling along
    // (1, -1, 0) its shadow is it moved 1 m along +x and down: (1.7, 0, -0.15) is in it,
    // (1.7, 0, -0.6) is past its hypotenuse; and the camera sees both past the triangle.
    EXPECT_NEAR(at(withoutIt, 1.7f, -0.15f, 3.0f), kOpenFloor, 0.02f * kOpenFloor);
    EXPECT_NEAR(at(shadowless, 1.7f, -0.15f, 3.0f), kOpenFloor, 0.02f * kOpenFloor);
    EXPECT_LT(at(shadowing, 1.7f, -0.15f, 3.0f), 0.02f * kOpenFloor);
    EXPECT_NEAR(at(shadowing, 1.7f, -0.6f, 3.0f), kOpenFloor, 0.02f * kOpenFloor);
    // Both see the item itself.
    EXPECT_NEAR(at(shadowless, 0.2f, -0.2f, 2.0f), kItem, 0.02f * kItem);
    EXPECT_NEAR(at(shadowing, 0.2f, -0.2f, 2.0f), kItem, 0.02f * kItem);
    EXPECT_NEAR(at(withoutIt, 0.2f, -0.2f, 2.0f), kOpenFloor, 0.02f * kOpenFloor);
}

// A surface that light passes (a Quake 3 translucent one, castsShadows false) is drawn by the
// frame, so camera rays see it (seen_only.hpp); the bake's scene never hits it. The same triangle
// as above, now a static surface of such a material: seen at its lit radiance, with no shadow.
TEST(FramePoses, ASurfaceLightPassesIsSeenByCameraRaysAlone) {
    world::SourceLevel level = sunlitFloor();
    const uint32_t glass = test::addLambertMaterial(level, 0.8f);
    level.materials[glass].castsShadows = false;
    test::addQuad(level, {0, 1, 0}, {1, 1, 0}, {1, 1, -1}, {0, 1, -1}, glass, "glass");
    const world::SplitLevel split = world::splitStaticDynamic(level);
    world::StaticGeometry seenGeometry;
    appendShadowlessSurfaces(split.staticGeometry, level.materials, seenGeometry);
    ASSERT_EQ(seenGeometry.triangles.size(), 2u);

    const EmbreeDevice device;
    const SceneMaterials materials = loadSceneMaterials(level);
    const BakeScene scene(device, split.staticGeometry, materials);
    const BakeScene seen(device, seenGeometry, seenOnlyMaterials(materials));
    const BakeLights lights = makeLevelLights(scene, level, {}, std::nullopt);
    RayCounts rays;
    const ReferenceImage without =
        renderReference(scene, lights, level.cameras[0], kPixels, kPixels, 16, {}, nullptr, rays);
    const ReferenceImage with = renderReference(scene, lights, level.cameras[0], kPixels, kPixels,
                                                16, {}, nullptr, rays, 0, &seen);
    const auto at = floorPixel;
    const float kGlass = 0.8f / 3.14159265f * 1000.0f * std::sqrt(0.5f);
    EXPECT_NEAR(at(with, 0.5f, -0.5f, 2.0f), kGlass, 0.02f * kGlass);
    EXPECT_NEAR(at(without, 0.5f, -0.5f, 2.0f), kOpenFloor, 0.02f * kOpenFloor);
    EXPECT_NEAR(at(with, 1.7f, -0.5f, 3.0f), kOpenFloor, 0.02f * kOpenFloor);  // light passed it
}

}  // namespace
}  // namespace onelight::bake
