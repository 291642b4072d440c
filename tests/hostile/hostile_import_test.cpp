// Hostile input to the import: files that are not regular files, JSON that tinygltf would
// overflow on or silently default, glb headers that lie, and coordinates past the documented
// range. Every case must end in one world::Error line naming the file and the place, quickly.
#include <sys/stat.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "hostile_level.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/compile/compile_level.hpp"
#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/import/gltf_import.hpp"
#include "world/import/level_limits.hpp"

namespace onelight::test {
namespace {

using nlohmann::json;

// The message of the world::Error that importing `path` throws ("" when it imports).
std::string importError(const std::string& path) {
    try {
        (void)world::importGltf(path);
    } catch (const world::Error& e) {
        return e.what();
    }
    return "";
}

void expectImportError(const std::string& path, std::initializer_list<const char*> fragments) {
    const auto start = std::chrono::steady_clock::now();
    const std::string message = importError(path);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_NE(message, "") << path << " imported; expected an error";
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_LE(message.size(), 400u) << message;
    for (const char* f : fragments) EXPECT_NE(message.find(f), std::string::npos) << message;
    EXPECT_LT(seconds, 10.0) << "no hang";
}

// Writes the triangle level with one edit and expects its import to fail naming `fragments`.
void expectEditRejected(const std::string& name, const std::function<void(json&)>& edit,
                        std::initializer_list<const char*> fragments) {
    SCOPED_TRACE(name);
    const std::string gltf = writeTriangleLevel(hostileFolder(name), edit);
    expectImportError(gltf, fragments);
    // Every message names the file.
    EXPECT_NE(importError(gltf).find("level.gltf"), std::string::npos);
}

TEST(HostileImport, TheUneditedLevelImports) {
    const world::SourceLevel level = world::importGltf(writeTriangleLevel(hostileFolder("plain")));
    ASSERT_EQ(level.instances.size(), 1u);
    EXPECT_EQ(level.lights.size(), 1u);
    EXPECT_EQ(level.cameras.size(), 1u);
    // What the import read, so that no command may write over it.
    ASSERT_EQ(level.inputFiles.size(), 2u);
    EXPECT_NE(level.inputFiles[1].find("level.bin"), std::string::npos);
}

TEST(HostileImport, OnlyRegularFilesAreRead) {
    const std::filesystem::path folder = hostileFolder("files");
    const std::string fifo = (folder / "fifo.gltf").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    expectImportError(fifo, {"fifo.gltf", "is a FIFO"});
    expectImportError("/dev/zero", {"/dev/zero", "character device"});
    std::filesystem::create_directories(folder / "dir.gltf");
    expectImportError((folder / "dir.gltf").string(), {"dir.gltf", "is a directory"});
    expectImportError((folder / "missing.gltf").string(), {"missing.gltf", "cannot open"});
    // A buffer that is a FIFO: no wait for a writer.
    const std::string gltf = writeTriangleLevel(folder);
    std::filesystem::remove(folder / "level.bin");
    ASSERT_EQ(::mkfifo((folder / "level.bin").c_str(), 0600), 0);
    expectImportError(gltf, {"level.gltf", "level.bin", "FIFO"});
}

TEST(HostileImport, ReadRegularFileBoundsTheSize) {
    const std::filesystem::path folder = hostileFolder("size");
    std::ofstream(folder / "ten") << "0123456789";
    EXPECT_EQ(world::readRegularFile((folder / "ten").string(), "ten bytes", 10).size(), 10u);
    try {
        (void)world::readRegularFile((folder / "ten").string(), "a small file", 9);
        FAIL() << "read past its limit";
    } catch (const world::Error& e) {
        EXPECT_NE(std::string(e.what()).find("10 bytes; expected a small file of at most 9"),
                  std::string::npos)
            << e.what();
    }
}

TEST(HostileImport, DeepNestingIsRefusedBeforeAnyParser) {
    const std::filesystem::path folder = hostileFolder("deep");
    const std::string path = (folder / "deep.gltf").string();
    // 200k levels: tinygltf's recursive parser overflowed the stack on this.
    std::ofstream(path) << "{\"asset\": {\"version\": \"2.0\"}, \"extras\": {\"x\": "
                        << std::string(200000, '[') << std::string(200000, ']') << "}}";
    expectImportError(path, {"deep.gltf", "nested deeper than 64"});
    // Brackets inside strings are not nesting.
    const world::SourceLevel level =
        world::importGltf(writeTriangleLevel(hostileFolder("brackets"), [](json& j) {
            j["nodes"][0]["name"] = std::string(1000, '[');
        }));
    EXPECT_EQ(level.instances.size(), 1u);
}

// Found by fuzz_gltf: a number past double's range made the JSON parser throw out_of_range,
// which nothing caught.
TEST(HostileImport, ANumberPastDoublesRangeIsAnError) {
    const std::filesystem::path folder = hostileFolder("huge-number");
    std::ofstream(folder / "huge.gltf") << R"({"asset": {"version": "2.0"}, "scene": 1e400})";
    expectImportError((folder / "huge.gltf").string(), {"huge.gltf", "not JSON"});
}

TEST(HostileImport, GlbHeadersThatLieAreRejected) {
    const std::filesystem::path folder = hostileFolder("glb");
    auto writeGlb = [&](const std::string& name, uint32_t version, uint32_t length,
                        uint32_t chunkLength, uint32_t chunkType, const std::string& body) {
        const std::string path = (folder / name).string();
        std::ofstream out(path, std::ios::binary);
        const uint32_t words[5] = {0x46546C67, version, length, chunkLength, chunkType};
        out.write(reinterpret_cast<const char*>(words), sizeof words);
        out << body;
        return path;
    };
    const std::string body = R"({"asset":{"version":"2.0"}})";
    const uint32_t size = uint32_t(20 + body.size());
    expectImportError(writeGlb("v1.glb", 1, size, uint32_t(body.size()), 0x4E4F534A, body),
                      {"v1.glb", "glb version 1; expected version 2"});
    expectImportError(writeGlb("long.glb", 2, 1u << 30, uint32_t(body.size()), 0x4E4F534A, body),
                      {"long.glb", "header length"});
    expectImportError(writeGlb("chunk.glb", 2, size, 1u << 30, 0x4E4F534A, body),
                      {"chunk.glb", "JSON chunk"});
    expectImportError(writeGlb("bin.glb", 2, size, uint32_t(body.size()), 0x004E4942, body),
                      {"bin.glb", "JSON chunk"});
}

TEST(HostileImport, WrongTypesLengthsAndRangesAreErrorsNotDefaults) {
    expectEditRejected(
        "matrix15",
        [](json& j) {
            j["nodes"][0]["matrix"] = json::array({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0});
        },
        {"nodes[0].matrix", "15 elements; expected 16 numbers"});
    expectEditRejected("colour2",
                       [](json& j) {
                           j["extensions"]["KHR_lights_punctual"]["lights"][0]["color"] = {1, 1};
                       },
                       {"lights[0].color", "2 elements; expected 3"});
    expectEditRejected(
        "intensity-string",
        [](json& j) { j["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = "3"; },
        {"lights[0].intensity", "expected a number"});
    expectEditRejected(
        "intensity-negative",
        [](json& j) { j["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = -1; },
        {"lights[0].intensity", "expected a number in [0"});
    expectEditRejected("offset-negative", [](json& j) { j["accessors"][0]["byteOffset"] = -4; },
                       {"accessors[0].byteOffset", "is -4"});
    expectEditRejected("offset-string", [](json& j) { j["bufferViews"][0]["byteOffset"] = "0"; },
                       {"bufferViews[0].byteOffset", "expected an integer"});
    expectEditRejected("translation2",
                       [](json& j) {
                           j["nodes"][2]["translation"] = {0, 1};
                       },
                       {"nodes[2].translation", "2 elements; expected 3"});
    expectEditRejected("required-extension",
                       [](json& j) { j["extensionsRequired"] = {"KHR_draco_mesh_compression"}; },
                       {"extensionsRequired[0]", "KHR_draco_mesh_compression", "not supported"});
    expectEditRejected("extras-null", [](json& j) { j["nodes"][0]["extras"] = nullptr; },
                       {"nodes[0].extras", "is null; expected an object"});
    expectEditRejected("extras-empty",
                       [](json& j) {
                           j["nodes"][0]["extras"] = {{"onelight", json::object()}};
                       },
                       {"nodes[0].extras.onelight", "is empty"});
    expectEditRejected("extras-typo",
                       [](json& j) {
                           j["nodes"][0]["extras"] = {{"onelight", {{"texels_per_meter", 4}}}};
                       },
                       {"nodes[0].extras.onelight.texels_per_meter", "is not a setting"});
    expectEditRejected("zfar", [](json& j) { j["cameras"][0]["perspective"]["zfar"] = 0.05; },
                       {"cameras[0].perspective.zfar", "expected zfar > znear"});
    expectEditRejected("aspect",
                       [](json& j) { j["cameras"][0]["perspective"]["aspectRatio"] = -1.5; },
                       {"cameras[0].perspective.aspectRatio", "is -1.5"});
    expectEditRejected("spot",
                       [](json& j) {
                           j["extensions"]["KHR_lights_punctual"]["lights"][0] = {
                               {"type", "spot"},
                               {"spot", {{"innerConeAngle", 0.6}, {"outerConeAngle", 0.5}}}};
                       },
                       {"lights[0].spot", "expected inner < outer"});
}

TEST(HostileImport, WhatTheGltfSpecForbidsIsRefusedNamingTheNodeAndKey) {
    expectEditRejected("version3", [](json& j) { j["asset"]["version"] = "3.0"; },
                       {"asset.version: '3.0'", "expected 2.x"});
    expectEditRejected("version-number", [](json& j) { j["asset"]["version"] = 2; },
                       {"asset.version", "expected a string"});
    expectEditRejected("min-version", [](json& j) { j["asset"]["minVersion"] = "2.1"; },
                       {"asset.minVersion: '2.1'", "expected 2.0"});
    expectEditRejected("two-parents",
                       [](json& j) {
                           j["nodes"][0]["children"] = {2};
                           j["nodes"][1]["children"] = {2};
                       },
                       {"nodes[1].children[0]", "already a child of node 0"});
    // Nodes whose children form a cycle, with no scene to start from: refused, not dropped.
    expectEditRejected("cycle",
                       [](json& j) {
                           j.erase("scene");
                           j.erase("scenes");
                           j["nodes"][0]["children"] = {2};
                           j["nodes"][2]["children"] = {0};
                       },
                       {"nodes[", "children", "cycle"});
    // null is not a setting's default: it is refused like any other wrong type.
    expectEditRejected("setting-null",
                       [](json& j) {
                           j["extras"] = {{"onelight", {{"texels_per_metre", nullptr}}}};
                       },
                       {"extras.onelight.texels_per_metre", "null"});
}

TEST(HostileImport, CoordinatesPastTheDocumentedRangeAreRejected) {
    EXPECT_EQ(world::kMaxCoordinateMetres, 1e6);
    expectEditRejected("far-translation",
                       [](json& j) {
                           j["nodes"][0]["translation"] = {1e30, 0, 0};
                       },
                       {"node 'floor'", "vertex 0", "expected |x|, |y|, |z| <= 1e+06 m"});
    expectEditRejected("huge-scale",
                       [](json& j) {
                           j["nodes"][0]["scale"] = {1e20, 1, 1};
                       },
                       {"node 'floor'", "lies in the world"});
    expectEditRejected("far-light",
                       [](json& j) {
                           j["nodes"][1]["translation"] = {0, -2e6, 0};
                       },
                       {"light 'sun'", "expected |x|"});
    expectEditRejected("far-camera",
                       [](json& j) {
                           j["nodes"][2]["translation"] = {0, 0, 5e6};
                       },
                       {"camera 'view'", "expected |x|"});
    // Just inside the range still imports.
    const world::SourceLevel level =
        world::importGltf(writeTriangleLevel(hostileFolder("near-limit"), [](json& j) {
            j["nodes"][0]["translation"] = {9e5, 0, 0};
        }));
    EXPECT_EQ(level.instances.size(), 1u);
}

TEST(HostileImport, ALightmapPastTheTexelLimitIsRefusedBeforeAllocating) {
    // 200 two-metre triangles at 1024 texels per metre: 200 full 1024^2 atlases, 210M texels,
    // about 20 GB to bake. Refused at compile with the figures, not "out of memory" in the bake.
    const std::string gltf = writeTriangleLevel(hostileFolder("texels"), [](json& j) {
        json nodes = json::array();
        for (int i = 0; i < 200; ++i) {
            json node = j["nodes"][0];
            node["translation"] = {3 * (i % 20), 0, 3 * (i / 20)};
            nodes.push_back(node);
        }
        nodes.push_back(j["nodes"][1]);
        nodes.push_back(j["nodes"][2]);
        j["nodes"] = nodes;
        json roots = json::array();
        for (int i = 0; i < 202; ++i) roots.push_back(i);
        j["scenes"][0]["nodes"] = roots;
    });
    world::CompileOptions options;
    options.charts.texelsPerMetre = 1024.0;
    options.charts.densityFromCommandLine = true;
    const auto start = std::chrono::steady_clock::now();
    try {
        (void)compileFile(gltf, options);
        FAIL() << "compiled 210M texels";
    } catch (const world::Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("level.gltf: 209715200 lightmap texels in 200 atlases"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("expected at most 134217728 texels"), std::string::npos) << message;
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
              10.0);
    // The same level at 16 texels per metre compiles.
    options.charts.texelsPerMetre = 16.0;
    EXPECT_GE(compileFile(gltf, options).level.surfaces.size(), 200u);
}

}  // namespace
}  // namespace onelight::test
