#include "world/bsp/bsp_query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace onelight::world {
namespace {

using Triangle = std::array<glm::dvec3, 3>;

Triangle triangleAt(const BspView& bsp, uint32_t triangle) {
    return {glm::dvec3(bsp.vertices[bsp.indices[3 * triangle]].position),
            glm::dvec3(bsp.vertices[bsp.indices[3 * triangle + 1]].position),
            glm::dvec3(bsp.vertices[bsp.indices[3 * triangle + 2]].position)};
}

double planeDistance(const BspPlane& plane, const glm::dvec3& p) {
    return glm::dot(plane.normal, p) - plane.distance;
}

/// Moeller and Trumbore 1997, "Fast, Minimum Storage Ray/Triangle Intersection"; both sides.
bool rayTriangle(const glm::dvec3& origin, const glm::dvec3& direction, const Triangle& tri,
                 double& t) {
    const glm::dvec3 e1 = tri[1] - tri[0], e2 = tri[2] - tri[0];
    const glm::dvec3 p = glm::cross(direction, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0 || !std::isfinite(det)) return false;
    const double inv = 1.0 / det;
    const glm::dvec3 s = origin - tri[0];
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return false;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(direction, q) * inv;
    if (v < 0.0 || u + v > 1.0) return false;
    t = glm::dot(e2, q) * inv;
    return std::isfinite(t);
}

/// Ericson 2005, "Real-Time Collision Detection", 5.1.5 ClosestPtPointTriangle.
glm::dvec3 closestPointOnTriangle(const glm::dvec3& p, const Triangle& tri) {
    const glm::dvec3 &a = tri[0], &b = tri[1], &c = tri[2];
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

/// Smallest t in [0, 1] with |start + t d - centre| = r, for a start outside the sphere.
bool segmentSphere(const glm::dvec3& start, const glm::dvec3& d, const glm::dvec3& centre, double r,
                   double& t) {
    const glm::dvec3 m = start - centre;
    const double a = glm::dot(d, d), b = glm::dot(m, d), c = glm::dot(m, m) - r * r;
    if (a == 0.0) return false;
    const double disc = b * b - a * c;
    if (disc < 0.0) return false;
    t = (-b - std::sqrt(disc)) / a;
    return t >= 0.0 && t <= 1.0;
}

/// Smallest t in [0, 1] where the moving point is at distance r from segment [p, q]'s
/// interior (infinite cylinder, clamped to the segment).
bool segmentCylinder(const glm::dvec3& start, const glm::dvec3& d, const glm::dvec3& p,
                     const glm::dvec3& q, double r, double& t) {
    const glm::dvec3 axis = q - p;
    const double axisLength2 = glm::dot(axis, axis);
    if (axisLength2 == 0.0) return false;
    const glm::dvec3 m = start - p;
    // Components perpendicular to the axis.
    const glm::dvec3 dp = d - axis * (glm::dot(d, axis) / axisLength2);
    const glm::dvec3 mp = m - axis * (glm::dot(m, axis) / axisLength2);
    const double a = glm::dot(dp, dp), b = glm::dot(mp, dp), c = glm::dot(mp, mp) - r * r;
    if (a == 0.0) return false;
    const double disc = b * b - a * c;
    if (disc < 0.0) return false;
    t = (-b - std::sqrt(disc)) / a;
    if (t < 0.0 || t > 1.0) return false;
    const double s = glm::dot(m + d * t, axis) / axisLength2;
    return s >= 0.0 && s <= 1.0;
}

/// First contact of a sphere moving start -> start + d with a triangle; t in [0, 1].
bool sweepSphereTriangle(const glm::dvec3& start, const glm::dvec3& d, double r,
                         const Triangle& tri, double& t) {
    if (glm::length(start - closestPointOnTriangle(start, tri)) < r) {
        t = 0.0;
        return true;
    }
    double best = std::numeric_limits<double>::infinity();
    // Face: the centre reaches distance r from the plane inside the triangle.
    const glm::dvec3 nRaw = glm::cross(tri[1] - tri[0], tri[2] - tri[0]);
    const double nLength = glm::length(nRaw);
    if (nLength > 0.0) {
        const glm::dvec3 n = nRaw / nLength;
        const double s0 = glm::dot(n, start - tri[0]), speed = glm::dot(n, d);
        if (speed != 0.0) {
            const double side = s0 >= 0.0 ? 1.0 : -1.0;
            const double tf = (side * r - s0) / speed;
            if (tf >= 0.0 && tf <= 1.0) {
                const glm::dvec3 contact = start + d * tf - n * (side * r);
                const glm::dvec3 closest = closestPointOnTriangle(contact, tri);
                if (glm::length(contact - closest) <= 1e-9 * (1.0 + glm::length(contact)))
                    best = tf;
            }
        }
    }
    double te;
    for (int k = 0; k < 3; ++k) {
        if (segmentCylinder(start, d, tri[static_cast<size_t>(k)],
                            tri[static_cast<size_t>((k + 1) % 3)], r, te))
            best = std::min(best, te);
        if (segmentSphere(start, d, tri[static_cast<size_t>(k)], r, te)) best = std::min(best, te);
    }
    if (!std::isfinite(best)) return false;
    t = best;
    return true;
}

bool boxOutside(const Frustum& frustum, const glm::vec3& lo, const glm::vec3& hi) {
    for (const glm::dvec4& p : frustum.planes) {
        const glm::dvec3 corner(p.x >= 0.0 ? hi.x : lo.x, p.y >= 0.0 ? hi.y : lo.y,
                                p.z >= 0.0 ? hi.z : lo.z);
        if (glm::dot(glm::dvec3(p), corner) + p.w < 0.0) return true;
    }
    return false;
}

struct RayWalk {
    const BspView& bsp;
    glm::dvec3 origin, direction;
    double tMax;
    RayHit best;

    void leaf(uint32_t index) {
        const BspLeaf& l = bsp.leaves[index];
        for (uint32_t i = 0; i < l.triangleCount; ++i) {
            double t;
            const uint32_t tri = l.firstTriangle + i;
            if (rayTriangle(origin, direction, triangleAt(bsp, tri), t) && t >= 0.0 && t <= tMax &&
                (!best.hit || t < best.t || (t == best.t && tri < best.triangle))) {
                best = {true, t, tri};
            }
        }
    }

    void walk(int32_t child, double t0, double t1) {
        if (child < 0) return leaf(static_cast<uint32_t>(-child - 1));
        const BspNode& node = bsp.nodes[static_cast<size_t>(child)];
        const BspPlane& plane = bsp.planes[node.plane];
        const double d0 = planeDistance(plane, origin + direction * t0);
        const double d1 = planeDistance(plane, origin + direction * t1);
        const double e = bsp.epsilon;
        if (d0 >= e && d1 >= e) return walk(node.front, t0, t1);
        if (d0 <= -e && d1 <= -e) return walk(node.back, t0, t1);
        const bool frontFirst = d0 >= 0.0;
        const int32_t nearChild = frontFirst ? node.front : node.back;
        const int32_t farChild = frontFirst ? node.back : node.front;
        // Where the ray enters the far side's slab (|d| within e counts as both sides).
        const double towardFar = frontFirst ? d0 - d1 : d1 - d0;  // > 0 when heading there
        double tFar = t0;
        if (towardFar > 0.0) {
            const double start = frontFirst ? d0 - e : -d0 - e;  // distance to the far slab
            tFar = t0 + std::clamp(start / towardFar, 0.0, 1.0) * (t1 - t0);
        }
        walk(nearChild, t0, t1);
        if (!best.hit || best.t >= tFar) walk(farChild, tFar, t1);
    }
};

struct SphereWalk {
    const BspView& bsp;
    glm::dvec3 start, delta;
    double radius;
    SweepHit best;

    void leaf(uint32_t index) {
        const BspLeaf& l = bsp.leaves[index];
        for (uint32_t i = 0; i < l.triangleCount; ++i) {
            const uint32_t tri = l.firstTriangle + i;
            double t;
            if (!sweepSphereTriangle(start, delta, radius, triangleAt(bsp, tri), t)) continue;
            if (!best.hit || t < best.fraction || (t == best.fraction && tri < best.triangle)) {
                best.hit = true;
                best.fraction = t;
                best.triangle = tri;
            }
        }
    }

    void walk(int32_t child) {
        if (child < 0) return leaf(static_cast<uint32_t>(-child - 1));
        const BspNode& node = bsp.nodes[static_cast<size_t>(child)];
        const BspPlane& plane = bsp.planes[node.plane];
        const double d0 = planeDistance(plane, start), d1 = planeDistance(plane, start + delta);
        const double reach = radius + bsp.epsilon;
        if (d0 >= reach && d1 >= reach) return walk(node.front);
        if (d0 <= -reach && d1 <= -reach) return walk(node.back);
        walk(node.front);
        walk(node.back);
    }
};

SweepHit finish(const BspView& bsp, const glm::dvec3& start, const glm::dvec3& delta,
                SweepHit hit) {
    if (!hit.hit) return hit;
    const glm::dvec3 centre = start + delta * hit.fraction;
    const glm::dvec3 contact = closestPointOnTriangle(centre, triangleAt(bsp, hit.triangle));
    const glm::dvec3 away = centre - contact;
    const double length = glm::length(away);
    if (length > 0.0) {
        hit.normal = away / length;
    } else {
        const Triangle tri = triangleAt(bsp, hit.triangle);
        const glm::dvec3 n = glm::cross(tri[1] - tri[0], tri[2] - tri[0]);
        hit.normal = glm::length(n) > 0.0 ? glm::normalize(n) : glm::dvec3(0.0, 0.0, 1.0);
    }
    return hit;
}

}  // namespace

BspView bspView(const CompiledLevel& level) {
    BspView view;
    view.planes = level.bspPlanes;
    view.nodes = level.bspNodes;
    view.leaves = level.bspLeaves;
    view.vertices = level.vertices;
    view.indices = level.indices;
    double maxAbs = 0.0;
    for (const Vertex& v : level.vertices)
        maxAbs = std::max({maxAbs, double(std::abs(v.position.x)), double(std::abs(v.position.y)),
                           double(std::abs(v.position.z))});
    view.epsilon = bspQueryEpsilon(maxAbs);
    return view;
}

double bspBuildEpsilon(double maxAbsCoordinate) {
    return std::max(
        1e-5, 4.0 * static_cast<double>(std::numeric_limits<float>::epsilon()) * maxAbsCoordinate);
}

double bspQueryEpsilon(double maxAbsCoordinate) {
    // The build's tolerance plus the rounding of the vertices to float.
    return bspBuildEpsilon(maxAbsCoordinate) +
           4.0 * static_cast<double>(std::numeric_limits<float>::epsilon()) * maxAbsCoordinate;
}

uint32_t findLeaf(const BspView& bsp, const glm::dvec3& point) {
    if (bsp.nodes.empty()) return 0;
    int32_t child = 0;
    while (child >= 0) {
        const BspNode& node = bsp.nodes[static_cast<size_t>(child)];
        child = planeDistance(bsp.planes[node.plane], point) >= 0.0 ? node.front : node.back;
    }
    return static_cast<uint32_t>(-child - 1);
}

void leavesFrontToBack(const BspView& bsp, const glm::dvec3& eye,
                       const std::function<void(uint32_t leaf)>& visit, const Frustum* frustum) {
    if (bsp.nodes.empty()) {
        if (!bsp.leaves.empty()) visit(0);
        return;
    }
    std::vector<int32_t> stack{0};
    while (!stack.empty()) {
        const int32_t child = stack.back();
        stack.pop_back();
        if (child < 0) {
            const uint32_t leaf = static_cast<uint32_t>(-child - 1);
            const BspLeaf& l = bsp.leaves[leaf];
            if (frustum && l.triangleCount > 0 && boxOutside(*frustum, l.boundsMin, l.boundsMax))
                continue;
            visit(leaf);
            continue;
        }
        const BspNode& node = bsp.nodes[static_cast<size_t>(child)];
        if (frustum && boxOutside(*frustum, node.boundsMin, node.boundsMax)) continue;
        const bool eyeInFront = planeDistance(bsp.planes[node.plane], eye) >= 0.0;
        // Far side pushed first so the near side pops first.
        stack.push_back(eyeInFront ? node.back : node.front);
        stack.push_back(eyeInFront ? node.front : node.back);
    }
}

RayHit raycast(const BspView& bsp, const glm::dvec3& origin, const glm::dvec3& direction,
               double tMax) {
    RayWalk walk{bsp, origin, direction, tMax, {}};
    if (bsp.nodes.empty()) {
        if (!bsp.leaves.empty()) walk.leaf(0);
    } else {
        walk.walk(0, 0.0, tMax);
    }
    return walk.best;
}

RayHit raycastBruteForce(const BspView& bsp, const glm::dvec3& origin, const glm::dvec3& direction,
                         double tMax) {
    RayHit best;
    for (uint32_t tri = 0; tri < bsp.indices.size() / 3; ++tri) {
        double t;
        if (rayTriangle(origin, direction, triangleAt(bsp, tri), t) && t >= 0.0 && t <= tMax &&
            (!best.hit || t < best.t))
            best = {true, t, tri};
    }
    return best;
}

SweepHit sweepSphere(const BspView& bsp, const glm::dvec3& start, const glm::dvec3& end,
                     double radius) {
    SphereWalk walk{bsp, start, end - start, radius, {}};
    if (bsp.nodes.empty()) {
        if (!bsp.leaves.empty()) walk.leaf(0);
    } else {
        walk.walk(0);
    }
    return finish(bsp, start, end - start, walk.best);
}

SweepHit sweepSphereBruteForce(const BspView& bsp, const glm::dvec3& start, const glm::dvec3& end,
                               double radius) {
    SweepHit best;
    for (uint32_t tri = 0; tri < bsp.indices.size() / 3; ++tri) {
        double t;
        if (!sweepSphereTriangle(start, end - start, radius, triangleAt(bsp, tri), t)) continue;
        if (!best.hit || t < best.fraction) {
            best.hit = true;
            best.fraction = t;
            best.triangle = tri;
        }
    }
    return finish(bsp, start, end - start, best);
}

}  // namespace onelight::world
