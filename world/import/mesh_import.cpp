#include "world/import/mesh_import.hpp"

#include <cmath>

#include <tiny_gltf.h>

#include "world/error.hpp"
#include "world/import/accessor_reader.hpp"
#include "world/import/tangent_generation.hpp"

namespace onelight::world {
namespace {

std::vector<uint32_t> triangleList(const std::vector<uint32_t>& raw, int mode) {
    std::vector<uint32_t> list;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        list.assign(raw.begin(), raw.begin() + static_cast<std::ptrdiff_t>(raw.size() / 3 * 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (size_t i = 2; i < raw.size(); ++i) {
            const bool odd = (i % 2) == 1;
            list.push_back(raw[i - 2]);
            list.push_back(odd ? raw[i] : raw[i - 1]);
            list.push_back(odd ? raw[i - 1] : raw[i]);
        }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (size_t i = 2; i < raw.size(); ++i) {
            list.push_back(raw[0]);
            list.push_back(raw[i - 1]);
            list.push_back(raw[i]);
        }
    }
    return list;
}

bool allFinite(const std::vector<float>& values) {
    for (float v : values)
        if (!std::isfinite(v)) return false;
    return true;
}

size_t firstNonFinite(const std::vector<float>& values, int components) {
    for (size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i])) return i / static_cast<size_t>(components);
    return 0;
}

/// glTF: "When normals are not specified, client implementations MUST calculate flat normals."
/// Unwelds the mesh so each triangle has its own three vertices.
void makeFlatNormals(std::vector<Vertex>& vertices, std::vector<uint32_t>& indices) {
    std::vector<Vertex> flat;
    flat.reserve(indices.size());
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        Vertex a = vertices[indices[t]], b = vertices[indices[t + 1]], c = vertices[indices[t + 2]];
        const glm::dvec3 n = glm::cross(glm::dvec3(b.position) - glm::dvec3(a.position),
                                        glm::dvec3(c.position) - glm::dvec3(a.position));
        const double length = glm::length(n);
        const glm::vec3 normal =
            length > 0.0 && std::isfinite(length) ? glm::vec3(n / length) : glm::vec3(0, 0, 1);
        a.normal = b.normal = c.normal = normal;
        flat.push_back(a);
        flat.push_back(b);
        flat.push_back(c);
    }
    vertices = std::move(flat);
    indices.resize(vertices.size());
    for (size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<uint32_t>(i);
}

}  // namespace

ImportedPrimitive importPrimitive(const tinygltf::Model& model, int meshIndex, int primitiveIndex,
                                  const std::string& file) {
    const tinygltf::Mesh& mesh = model.meshes[static_cast<size_t>(meshIndex)];
    const tinygltf::Primitive& primitive = mesh.primitives[static_cast<size_t>(primitiveIndex)];
    const std::string where = file + ": mesh '" +
                              (mesh.name.empty() ? std::to_string(meshIndex) : mesh.name) +
                              "' primitive " + std::to_string(primitiveIndex);
    ImportedPrimitive out;
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        out.isTriangles = false;
        return out;
    }
    const auto attribute = [&](const char* name) {
        const auto it = primitive.attributes.find(name);
        return it == primitive.attributes.end() ? -1 : it->second;
    };
    const int positionAccessor = attribute("POSITION");
    if (positionAccessor < 0) throw Error(where + ": POSITION attribute is missing");
    const std::vector<float> positions =
        readFloatAccessor(model, positionAccessor, 3, where + " POSITION");
    if (!allFinite(positions)) {
        throw Error(where + ": POSITION of vertex " + std::to_string(firstNonFinite(positions, 3)) +
                    " is NaN or Inf; expected finite coordinates");
    }
    const size_t vertexCount = positions.size() / 3;
    const auto readOptional = [&](const char* name, int components) {
        const int accessor = attribute(name);
        if (accessor < 0) return std::vector<float>();
        const std::string place = where + " " + name;
        std::vector<float> values = readFloatAccessor(model, accessor, components, place);
        if (values.size() != vertexCount * static_cast<size_t>(components)) {
            throw Error(place + ": has " +
                        std::to_string(values.size() / static_cast<size_t>(components)) +
                        " elements; expected " + std::to_string(vertexCount) + " like POSITION");
        }
        if (!allFinite(values)) {
            throw Error(place + ": element " + std::to_string(firstNonFinite(values, components)) +
                        " is NaN or Inf; expected finite values");
        }
        return values;
    };
    const std::vector<float> normals = readOptional("NORMAL", 3);
    const std::vector<float> tangents = readOptional("TANGENT", 4);
    const std::vector<float> uv0 = readOptional("TEXCOORD_0", 2);
    const std::vector<float> uv1 = readOptional("TEXCOORD_1", 2);
    out.hasUv1 = !uv1.empty();

    out.vertices.resize(vertexCount);
    for (size_t i = 0; i < vertexCount; ++i) {
        Vertex& v = out.vertices[i];
        v.position = glm::vec3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
        if (!normals.empty()) {
            const glm::vec3 n(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
            const float length = glm::length(n);
            v.normal = length > 1e-12f ? n / length : glm::vec3(0.0f);
        }
        if (!tangents.empty()) {
            const glm::vec3 t(tangents[4 * i], tangents[4 * i + 1], tangents[4 * i + 2]);
            const float length = glm::length(t);
            v.tangent = length > 1e-12f
                            ? glm::vec4(t / length, tangents[4 * i + 3] < 0.0f ? -1.0f : 1.0f)
                            : glm::vec4(0.0f);
        }
        if (!uv0.empty()) v.uv0 = glm::vec2(uv0[2 * i], uv0[2 * i + 1]);
        if (!uv1.empty()) v.uv1 = glm::vec2(uv1[2 * i], uv1[2 * i + 1]);
    }

    std::vector<uint32_t> raw;
    if (primitive.indices >= 0) {
        raw = readIndexAccessor(model, primitive.indices, where + " indices");
        for (size_t i = 0; i < raw.size(); ++i) {
            if (raw[i] >= vertexCount) {
                throw Error(where + ": index " + std::to_string(i) + " is " +
                            std::to_string(raw[i]) + "; expected below the vertex count " +
                            std::to_string(vertexCount));
            }
        }
    } else {
        raw.resize(vertexCount);
        for (size_t i = 0; i < vertexCount; ++i) raw[i] = static_cast<uint32_t>(i);
    }
    out.indices = triangleList(raw, mode);

    if (normals.empty()) makeFlatNormals(out.vertices, out.indices);
    // Zero-length authored normals fall back to the normal of a triangle that uses the vertex.
    for (size_t t = 0; t + 2 < out.indices.size(); t += 3) {
        const glm::dvec3 a(out.vertices[out.indices[t]].position);
        const glm::dvec3 b(out.vertices[out.indices[t + 1]].position);
        const glm::dvec3 c(out.vertices[out.indices[t + 2]].position);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double length = glm::length(n);
        for (size_t k = 0; k < 3; ++k) {
            Vertex& v = out.vertices[out.indices[t + k]];
            if (v.normal == glm::vec3(0.0f))
                v.normal = length > 0.0 ? glm::vec3(n / length) : glm::vec3(0, 0, 1);
        }
    }
    for (Vertex& v : out.vertices)
        if (v.normal == glm::vec3(0.0f)) v.normal = glm::vec3(0, 0, 1);

    bool tangentsUsable = !tangents.empty();
    for (const Vertex& v : out.vertices)
        if (v.tangent == glm::vec4(0.0f)) tangentsUsable = false;
    if (!tangentsUsable) generateTangents(out.vertices, out.indices);
    return out;
}

}  // namespace onelight::world
