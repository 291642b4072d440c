#include "tests/world/world_test_support.hpp"

#include <filesystem>

#include "tests/support/scratch_folder.hpp"
#include "world/import/gltf_import.hpp"

namespace onelight::test {

world::CompileResult compileFile(const std::string& path, const world::CompileOptions& options) {
    return world::compileLevel(world::importGltf(path), options);
}

std::string sharedAsset(const std::string& relative) {
    const std::filesystem::path path = std::filesystem::path(ONELIGHT_SHARED_ASSETS) / relative;
    return std::filesystem::exists(path) ? path.string() : std::string();
}

std::string writeTwoLampFloor(const std::string& label, int cells, double size, bool lights) {
    GltfBuilder gltf;
    gltf.addNode({{"name", "floor"}, {"mesh", gltf.addMesh(gridMesh("floor", cells, size, 0.0))}});
    if (lights) {
        for (int i = 0; i < 2; ++i) {
            const int light = gltf.addLight({{"type", "point"}, {"intensity", 100.0}});
            gltf.addNode({{"name", i == 0 ? "west" : "east"},
                          {"translation", {(i == 0 ? -0.25 : 0.25) * size, 2.0, 0.0}},
                          {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}});
        }
    }
    return gltf.write(freshFolder(label), label);
}

std::filesystem::path freshFolder(const std::string& label) {
    return scratchFolder("onelight-world-" + label);
}

}  // namespace onelight::test
