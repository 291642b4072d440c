#include "world/import/q3/computed_view.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace onelight::world::q3 {
namespace {

struct Triangle {
    glm::vec3 a, e1, e2;  // a corner and the edges from it
    glm::vec3 normal;     // by the winding (counter-clockwise is the front)
};

struct Scene {
    std::vector<Triangle> triangles;
    glm::vec3 lo{1e30f}, hi{-1e30f};
};

Scene sceneOf(const SourceLevel& level) {
    Scene scene;
    for (const MeshInstance& mesh : level.instances) {
        if (mesh.dynamic) continue;
        const glm::mat4 toWorld(mesh.worldFromLocal);
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            glm::vec3 p[3];
            for (int k = 0; k < 3; ++k)
                p[k] = glm::vec3(toWorld *
                                 glm::vec4(mesh.vertices[mesh.indices[t + size_t(k)]].position, 1));
            const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
            const float length = glm::length(n);
            if (!(length > 1e-12f)) continue;
            scene.triangles.push_back({p[0], p[1] - p[0], p[2] - p[0], n / length});
            for (const glm::vec3& q : p) {
                scene.lo = glm::min(scene.lo, q);
                scene.hi = glm::max(scene.hi, q);
            }
        }
    }
    return scene;
}

struct Hit {
    float distance = -1.0f;  // < 0: none
    bool front = false;      // the ray meets the front of the surface
};

// The nearest hit along the ray (Moller-Trumbore).
Hit cast(const Scene& scene, glm::vec3 origin, glm::vec3 direction) {
    Hit best;
    for (const Triangle& t : scene.triangles) {
        const glm::vec3 p = glm::cross(direction, t.e2);
        const float det = glm::dot(t.e1, p);
        if (std::abs(det) < 1e-12f) continue;
        const float inv = 1.0f / det;
        const glm::vec3 s = origin - t.a;
        const float u = glm::dot(s, p) * inv;
        if (u < 0.0f || u > 1.0f) continue;
        const glm::vec3 q = glm::cross(s, t.e1);
        const float v = glm::dot(direction, q) * inv;
        if (v < 0.0f || u + v > 1.0f) continue;
        const float d = glm::dot(t.e2, q) * inv;
        if (d > 1e-4f && (best.distance < 0.0f || d < best.distance)) {
            best.distance = d;
            best.front = glm::dot(t.normal, direction) < 0.0f;
        }
    }
    return best;
}

const glm::vec3 kAround[10] = {{1, 0, 0},
                               {-1, 0, 0},
                               {0, 0, 1},
                               {0, 0, -1},
                               {0, -1, 0},
                               {0, 1, 0},
                               {0.70710678f, 0, 0.70710678f},
                               {-0.70710678f, 0, 0.70710678f},
                               {0.70710678f, 0, -0.70710678f},
                               {-0.70710678f, 0, -0.70710678f}};

// The free distance in each of kAround's directions, or nothing when the point is not inside.
std::optional<std::vector<float>> around(const Scene& scene, glm::vec3 point) {
    std::vector<float> free(10, 0.0f);
    for (int i = 0; i < 10; ++i) {
        const Hit h = cast(scene, point, kAround[i]);
        if (i == 5 && h.distance < 0.0f) {  // up: open sky
            free[size_t(i)] = glm::length(scene.hi - scene.lo);
            continue;
        }
        if (h.distance < 0.0f || !h.front) return std::nullopt;
        free[size_t(i)] = h.distance;
    }
    return free;
}

}  // namespace

bool insideLevel(const SourceLevel& level, glm::vec3 point) {
    return around(sceneOf(level), point).has_value();
}

std::optional<ComputedView> computeViewInside(const SourceLevel& level) {
    const Scene scene = sceneOf(level);
    if (scene.triangles.empty()) return std::nullopt;
    const glm::vec3 size = scene.hi - scene.lo;
    const bool alongX = size.x >= size.z;
    std::optional<ComputedView> best;
    float bestScore = 0.0f;
    // The view at `feet` when the eyes fit under the ceiling and are inside; its score is the
    // open area about the eyes.
    const auto consider = [&](glm::vec3 feet) {
        const glm::vec3 eye = feet + glm::vec3(0.0f, kComputedViewEyeHeight, 0.0f);
        const std::optional<std::vector<float>> free = around(scene, eye);
        if (!free) return std::optional<std::vector<float>>();
        const float score = ((*free)[0] + (*free)[1]) * ((*free)[2] + (*free)[3]);
        if (!best || score > bestScore) {
            ComputedView v;
            v.feet = feet;
            v.eye = eye;
            const float ahead = alongX ? (*free)[0] : (*free)[2],
                        behind = alongX ? (*free)[1] : (*free)[3];
            v.forward = alongX ? glm::vec3(ahead >= behind ? 1.0f : -1.0f, 0.0f, 0.0f)
                               : glm::vec3(0.0f, 0.0f, ahead >= behind ? 1.0f : -1.0f);
            v.rotation =
                glm::angleAxis(std::atan2(-v.forward.x, -v.forward.z), glm::vec3(0.0f, 1.0f, 0.0f));
            best = v;
            bestScore = score;
        }
        return free;
    };
    // The floor under `point`, if a floor's front is below it.
    const auto floorUnder = [&](glm::vec3 point) -> std::optional<glm::vec3> {
        const Hit down = cast(scene, point, glm::vec3(0.0f, -1.0f, 0.0f));
        if (down.distance < 0.0f || !down.front) return std::nullopt;
        return point - glm::vec3(0.0f, down.distance - 0.01f, 0.0f);
    };
    const int steps = 9, levels = 4;
    for (int j = 0; j < levels; ++j)
        for (int x = 0; x < steps; ++x)
            for (int z = 0; z < steps; ++z) {
                const glm::vec3 point =
                    scene.lo + size * glm::vec3((float(x) + 0.5f) / float(steps),
                                                (float(j) + 0.5f) / float(levels),
                                                (float(z) + 0.5f) / float(steps));
                const std::optional<glm::vec3> feet = floorUnder(point);
                if (!feet) continue;
                const std::optional<std::vector<float>> free = consider(*feet);
                if (!free) continue;
                // The middle of the open span about it, once.
                const glm::vec3 middle =
                    *feet + glm::vec3(0.5f * ((*free)[0] - (*free)[1]), kComputedViewEyeHeight,
                                      0.5f * ((*free)[2] - (*free)[3]));
                if (const std::optional<glm::vec3> centred = floorUnder(middle))
                    (void)consider(*centred);
            }
    return best;
}

}  // namespace onelight::world::q3
