#include "hostile_level.hpp"

#include <fstream>

#include "tests/support/scratch_folder.hpp"

namespace onelight::test {

nlohmann::json triangleLevelJson() {
    return nlohmann::json::parse(R"({
      "asset": {"version": "2.0"},
      "scene": 0,
      "scenes": [{"nodes": [0, 1, 2]}],
      "nodes": [
        {"name": "floor", "mesh": 0},
        {"name": "sun", "rotation": [-0.7071068, 0, 0, 0.7071068],
         "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"name": "view", "camera": 0, "translation": [0, 1, 3]}
      ],
      "meshes": [{"name": "floor", "primitives": [{"attributes": {"POSITION": 0}}]}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                     "min": [-1, 0, -1], "max": [1, 0, 1]}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "buffers": [{"uri": "level.bin", "byteLength": 36}],
      "cameras": [{"type": "perspective",
                   "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100, "aspectRatio": 1.5}}],
      "extensionsUsed": ["KHR_lights_punctual"],
      "extensions": {"KHR_lights_punctual": {"lights": [
        {"name": "sun", "type": "directional", "color": [1, 1, 1], "intensity": 3}]}}
    })");
}

std::string writeTriangleLevel(const std::filesystem::path& folder,
                               const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json json = triangleLevelJson();
    if (edit) edit(json);
    const std::string gltf = (folder / "level.gltf").string();
    std::ofstream(gltf) << json.dump();
    // Counter-clockwise seen from above: the floor faces up.
    const float positions[9] = {-1, 0, 1, 1, 0, 1, 0, 0, -1};
    std::ofstream bin(folder / "level.bin", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(positions), sizeof positions);
    return gltf;
}

std::filesystem::path hostileFolder(const std::string& name) {
    return scratchFolder("onelight-hostile-" + name);
}

}  // namespace onelight::test
