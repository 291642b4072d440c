#include "world/import/tangent_generation.hpp"

#include <cmath>

namespace onelight::world {

glm::vec3 anyPerpendicular(const glm::vec3& n) {
    // Duff et al. 2017, "Building an Orthonormal Basis, Revisited", listing 3
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
}

void generateTangents(std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices) {
    // Lengyel 2001: for a triangle with edges e1, e2 and UV deltas (s1,t1), (s2,t2),
    //   T = (t2 e1 - t1 e2) / det,  B = (s1 e2 - s2 e1) / det,  det = s1 t2 - s2 t1.
    // Accumulated unnormalised (area weighted), then Gram-Schmidt against the normal.
    std::vector<glm::dvec3> tangentSum(vertices.size(), glm::dvec3(0.0));
    std::vector<glm::dvec3> bitangentSum(vertices.size(), glm::dvec3(0.0));
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const Vertex& a = vertices[indices[t]];
        const Vertex& b = vertices[indices[t + 1]];
        const Vertex& c = vertices[indices[t + 2]];
        const glm::dvec3 e1 = glm::dvec3(b.position) - glm::dvec3(a.position);
        const glm::dvec3 e2 = glm::dvec3(c.position) - glm::dvec3(a.position);
        const glm::dvec2 d1 = glm::dvec2(b.uv0) - glm::dvec2(a.uv0);
        const glm::dvec2 d2 = glm::dvec2(c.uv0) - glm::dvec2(a.uv0);
        const double s1 = d1.x, t1 = d1.y, s2 = d2.x, t2 = d2.y;
        const double det = s1 * t2 - s2 * t1;
        if (!(std::abs(det) > 1e-20)) continue;
        const glm::dvec3 tangent = (t2 * e1 - t1 * e2) / det;
        const glm::dvec3 bitangent = (s1 * e2 - s2 * e1) / det;
        if (!std::isfinite(glm::dot(tangent, tangent)) ||
            !std::isfinite(glm::dot(bitangent, bitangent)))
            continue;
        for (int k = 0; k < 3; ++k) {
            tangentSum[indices[t + static_cast<size_t>(k)]] += tangent;
            bitangentSum[indices[t + static_cast<size_t>(k)]] += bitangent;
        }
    }
    for (size_t i = 0; i < vertices.size(); ++i) {
        const glm::dvec3 n = glm::dvec3(vertices[i].normal);
        glm::dvec3 t = tangentSum[i] - n * glm::dot(n, tangentSum[i]);
        const double length = glm::length(t);
        if (!(length > 1e-12) || !std::isfinite(length)) {
            vertices[i].tangent = glm::vec4(anyPerpendicular(vertices[i].normal), 1.0f);
            continue;
        }
        t /= length;
        // glTF: bitangent = cross(normal, tangent.xyz) * w
        const double handedness = glm::dot(glm::cross(n, t), bitangentSum[i]) < 0.0 ? -1.0 : 1.0;
        vertices[i].tangent = glm::vec4(glm::vec3(t), static_cast<float>(handedness));
    }
}

}  // namespace onelight::world
