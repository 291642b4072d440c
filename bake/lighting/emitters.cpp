#include "bake/lighting/emitters.hpp"

#include <algorithm>
#include <cmath>

#include "bake/lighting/cell_visibility.hpp"
#include "bake/lighting/sampling.hpp"

namespace onelight::bake {
namespace {

/// The density per steradian of a point drawn on a triangle chosen with `probability` and
/// uniform over its `area`, seen at `distance` and cosine `cosLight` (emitters.hpp).
float solidAnglePdf(float probability, float area, float distance, float cosLight) {
    return probability / area * distance * distance / cosLight;
}

}  // namespace

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
    std::vector<LightBound> bounds(out.triangles.size());
    out.emitterOf.assign(scene.triangleCount(), ~0u);
    for (size_t i = 0; i < out.triangles.size(); ++i) {
        const EmissiveTriangle& e = out.triangles[i];
        LightBound& b = bounds[i];
        b.lo = glm::min(e.a, glm::min(e.a + e.ab, e.a + e.ac));
        b.hi = glm::max(e.a, glm::max(e.a + e.ab, e.a + e.ac));
        b.power = static_cast<float>(power[i]);
        if (!e.doubleSided) {
            b.planeNormal = e.normal;
            b.planePoint = e.a;
        }
        out.emitterOf[e.triangle] = static_cast<uint32_t>(i);
    }
    out.cells = layoutLightCells(bounds.size(), scene.boundsMin(), scene.boundsMax());
    const CellSurfacePoints points = surfacePointsOfCells(scene, out.cells);
    fillLightCells(out.cells, bounds, [&](uint32_t source, uint32_t cell) {
        const EmissiveTriangle& e = out.triangles[source];
        const glm::vec3 centre = e.a + (e.ab + e.ac) / 3.0f;
        return visibleFraction(points, cell, [&](const glm::vec3& p, const glm::vec3& n) {
            const glm::vec3 to = centre - p;
            const float distance = glm::length(to);
            if (!(distance > 0.0f)) return false;
            const glm::vec3 d = to / distance;
            uint64_t rays = 0;
            return glm::dot(n, d) > 0.0f && (e.doubleSided || glm::dot(d, e.normal) < 0.0f) &&
                   !scene.occluded(p, d, distance * (1.0f - 1e-4f) - 2.0f * scene.rayOffset(),
                                   rays);
        });
    });
    return out;
}

EmitterSample sampleEmitter(const BakeScene& scene, const Emitters& emitters, const glm::vec3& from,
                            glm::vec3 u) {
    EmitterSample s;
    if (emitters.empty()) return s;
    const LightPick pick = pickLight(emitters.cells, from, u.x);
    if (!(pick.probability > 0.0f)) return s;
    const EmissiveTriangle& e = emitters.triangles[pick.source];
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
    s.pdf = solidAnglePdf(pick.probability, e.area, s.distance, std::fabs(cosLight));
    // Stop short of the emitter by the self-intersection offset, relative to the distance too.
    s.shadowDistance = std::max(0.0f, s.distance * (1.0f - 1e-4f) - 2.0f * scene.rayOffset());
    return s;
}

float emitterPdf(const Emitters& emitters, const glm::vec3& from, uint32_t triangle, float distance,
                 float cosLight) {
    if (emitters.empty() || triangle >= emitters.emitterOf.size() || !(cosLight > 0.0f))
        return 0.0f;
    const uint32_t e = emitters.emitterOf[triangle];
    if (e == ~0u) return 0.0f;
    return solidAnglePdf(lightProbability(emitters.cells, from, e), emitters.triangles[e].area,
                         distance, cosLight);
}

}  // namespace onelight::bake
