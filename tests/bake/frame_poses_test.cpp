// The reference's --poses (bake/reference/frame_poses.hpp): a frame capture's dynamic objects
// are read with every field checked, and each posed entity's meshes land in world space where
// the frame drew them, normals and tangents turned with them.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "bake/reference/frame_poses.hpp"
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

}  // namespace
}  // namespace onelight::bake
