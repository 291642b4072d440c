#include "world/bsp/bsp_build.hpp"

#include "world/bsp/bsp_query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace onelight::world {
namespace {

enum Side { kBack = -1, kOn = 0, kFront = 1 };

class BspBuilder {
public:
    BspBuilder(StaticGeometry& geometry, const BspOptions& options, BspBuild& out)
        : geometry_(geometry), options_(options), out_(out) {}

    int32_t build(std::vector<uint32_t> triangles, uint32_t depth) {
        out_.depth = std::max(out_.depth, depth);
        if (triangles.size() <= options_.maxLeafTriangles || depth >= options_.maxDepth)
            return makeLeaf(std::move(triangles));
        BspPlane plane;
        if (!choosePlane(triangles, plane)) return makeLeaf(std::move(triangles));
        std::vector<uint32_t> front, back;
        partition(triangles, plane, front, back);
        triangles = {};
        const uint32_t node = static_cast<uint32_t>(out_.nodes.size());
        out_.nodes.push_back(BspNode{});
        out_.nodes[node].plane = static_cast<uint32_t>(out_.planes.size());
        out_.planes.push_back(plane);
        const int32_t frontChild = build(std::move(front), depth + 1);
        const int32_t backChild = build(std::move(back), depth + 1);
        out_.nodes[node].front = frontChild;
        out_.nodes[node].back = backChild;
        return static_cast<int32_t>(node);
    }

    std::vector<std::vector<uint32_t>> leafTriangles;

private:
    int32_t makeLeaf(std::vector<uint32_t> triangles) {
        leafTriangles.push_back(std::move(triangles));
        out_.leaves.push_back(BspLeaf{});
        return -static_cast<int32_t>(out_.leaves.size());
    }

    bool planeOf(uint32_t t, BspPlane& plane) const {
        const glm::dvec3 n = areaVector(geometry_, geometry_.triangles[t]);
        const double length = glm::length(n);
        if (!(length > 0.0)) return false;
        plane.normal = n / length;
        plane.distance =
            glm::dot(plane.normal, geometry_.vertices[geometry_.triangles[t].v[0]].position);
        return true;
    }

    int sideOf(const BspPlane& plane, uint32_t vertex) const {
        const double d =
            glm::dot(plane.normal, geometry_.vertices[vertex].position) - plane.distance;
        return d > out_.epsilon ? kFront : d < -out_.epsilon ? kBack : kOn;
    }

    /// kFront, kBack, or kOn for a triangle that must be cut.
    int classify(const BspPlane& plane, uint32_t t) const {
        bool anyFront = false, anyBack = false;
        for (uint32_t v : geometry_.triangles[t].v) {
            const int s = sideOf(plane, v);
            anyFront |= s == kFront;
            anyBack |= s == kBack;
        }
        if (anyFront && anyBack) return kOn;
        if (anyFront) return kFront;
        if (anyBack) return kBack;
        // In the plane: the side the triangle faces.
        return glm::dot(areaVector(geometry_, geometry_.triangles[t]), plane.normal) >= 0.0 ? kFront
                                                                                            : kBack;
    }

    /// The plane through edge k of triangle t that contains the triangle's normal: separates
    /// coplanar neighbours (a subdivided floor) that the triangle's own plane cannot.
    bool edgePlaneOf(uint32_t t, size_t k, BspPlane& plane) const {
        const StaticTriangle& tri = geometry_.triangles[t];
        const glm::dvec3& a = geometry_.vertices[tri.v[k]].position;
        const glm::dvec3& b = geometry_.vertices[tri.v[(k + 1) % 3]].position;
        const glm::dvec3 n = glm::cross(b - a, areaVector(geometry_, tri));
        const double length = glm::length(n);
        if (!(length > 0.0) || !std::isfinite(length)) return false;
        plane.normal = n / length;
        plane.distance = glm::dot(plane.normal, a);
        return true;
    }

    void scorePlane(const std::vector<uint32_t>& triangles, const BspPlane& plane,
                    double& bestScore, BspPlane& best) const {
        size_t front = 0, back = 0, splits = 0;
        for (uint32_t t : triangles) {
            const int s = classify(plane, t);
            if (s == kFront)
                ++front;
            else if (s == kBack)
                ++back;
            else
                ++splits;
        }
        if (front + splits == 0 || back + splits == 0) return;  // no progress
        const double score = options_.splitWeight * static_cast<double>(splits) +
                             std::abs(static_cast<double>(front) - static_cast<double>(back));
        if (score < bestScore) {
            bestScore = score;
            best = plane;
        }
    }

    /// Candidates: the planes of a spread of the node's triangles, then planes through their
    /// edges; the lowest splitWeight * splits + |front - back| wins.
    bool choosePlane(const std::vector<uint32_t>& triangles, BspPlane& best) const {
        const size_t count = std::min<size_t>(options_.candidatePlanes, triangles.size());
        const size_t stride = triangles.size() / count;
        double bestScore = std::numeric_limits<double>::infinity();
        for (size_t c = 0; c < count; ++c) {
            BspPlane plane;
            if (planeOf(triangles[c * stride + stride / 2], plane))
                scorePlane(triangles, plane, bestScore, best);
        }
        // Edge planes when the face planes leave the node badly unbalanced (coplanar sets).
        if (bestScore > 0.25 * static_cast<double>(triangles.size())) {
            const size_t edgeCount = std::max<size_t>(1, count / 3);
            const size_t edgeStride = triangles.size() / edgeCount;
            for (size_t c = 0; c < edgeCount; ++c) {
                for (size_t k = 0; k < 3; ++k) {
                    BspPlane plane;
                    if (edgePlaneOf(triangles[c * edgeStride + edgeStride / 2], k, plane))
                        scorePlane(triangles, plane, bestScore, best);
                }
            }
        }
        return std::isfinite(bestScore);
    }

    uint32_t cutPoint(uint32_t a, uint32_t b, const BspPlane& plane) {
        if (a > b) std::swap(a, b);  // one cut point per edge, whichever triangle asks
        const auto found = cuts_.find({a, b});
        if (found != cuts_.end()) return found->second;
        const CompileVertex& va = geometry_.vertices[a];
        const CompileVertex& vb = geometry_.vertices[b];
        const double da = glm::dot(plane.normal, va.position) - plane.distance;
        const double db = glm::dot(plane.normal, vb.position) - plane.distance;
        const double t = std::clamp(da / (da - db), 0.0, 1.0);
        const CompileVertex v = interpolate(va, vb, t);
        geometry_.vertices.push_back(v);
        const uint32_t id = static_cast<uint32_t>(geometry_.vertices.size() - 1);
        cuts_.emplace(std::make_pair(a, b), id);
        return id;
    }

    void emitPolygon(const std::vector<uint32_t>& polygon, const StaticTriangle& source,
                     std::vector<uint32_t>& out) {
        for (size_t i = 1; i + 1 < polygon.size(); ++i) {
            StaticTriangle t = source;
            t.v = {polygon[0], polygon[i], polygon[i + 1]};
            geometry_.triangles.push_back(t);
            out.push_back(static_cast<uint32_t>(geometry_.triangles.size() - 1));
        }
    }

    void partition(const std::vector<uint32_t>& triangles, const BspPlane& plane,
                   std::vector<uint32_t>& front, std::vector<uint32_t>& back) {
        cuts_.clear();
        for (uint32_t t : triangles) {
            const int s = classify(plane, t);
            if (s == kFront) {
                front.push_back(t);
                continue;
            }
            if (s == kBack) {
                back.push_back(t);
                continue;
            }
            ++out_.splits;
            const StaticTriangle source = geometry_.triangles[t];
            std::vector<uint32_t> frontPolygon, backPolygon;
            for (size_t k = 0; k < 3; ++k) {
                const uint32_t a = source.v[k], b = source.v[(k + 1) % 3];
                const int sa = sideOf(plane, a), sb = sideOf(plane, b);
                if (sa != kBack) frontPolygon.push_back(a);
                if (sa != kFront) backPolygon.push_back(a);
                if ((sa == kFront && sb == kBack) || (sa == kBack && sb == kFront)) {
                    const uint32_t cut = cutPoint(a, b, plane);
                    frontPolygon.push_back(cut);
                    backPolygon.push_back(cut);
                }
            }
            // The cut triangle's slot is reused by its first front piece.
            StaticTriangle first = source;
            first.v = {frontPolygon[0], frontPolygon[1], frontPolygon[2]};
            geometry_.triangles[t] = first;
            front.push_back(t);
            for (size_t i = 2; i + 1 < frontPolygon.size(); ++i) {
                StaticTriangle extra = source;
                extra.v = {frontPolygon[0], frontPolygon[i], frontPolygon[i + 1]};
                geometry_.triangles.push_back(extra);
                front.push_back(static_cast<uint32_t>(geometry_.triangles.size() - 1));
            }
            emitPolygon(backPolygon, source, back);
        }
    }

    StaticGeometry& geometry_;
    const BspOptions& options_;
    BspBuild& out_;
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> cuts_;
};

}  // namespace

BspBuild buildBsp(StaticGeometry& geometry, const BspOptions& options) {
    BspBuild out;
    double maxAbs = 0.0;
    for (const CompileVertex& v : geometry.vertices)
        maxAbs = std::max(
            {maxAbs, std::abs(v.position.x), std::abs(v.position.y), std::abs(v.position.z)});
    out.epsilon = bspBuildEpsilon(maxAbs);
    BspBuilder builder(geometry, options, out);
    std::vector<uint32_t> all(geometry.triangles.size());
    for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    builder.build(std::move(all), 0);

    // Reorder triangles leaf by leaf.
    std::vector<StaticTriangle> ordered;
    ordered.reserve(geometry.triangles.size());
    for (size_t leaf = 0; leaf < out.leaves.size(); ++leaf) {
        out.leaves[leaf].firstTriangle = static_cast<uint32_t>(ordered.size());
        out.leaves[leaf].triangleCount = static_cast<uint32_t>(builder.leafTriangles[leaf].size());
        for (uint32_t t : builder.leafTriangles[leaf]) ordered.push_back(geometry.triangles[t]);
    }
    geometry.triangles = std::move(ordered);
    return out;
}

}  // namespace onelight::world
