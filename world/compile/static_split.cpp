#include "world/compile/static_split.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <string_view>
#include <unordered_map>

#include "world/error.hpp"

namespace onelight::world {
namespace {

/// sin of the smallest angle below which a triangle counts as degenerate (zero area).
constexpr double kDegenerateSine = 1e-12;

bool isDegenerate(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const double longest =
        std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)});
    const double twiceArea = glm::length(glm::cross(b - a, c - a));
    return !(twiceArea > kDegenerateSine * longest);
}

/// Corners of a triangle, rotated so the lexicographically smallest comes first (winding kept):
/// two triangles are duplicates when their keys are equal.
using TriangleKey = std::array<double, 9>;
TriangleKey duplicateKey(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const std::array<glm::dvec3, 3> p{a, b, c};
    const auto less = [](const glm::dvec3& x, const glm::dvec3& y) {
        return std::tie(x.x, x.y, x.z) < std::tie(y.x, y.y, y.z);
    };
    size_t first = 0;
    for (size_t i = 1; i < 3; ++i)
        if (less(p[i], p[first])) first = i;
    TriangleKey key;
    for (size_t k = 0; k < 3; ++k) {
        const glm::dvec3& q = p[(first + k) % 3];
        key[3 * k] = q.x + 0.0;  // + 0.0 folds -0 into +0
        key[3 * k + 1] = q.y + 0.0;
        key[3 * k + 2] = q.z + 0.0;
    }
    return key;
}

glm::dmat4 entityWorld(const Entity& e) {
    glm::dmat4 m = glm::dmat4(glm::mat3_cast(glm::dquat(e.rotation)));
    m[0] *= e.scale.x;
    m[1] *= e.scale.y;
    m[2] *= e.scale.z;
    m[3] = glm::dvec4(glm::dvec3(e.position), 1.0);
    return m;
}

}  // namespace

InstanceTransform instanceTransformOf(const glm::dmat4& worldFromLocal) {
    InstanceTransform t;
    t.worldFromLocal = worldFromLocal;
    const glm::dmat3 a(worldFromLocal);
    const glm::dmat3 cofactor(glm::cross(a[1], a[2]), glm::cross(a[2], a[0]),
                              glm::cross(a[0], a[1]));
    t.mirrored = glm::determinant(a) < 0.0;
    t.normalMatrix = t.mirrored ? -cofactor : cofactor;
    return t;
}

CompileVertex worldVertexOf(const Vertex& v, const InstanceTransform& transform) {
    CompileVertex out;
    out.position = glm::dvec3(transform.worldFromLocal * glm::dvec4(glm::dvec3(v.position), 1.0));
    const glm::dvec3 n = transform.normalMatrix * glm::dvec3(v.normal);
    const double nLength = glm::length(n);
    out.normal =
        nLength > 0.0 && std::isfinite(nLength) ? glm::vec3(n / nLength) : glm::vec3(0, 0, 1);
    const glm::dvec3 t = glm::dmat3(transform.worldFromLocal) * glm::dvec3(v.tangent);
    const double tLength = glm::length(t);
    out.tangent = glm::vec4(
        tLength > 0.0 && std::isfinite(tLength) ? glm::vec3(t / tLength) : glm::vec3(1, 0, 0),
        transform.mirrored ? -v.tangent.w : v.tangent.w);
    out.uv0 = v.uv0;
    out.uv1 = v.uv1;
    return out;
}

SplitLevel splitStaticDynamic(const SourceLevel& level) {
    SplitLevel out;
    out.entities = level.entities;
    StaticGeometry& geometry = out.staticGeometry;
    std::map<TriangleKey, uint32_t> seen;

    for (size_t i = 0; i < level.instances.size(); ++i) {
        const MeshInstance& instance = level.instances[i];
        const std::string name = instance.nodeName + "/" + instance.meshName;
        geometry.instanceHasUv1.push_back(instance.hasUv1 ? 1 : 0);
        geometry.instanceNames.push_back(name);
        geometry.instanceIsProp.push_back(instance.prop ? 1 : 0);
        geometry.instanceLightingOrigin.push_back(instance.lightingOrigin);
        if (instance.dynamic) continue;
        const InstanceTransform transform = instanceTransformOf(instance.worldFromLocal);
        const bool mirrored = transform.mirrored;
        const uint32_t base = static_cast<uint32_t>(geometry.vertices.size());
        for (const Vertex& v : instance.vertices) {
            const CompileVertex cv = worldVertexOf(v, transform);
            if (!std::isfinite(cv.position.x) || !std::isfinite(cv.position.y) ||
                !std::isfinite(cv.position.z))
                throw Error(level.sourcePath + ": mesh '" + instance.meshName + "' of node '" +
                            instance.nodeName +
                            "': world position is NaN or Inf; expected finite values");
            geometry.vertices.push_back(cv);
        }
        for (size_t t = 0; t + 2 < instance.indices.size(); t += 3) {
            StaticTriangle triangle;
            // A mirroring transform flips the winding; swap to keep counter-clockwise fronts.
            triangle.v = {base + instance.indices[t],
                          base + instance.indices[t + (mirrored ? 2 : 1)],
                          base + instance.indices[t + (mirrored ? 1 : 2)]};
            triangle.material = instance.material;
            triangle.instance = static_cast<uint32_t>(i);
            const glm::dvec3& a = geometry.vertices[triangle.v[0]].position;
            const glm::dvec3& b = geometry.vertices[triangle.v[1]].position;
            const glm::dvec3& c = geometry.vertices[triangle.v[2]].position;
            if (isDegenerate(a, b, c)) {
                ++out.degenerateRemoved;
                continue;
            }
            if (!seen.emplace(duplicateKey(a, b, c), 0u).second) {
                ++out.duplicatesRemoved;
                continue;
            }
            geometry.triangles.push_back(triangle);
        }
    }

    // Dynamic meshes, grouped by entity, in the entity's space. Meshes whose vertices and
    // indices come out identical there (the items of a class, placed many times) share one copy:
    // the first one's ranges (bucketed by a hash of their bytes, compared whole).
    std::unordered_multimap<size_t, size_t> copies;  // hash -> a dynamic mesh holding that copy
    std::vector<size_t> dynamicInstances;
    for (size_t i = 0; i < level.instances.size(); ++i)
        if (level.instances[i].dynamic) dynamicInstances.push_back(i);
    std::stable_sort(dynamicInstances.begin(), dynamicInstances.end(), [&](size_t a, size_t b) {
        return level.instances[a].entity < level.instances[b].entity;
    });
    for (size_t i : dynamicInstances) {
        const MeshInstance& instance = level.instances[i];
        Entity& entity = out.entities[instance.entity];
        if (entity.dynamicMeshCount == 0)
            entity.firstDynamicMesh = static_cast<uint32_t>(out.dynamicMeshes.size());
        ++entity.dynamicMeshCount;
        const glm::dmat4 world = entityWorld(entity);
        const double det = glm::determinant(glm::dmat3(world));
        if (!(std::abs(det) > 1e-30) || !std::isfinite(det))
            throw Error(level.sourcePath + ": node '" + entity.name +
                        "': a dynamic node needs an invertible transform (no zero scale)");
        glm::dmat4 m = glm::inverse(world) * instance.worldFromLocal;
        // A mesh placed by its entity alone (the usual case) is in the entity's space already:
        // the product above is the identity but for rounding (the entity keeps its turn in
        // floats), which is dropped, so that copies of one mesh placed by different entities
        // come out bit for bit alike (and share one copy below).
        bool identity = true;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                identity = identity && std::abs(m[c][r] - (c == r ? 1.0 : 0.0)) < 1e-6;
        if (identity) m = glm::dmat4(1.0);
        const InstanceTransform transform = instanceTransformOf(m);
        const bool mirrored = transform.mirrored;
        DynamicMesh mesh;
        mesh.name = instance.nodeName + "/" + instance.meshName;
        mesh.material = instance.material;
        std::vector<Vertex> vertices;
        vertices.reserve(instance.vertices.size());
        for (const Vertex& v : instance.vertices) {
            const CompileVertex c = worldVertexOf(v, transform);
            const Vertex w{glm::vec3(c.position), c.normal, c.tangent, c.uv0, c.uv1};
            if (!std::isfinite(w.position.x) || !std::isfinite(w.position.y) ||
                !std::isfinite(w.position.z))
                throw Error(level.sourcePath + ": mesh '" + instance.meshName + "' of node '" +
                            instance.nodeName + "': position is NaN or Inf in its entity's space");
            vertices.push_back(w);
        }
        std::vector<uint32_t> indices;
        indices.reserve(instance.indices.size());
        for (size_t t = 0; t + 2 < instance.indices.size(); t += 3) {
            indices.push_back(instance.indices[t]);
            indices.push_back(instance.indices[t + (mirrored ? 2 : 1)]);
            indices.push_back(instance.indices[t + (mirrored ? 1 : 2)]);
        }
        mesh.vertexCount = static_cast<uint32_t>(vertices.size());
        mesh.indexCount = static_cast<uint32_t>(indices.size());
        const std::string_view vertexBytes(reinterpret_cast<const char*>(vertices.data()),
                                           vertices.size() * sizeof(Vertex));
        const std::string_view indexBytes(reinterpret_cast<const char*>(indices.data()),
                                          indices.size() * sizeof(uint32_t));
        const size_t hash = std::hash<std::string_view>{}(vertexBytes)*31u +
                            std::hash<std::string_view>{}(indexBytes);
        bool shared = false;
        for (auto [at, end] = copies.equal_range(hash); at != end && !shared; ++at) {
            const DynamicMesh& copy = out.dynamicMeshes[at->second];
            shared = copy.vertexCount == mesh.vertexCount && copy.indexCount == mesh.indexCount &&
                     std::memcmp(&out.dynamicVertices[copy.firstVertex], vertices.data(),
                                 vertexBytes.size()) == 0 &&
                     std::memcmp(&out.dynamicIndices[copy.firstIndex], indices.data(),
                                 indexBytes.size()) == 0;
            if (shared) {
                mesh.firstVertex = copy.firstVertex;
                mesh.firstIndex = copy.firstIndex;
                ++out.dynamicMeshesShared;
            }
        }
        if (!shared) {
            mesh.firstVertex = static_cast<uint32_t>(out.dynamicVertices.size());
            mesh.firstIndex = static_cast<uint32_t>(out.dynamicIndices.size());
            out.dynamicVertices.insert(out.dynamicVertices.end(), vertices.begin(), vertices.end());
            out.dynamicIndices.insert(out.dynamicIndices.end(), indices.begin(), indices.end());
            copies.emplace(hash, out.dynamicMeshes.size());
        }
        out.dynamicMeshes.push_back(std::move(mesh));
    }
    return out;
}

}  // namespace onelight::world
