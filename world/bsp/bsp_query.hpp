// Queries over a compiled level's BSP: the leaf containing a point, leaves front to back from
// an eye (optionally culled by a frustum), the first triangle a ray hits, and the first contact
// of a sphere swept along a segment (the player's collision). Each has a brute-force twin over
// all triangles that the tests compare against. Needs only GLM: the runtime links it.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"

namespace onelight::world {

/// Borrowed views of the arrays the queries read.
struct BspView {
    std::span<const BspPlane> planes;
    std::span<const BspNode> nodes;
    std::span<const BspLeaf> leaves;
    std::span<const Vertex> vertices;
    std::span<const uint32_t> indices;  // leaf triangles are index triples
    double epsilon = 1e-5;              // metres; plane-side slack of the traversal
};

[[nodiscard]] BspView bspView(const CompiledLevel& level);

/// The build's plane-side tolerance for a level whose coordinates reach `maxAbsCoordinate`
/// metres: a few float ulps there (authored data is float), never below 1e-5 m.
[[nodiscard]] double bspBuildEpsilon(double maxAbsCoordinate);

/// The queries' slack: the build's tolerance plus the rounding of vertices to float.
[[nodiscard]] double bspQueryEpsilon(double maxAbsCoordinate);

/// The leaf whose region holds `point` (points on a plane go to the front).
[[nodiscard]] uint32_t findLeaf(const BspView& bsp, const glm::dvec3& point);

/// A frustum as six planes (xyz normal pointing inside, w offset): inside when dot >= -w.
struct Frustum {
    std::array<glm::dvec4, 6> planes;
};

/// Calls `visit(leaf)` for every leaf, nearest the eye first; with a frustum, subtrees whose
/// bounds are outside are skipped.
void leavesFrontToBack(const BspView& bsp, const glm::dvec3& eye,
                       const std::function<void(uint32_t leaf)>& visit,
                       const Frustum* frustum = nullptr);

struct RayHit {
    bool hit = false;
    double t = 0.0;                // distance along the unit direction, metres
    uint32_t triangle = kNoIndex;  // first index / 3
};

/// First triangle (either side) hit by origin + t * direction, 0 <= t <= tMax.
[[nodiscard]] RayHit raycast(const BspView& bsp, const glm::dvec3& origin,
                             const glm::dvec3& direction, double tMax);
[[nodiscard]] RayHit raycastBruteForce(const BspView& bsp, const glm::dvec3& origin,
                                       const glm::dvec3& direction, double tMax);

struct SweepHit {
    bool hit = false;
    double fraction = 1.0;  // of the segment travelled before contact, [0, 1]
    uint32_t triangle = kNoIndex;
    glm::dvec3 normal{0.0};  // unit, from the contact point towards the sphere's centre
};

/// First contact of a sphere of `radius` whose centre moves from start to end.
[[nodiscard]] SweepHit sweepSphere(const BspView& bsp, const glm::dvec3& start,
                                   const glm::dvec3& end, double radius);
[[nodiscard]] SweepHit sweepSphereBruteForce(const BspView& bsp, const glm::dvec3& start,
                                             const glm::dvec3& end, double radius);

}  // namespace onelight::world
