// Writes glTF 2.0 files (.gltf + .bin) from code: the demo level's source, the tests' fixtures
// and the benchmark level are generated where they are used instead of committed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace onelight::world {

struct MeshData {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
    std::vector<glm::vec3> normals;  // optional
    std::vector<glm::vec2> uv0;      // optional
    std::vector<glm::vec2> uv1;      // optional
    int material = -1;
};

class GltfBuilder {
public:
    GltfBuilder();

    int addMesh(const MeshData& mesh);  // returns the glTF mesh index
    int addMaterial(const nlohmann::json& material);
    int addLight(const nlohmann::json& light);  // KHR_lights_punctual entry
    int addCamera(const nlohmann::json& camera);
    /// Adds a node; when `root`, it is listed in the scene.
    int addNode(const nlohmann::json& node, bool root = true);

    nlohmann::json& document() { return document_; }

    /// Writes NAME.gltf and NAME.bin into `folder` (each with world::writeFileAtomically, which
    /// throws world::Error); returns the .gltf path.
    std::string write(const std::filesystem::path& folder, const std::string& name) const;

private:
    int addAccessor(const void* data, size_t bytes, size_t count, int componentType,
                    const char* type, bool withBounds, const std::vector<glm::vec3>* boundsOf);

    nlohmann::json document_;
    std::vector<uint8_t> buffer_;
};

/// A flat square grid in the plane y = height: cells x cells quads, `size` metres wide,
/// centred on (centreX, centreZ), facing +y.
[[nodiscard]] MeshData gridMesh(const std::string& name, int cells, double size, double height,
                                double centreX = 0.0, double centreZ = 0.0);

/// An axis-aligned box with `cells` x `cells` quads per face, outward normals, no bottom face
/// when `openBottom`.
[[nodiscard]] MeshData boxMesh(const std::string& name, const glm::vec3& lo, const glm::vec3& hi,
                               int cells, bool openBottom);

}  // namespace onelight::world
