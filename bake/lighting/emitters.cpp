#include "bake/lighting/emitters.hpp"

#include <algorithm>
#include <cmath>

#include "bake/lighting/sampling.hpp"

namespace onelight::bake {

Emitters collectEmitters(const BakeScene& scene) {
    Emitters out;
    std::vector<double> power;
    for (uint32_t t = 0; t < scene.triangleCount(); ++t) {
        const uint32_t material = scene.materialIndexOf(t);
        const float y = luminance(meanEmission(scene.materials(), material));
        if (!(y > 0.0f)) continue;
        const std::array<glm::vec3, 3> v = scene.triangleVertices(t);
        EmissiveTriangle e;
        e.triangle = t;
        e.a = v[0];
        e.ab = v[1] - v[0];
        e.ac = v[2] - v[0];
        e.area = 0.5f * float(glm::length(glm::cross(glm::dvec3(e.ab), glm::dvec3(e.ac))));
        e.normal = scene.triangleNormal(t);
        e.doubleSided = scene.materialOf(t).doubleSided;
        if (!(e.area > 0.0f) || !std::isfinite(e.area)) continue;
        out.triangles.push_back(e);
        power.push_back(double(e.area) * double(y) * (e.doubleSided ? 2.0 : 1.0));
    }
    if (out.triangles.empty()) return out;
    double total = 0.0;
    for (double p : power) total += p;
    out.cdf.resize(power.size());
    out.choiceOverArea.assign(scene.triangleCount(), 0.0f);
    double running = 0.0;
    for (size_t i = 0; i < power.size(); ++i) {
        running += power[i];
        out.cdf[i] = float(running / total);
        out.choiceOverArea[out.triangles[i].triangle] =
            float(power[i] / total / double(out.triangles[i].area));
    }
    out.cdf.back() = 1.0f;
    return out;
}

EmitterSample sampleEmitter(const BakeScene& scene, const Emitters& emitters, const glm::vec3& from,
                            glm::vec3 u) {
    EmitterSample s;
    if (emitters.empty()) return s;
    const size_t i =
        std::min(size_t(std::upper_bound(emitters.cdf.begin(), emitters.cdf.end(), u.x) -
                        emitters.cdf.begin()),
                 emitters.triangles.size() - 1);
    const EmissiveTriangle& e = emitters.triangles[i];
    // A uniform point: barycentrics (sqrt(u1) (1 - u2), sqrt(u1) u2) (Turk 1990, Graphics Gems).
    const float r = std::sqrt(u.y);
    SurfaceHit at;
    at.triangle = e.triangle;
    at.barycentric = {r * (1.0f - u.z), r * u.z};
    const glm::vec3 point = e.a + at.barycentric.x * e.ab + at.barycentric.y * e.ac;
    const glm::vec3 toPoint = point - from;
    const float d2 = glm::dot(toPoint, toPoint);
    if (!(d2 > 0.0f)) return s;
    s.distance = std::sqrt(d2);
    s.direction = toPoint / s.distance;
    const float cosLight = glm::dot(s.direction, e.normal);  // > 0: the back face is seen
    const bool backFace = cosLight > 0.0f;
    if (std::fabs(cosLight) < 1e-6f) return s;
    // A cut-out or blended emitter lights only where rays would meet it (bake_scene.hpp).
    if (!scene.coverageAccepts(e.triangle, at.barycentric, from, s.direction)) return s;
    s.radiance = sampleEmission(scene.materials(), scene.materialIndexOf(e.triangle),
                                scene.attributesAt(at), backFace, 0.0f);
    if (s.radiance == glm::vec3(0.0f)) return s;
    s.pdf = emitterPdf(emitters, e.triangle, s.distance, std::fabs(cosLight));
    // Stop short of the emitter by the self-intersection offset, relative to the distance too.
    s.shadowDistance = std::max(0.0f, s.distance * (1.0f - 1e-4f) - 2.0f * scene.rayOffset());
    return s;
}

float emitterPdf(const Emitters& emitters, uint32_t triangle, float distance, float cosLight) {
    if (emitters.empty() || triangle >= emitters.choiceOverArea.size() || !(cosLight > 0.0f))
        return 0.0f;
    return emitters.choiceOverArea[triangle] * distance * distance / cosLight;
}

}  // namespace onelight::bake
