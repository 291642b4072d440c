// Bad input: a missing glTF, a truncated one, one whose buffer file is not there, one whose image
// file is not there, and a corrupt package each give one clear line
// "onelight: FILE: what was expected" on stderr and exit code 1, never a crash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "test_scene.hpp"

namespace {

using namespace onelight;
namespace fs = std::filesystem;

std::string badDir() {
    const std::string dir = test::outputDir() + "/bad_input";
    fs::create_directories(dir);
    return dir;
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

// `named`: the file the line must name (the input itself unless another file is at fault).
void expectOneClearLine(const std::string& file, const std::string& expectedWords,
                        std::string named = "") {
    if (named.empty()) named = fs::path(file).filename().string();
    const world::ChildResult r = test::runOnelight({file, "--headless", "--size", "64x64"});
    EXPECT_EQ(r.signal, 0) << "crashed on " << file;
    EXPECT_EQ(r.exitCode, 1) << r.err;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line:\n" << r.err;
    EXPECT_EQ(r.err.rfind("onelight: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << "the line does not name the file: " << r.err;
    EXPECT_NE(r.err.find(expectedWords), std::string::npos) << r.err;
    std::printf("[ bad input ] %s", r.err.c_str());
}

TEST(RenderBadInput, MissingGltf) {
    expectOneClearLine(badDir() + "/no_such_level.gltf", "no such file");
}

TEST(RenderBadInput, TruncatedGltf) {
    const std::string source =
        std::string(ONELIGHT_SHARED_ASSETS) + "/TextureSettingsTest/glTF/TextureSettingsTest.gltf";
    if (!std::filesystem::exists(source))
        GTEST_SKIP() << "the shared assets are absent: " << source;
    std::ifstream in(source, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(text.size(), 1000u);
    const std::string path = badDir() + "/truncated.gltf";
    writeText(path, text.substr(0, text.size() / 2));
    expectOneClearLine(path, "parse error");
}

TEST(RenderBadInput, GltfReferencingMissingBuffer) {
    const std::string path = badDir() + "/missing_buffer.gltf";
    writeText(path,
              R"({"asset":{"version":"2.0"},"buffers":[{"uri":"not_there.bin","byteLength":36}],)"
              R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
              R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
              R"("min":[0,0,0],"max":[1,1,0]}],)"
              R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
              R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})");
    expectOneClearLine(path, "not_there.bin");
}

TEST(RenderBadInput, GltfReferencingMissingImage) {
    // A valid level whose base-colour texture file is missing: the compile that makes its
    // package refuses it, naming the file (a package never refers to a file that is not there).
    test::Scene scene;
    scene.materials.push_back({});
    test::addFloor(scene, 0.0f, 0.0f, 1.0f, 0.0f, 0);
    const std::string path = badDir() + "/missing_image.gltf";
    test::writeGltf(scene, path);
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string material = R"("pbrMetallicRoughness":{)";
    const size_t at = text.find(material);
    ASSERT_NE(at, std::string::npos);
    text.insert(at + material.size(), R"("baseColorTexture":{"index":0},)");
    text.insert(text.rfind('}'),
                R"(,"textures":[{"source":0}],"images":[{"uri":"not_there.png"}])");
    writeText(path, text);
    fs::remove(badDir() + "/missing_image.olpak");
    expectOneClearLine(path, "expected an image the level uses", "not_there.png");
}

TEST(RenderBadInput, CorruptPackage) {
    const std::string path = badDir() + "/corrupt.olpak";
    writeText(path, "OLPK this is not a package");
    expectOneClearLine(path, "corrupt.olpak");
}

}  // namespace
