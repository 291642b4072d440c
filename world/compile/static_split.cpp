#include "world/compile/static_split.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include "world/error.hpp"

namespace onelight::world {
namespace {

/// sin of the smallest angle below which a triangle counts as degenerate (zero area).
constexpr double kDegenerateSine = 1e-12;

bool is_degenerate(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const double longest =
        std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)});
    const double twice_area = glm::length(glm::cross(b - a, c - a));
    return !(twice_area > kDegenerateSine * longest);
}

/// Corners of a triangle, rotated so the lexicographically smallest comes first (winding kept):
/// two triangles are duplicates when their keys are equal.
using TriangleKey = std::array<double, 9>;
TriangleKey duplicate_key(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
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

glm::dmat4 entity_world(const Entity& e) {
    glm::dmat4 m = glm::dmat4(glm::mat3_cast(glm::dquat(e.rotation)));
    m[0] *= e.scale.x;
    m[1] *= e.scale.y;
    m[2] *= e.scale.z;
    m[3] = glm::dvec4(glm::dvec3(e.position), 1.0);
    return m;
}

/// The matrix that carries normals: the cofactor matrix of the linear part (det * inverse
/// transpose), signed so a mirror keeps the side; defined even when the transform is singular.
glm::dmat3 normal_matrix_of(const glm::dmat4& m) {
    const glm::dmat3 a(m);
    glm::dmat3 cofactor(glm::cross(a[1], a[2]), glm::cross(a[2], a[0]), glm::cross(a[0], a[1]));
    return glm::determinant(a) < 0.0 ? -cofactor : cofactor;
}

Vertex transform_vertex(const Vertex& v, const glm::dmat4& m, const glm::dmat3& normal_matrix,
                        float mirror) {
    Vertex out = v;
    out.position = glm::vec3(glm::dvec3(m * glm::dvec4(glm::dvec3(v.position), 1.0)));
    const glm::dvec3 n = normal_matrix * glm::dvec3(v.normal);
    const double n_length = glm::length(n);
    out.normal =
        n_length > 0.0 && std::isfinite(n_length) ? glm::vec3(n / n_length) : glm::vec3(0, 0, 1);
    const glm::dvec3 t = glm::dmat3(m) * glm::dvec3(v.tangent);
    const double t_length = glm::length(t);
    out.tangent = glm::vec4(
        t_length > 0.0 && std::isfinite(t_length) ? glm::vec3(t / t_length) : glm::vec3(1, 0, 0),
        v.tangent.w * mirror);
    return out;
}

}  // namespace

SplitLevel split_static_dynamic(const SourceLevel& level) {
    SplitLevel out;
    out.entities = level.entities;
    StaticGeometry& geometry = out.static_geometry;
    std::map<TriangleKey, uint32_t> seen;

    for (size_t i = 0; i < level.instances.size(); ++i) {
        const MeshInstance& instance = level.instances[i];
        const std::string name = instance.node_name + "/" + instance.mesh_name;
        geometry.instance_has_uv1.push_back(instance.has_uv1 ? 1 : 0);
        geometry.instance_names.push_back(name);
        if (instance.dynamic) continue;
        const glm::dmat4& m = instance.world_from_local;
        const glm::dmat3 normal_matrix = normal_matrix_of(m);
        const bool mirrored = glm::determinant(glm::dmat3(m)) < 0.0;
        const uint32_t base = static_cast<uint32_t>(geometry.vertices.size());
        for (const Vertex& v : instance.vertices) {
            const Vertex w = transform_vertex(v, m, normal_matrix, mirrored ? -1.0f : 1.0f);
            CompileVertex cv;
            cv.position = glm::dvec3(m * glm::dvec4(glm::dvec3(v.position), 1.0));
            if (!std::isfinite(cv.position.x) || !std::isfinite(cv.position.y) ||
                !std::isfinite(cv.position.z))
                throw Error(level.source_path + ": mesh '" + instance.mesh_name + "' of node '" +
                            instance.node_name +
                            "': world position is NaN or Inf; expected finite values");
            cv.normal = w.normal;
            cv.tangent = w.tangent;
            cv.uv0 = v.uv0;
            cv.uv1 = v.uv1;
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
            if (is_degenerate(a, b, c)) {
                ++out.degenerate_removed;
                continue;
            }
            if (!seen.emplace(duplicate_key(a, b, c), 0u).second) {
                ++out.duplicates_removed;
                continue;
            }
            geometry.triangles.push_back(triangle);
        }
    }

    // Dynamic meshes, grouped by entity, in the entity's space.
    std::vector<size_t> dynamic_instances;
    for (size_t i = 0; i < level.instances.size(); ++i)
        if (level.instances[i].dynamic) dynamic_instances.push_back(i);
    std::stable_sort(dynamic_instances.begin(), dynamic_instances.end(), [&](size_t a, size_t b) {
        return level.instances[a].entity < level.instances[b].entity;
    });
    for (size_t i : dynamic_instances) {
        const MeshInstance& instance = level.instances[i];
        Entity& entity = out.entities[instance.entity];
        if (entity.dynamic_mesh_count == 0)
            entity.first_dynamic_mesh = static_cast<uint32_t>(out.dynamic_meshes.size());
        ++entity.dynamic_mesh_count;
        const glm::dmat4 world = entity_world(entity);
        const double det = glm::determinant(glm::dmat3(world));
        if (!(std::abs(det) > 1e-30) || !std::isfinite(det))
            throw Error(level.source_path + ": node '" + entity.name +
                        "': a dynamic node needs an invertible transform (no zero scale)");
        const glm::dmat4 m = glm::inverse(world) * instance.world_from_local;
        const glm::dmat3 normal_matrix = normal_matrix_of(m);
        const bool mirrored = glm::determinant(glm::dmat3(m)) < 0.0;
        DynamicMesh mesh;
        mesh.name = instance.node_name + "/" + instance.mesh_name;
        mesh.material = instance.material;
        mesh.first_vertex = static_cast<uint32_t>(out.dynamic_vertices.size());
        mesh.vertex_count = static_cast<uint32_t>(instance.vertices.size());
        mesh.first_index = static_cast<uint32_t>(out.dynamic_indices.size());
        mesh.index_count = static_cast<uint32_t>(instance.indices.size());
        for (const Vertex& v : instance.vertices) {
            const Vertex w = transform_vertex(v, m, normal_matrix, mirrored ? -1.0f : 1.0f);
            if (!std::isfinite(w.position.x) || !std::isfinite(w.position.y) ||
                !std::isfinite(w.position.z))
                throw Error(level.source_path + ": mesh '" + instance.mesh_name + "' of node '" +
                            instance.node_name + "': position is NaN or Inf in its entity's space");
            out.dynamic_vertices.push_back(w);
        }
        for (size_t t = 0; t + 2 < instance.indices.size(); t += 3) {
            out.dynamic_indices.push_back(instance.indices[t]);
            out.dynamic_indices.push_back(instance.indices[t + (mirrored ? 2 : 1)]);
            out.dynamic_indices.push_back(instance.indices[t + (mirrored ? 1 : 2)]);
        }
        out.dynamic_meshes.push_back(std::move(mesh));
    }
    return out;
}

}  // namespace onelight::world
