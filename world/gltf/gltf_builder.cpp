#include "world/gltf/gltf_builder.hpp"

#include <cstring>

#include "world/file_write.hpp"

namespace onelight::world {

GltfBuilder::GltfBuilder() {
    document_ = {{"asset", {{"version", "2.0"}, {"generator", "onelight"}}},
                 {"scene", 0},
                 {"scenes", nlohmann::json::array({{{"nodes", nlohmann::json::array()}}})},
                 {"nodes", nlohmann::json::array()},
                 {"meshes", nlohmann::json::array()},
                 {"accessors", nlohmann::json::array()},
                 {"bufferViews", nlohmann::json::array()},
                 {"materials", nlohmann::json::array()}};
}

int GltfBuilder::addAccessor(const void* data, size_t bytes, size_t count, int componentType,
                             const char* type, bool withBounds,
                             const std::vector<glm::vec3>* boundsOf) {
    while (buffer_.size() % 4 != 0) buffer_.push_back(0);
    const size_t offset = buffer_.size();
    buffer_.resize(offset + bytes);
    if (bytes > 0) std::memcpy(buffer_.data() + offset, data, bytes);
    document_["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
    nlohmann::json accessor = {{"bufferView", document_["bufferViews"].size() - 1},
                               {"componentType", componentType},
                               {"count", count},
                               {"type", type}};
    if (withBounds && boundsOf && !boundsOf->empty()) {
        glm::vec3 lo = boundsOf->front(), hi = boundsOf->front();
        for (const glm::vec3& p : *boundsOf) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        accessor["min"] = {lo.x, lo.y, lo.z};
        accessor["max"] = {hi.x, hi.y, hi.z};
    }
    document_["accessors"].push_back(accessor);
    return static_cast<int>(document_["accessors"].size() - 1);
}

int GltfBuilder::addMesh(const MeshData& mesh) {
    nlohmann::json attributes;
    attributes["POSITION"] =
        addAccessor(mesh.positions.data(), mesh.positions.size() * 12, mesh.positions.size(), 5126,
                    "VEC3", true, &mesh.positions);
    if (!mesh.normals.empty())
        attributes["NORMAL"] = addAccessor(mesh.normals.data(), mesh.normals.size() * 12,
                                           mesh.normals.size(), 5126, "VEC3", false, nullptr);
    if (!mesh.uv0.empty())
        attributes["TEXCOORD_0"] = addAccessor(mesh.uv0.data(), mesh.uv0.size() * 8,
                                               mesh.uv0.size(), 5126, "VEC2", false, nullptr);
    if (!mesh.uv1.empty())
        attributes["TEXCOORD_1"] = addAccessor(mesh.uv1.data(), mesh.uv1.size() * 8,
                                               mesh.uv1.size(), 5126, "VEC2", false, nullptr);
    nlohmann::json primitive = {{"attributes", attributes}, {"mode", 4}};
    primitive["indices"] = addAccessor(mesh.indices.data(), mesh.indices.size() * 4,
                                       mesh.indices.size(), 5125, "SCALAR", false, nullptr);
    if (mesh.material >= 0) primitive["material"] = mesh.material;
    document_["meshes"].push_back(
        {{"name", mesh.name}, {"primitives", nlohmann::json::array({primitive})}});
    return static_cast<int>(document_["meshes"].size() - 1);
}

int GltfBuilder::addMaterial(const nlohmann::json& material) {
    document_["materials"].push_back(material);
    return static_cast<int>(document_["materials"].size() - 1);
}

int GltfBuilder::addLight(const nlohmann::json& light) {
    nlohmann::json& lights = document_["extensions"]["KHR_lights_punctual"]["lights"];
    if (lights.is_null()) lights = nlohmann::json::array();
    lights.push_back(light);
    document_["extensionsUsed"] = {"KHR_lights_punctual"};
    return static_cast<int>(lights.size() - 1);
}

int GltfBuilder::addCamera(const nlohmann::json& camera) {
    if (!document_.contains("cameras")) document_["cameras"] = nlohmann::json::array();
    document_["cameras"].push_back(camera);
    return static_cast<int>(document_["cameras"].size() - 1);
}

int GltfBuilder::addNode(const nlohmann::json& node, bool root) {
    document_["nodes"].push_back(node);
    const int index = static_cast<int>(document_["nodes"].size() - 1);
    if (root) document_["scenes"][0]["nodes"].push_back(index);
    return index;
}

std::string GltfBuilder::write(const std::filesystem::path& folder, const std::string& name) const {
    nlohmann::json document = document_;
    document["buffers"] = {{{"uri", name + ".bin"}, {"byteLength", buffer_.size()}}};
    if (document["materials"].empty()) document.erase("materials");
    if (document["meshes"].empty()) document.erase("meshes");
    if (document["accessors"].empty()) document.erase("accessors");
    if (document["bufferViews"].empty()) document.erase("bufferViews");
    if (buffer_.empty()) document.erase("buffers");
    writeFileAtomically((folder / (name + ".bin")).string(), buffer_);
    const std::filesystem::path path = folder / (name + ".gltf");
    writeFileAtomically(path.string(), document.dump(1));
    return path.string();
}

MeshData gridMesh(const std::string& name, int cells, double size, double height, double centreX,
                  double centreZ) {
    MeshData mesh;
    mesh.name = name;
    const double step = size / cells;
    for (int j = 0; j <= cells; ++j) {
        for (int i = 0; i <= cells; ++i) {
            mesh.positions.emplace_back(centreX - size / 2 + i * step, height,
                                        centreZ - size / 2 + j * step);
            mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
            mesh.uv0.emplace_back(static_cast<float>(i) / cells, static_cast<float>(j) / cells);
        }
    }
    const auto at = [&](int i, int j) { return static_cast<uint32_t>(j * (cells + 1) + i); };
    for (int j = 0; j < cells; ++j) {
        for (int i = 0; i < cells; ++i) {
            // Counter-clockwise seen from +y.
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    }
    return mesh;
}

MeshData boxMesh(const std::string& name, const glm::vec3& lo, const glm::vec3& hi, int cells,
                 bool openBottom) {
    MeshData mesh;
    mesh.name = name;
    const glm::vec3 centre = (lo + hi) * 0.5f, half = (hi - lo) * 0.5f;
    // Each face: normal n, in-plane axes u, v with cross(u, v) == n.
    const glm::vec3 faces[6][3] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}}};
    for (int f = 0; f < 6; ++f) {
        if (openBottom && f == 3) continue;
        const glm::vec3 n = faces[f][0], u = faces[f][1], v = faces[f][2];
        const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
        for (int j = 0; j <= cells; ++j) {
            for (int i = 0; i <= cells; ++i) {
                const float a = -1.0f + 2.0f * static_cast<float>(i) / static_cast<float>(cells);
                const float b = -1.0f + 2.0f * static_cast<float>(j) / static_cast<float>(cells);
                mesh.positions.push_back(centre + half * (n + u * a + v * b));
                mesh.normals.push_back(n);
                mesh.uv0.emplace_back((a + 1.0f) * 0.5f, (b + 1.0f) * 0.5f);
            }
        }
        const auto at = [&](int i, int j) {
            return base + static_cast<uint32_t>(j * (cells + 1) + i);
        };
        for (int j = 0; j < cells; ++j) {
            for (int i = 0; i < cells; ++i) {
                mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    }
    return mesh;
}

}  // namespace onelight::world
