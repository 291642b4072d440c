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
        if (triangles.size() <= options_.max_leaf_triangles || depth >= options_.max_depth)
            return make_leaf(std::move(triangles));
        BspPlane plane;
        if (!choose_plane(triangles, plane)) return make_leaf(std::move(triangles));
        std::vector<uint32_t> front, back;
        partition(triangles, plane, front, back);
        triangles = {};
        const uint32_t node = static_cast<uint32_t>(out_.nodes.size());
        out_.nodes.push_back(BspNode{});
        out_.nodes[node].plane = static_cast<uint32_t>(out_.planes.size());
        out_.planes.push_back(plane);
        const int32_t front_child = build(std::move(front), depth + 1);
        const int32_t back_child = build(std::move(back), depth + 1);
        out_.nodes[node].front = front_child;
        out_.nodes[node].back = back_child;
        return static_cast<int32_t>(node);
    }

    std::vector<std::vector<uint32_t>> leaf_triangles;

private:
    int32_t make_leaf(std::vector<uint32_t> triangles) {
        leaf_triangles.push_back(std::move(triangles));
        out_.leaves.push_back(BspLeaf{});
        return -static_cast<int32_t>(out_.leaves.size());
    }

    bool plane_of(uint32_t t, BspPlane& plane) const {
        const glm::dvec3 n = area_vector(geometry_, geometry_.triangles[t]);
        const double length = glm::length(n);
        if (!(length > 0.0)) return false;
        plane.normal = n / length;
        plane.distance =
            glm::dot(plane.normal, geometry_.vertices[geometry_.triangles[t].v[0]].position);
        return true;
    }

    int side_of(const BspPlane& plane, uint32_t vertex) const {
        const double d =
            glm::dot(plane.normal, geometry_.vertices[vertex].position) - plane.distance;
        return d > out_.epsilon ? kFront : d < -out_.epsilon ? kBack : kOn;
    }

    /// kFront, kBack, or kOn for a triangle that must be cut.
    int classify(const BspPlane& plane, uint32_t t) const {
        bool any_front = false, any_back = false;
        for (uint32_t v : geometry_.triangles[t].v) {
            const int s = side_of(plane, v);
            any_front |= s == kFront;
            any_back |= s == kBack;
        }
        if (any_front && any_back) return kOn;
        if (any_front) return kFront;
        if (any_back) return kBack;
        // In the plane: the side the triangle faces.
        return glm::dot(area_vector(geometry_, geometry_.triangles[t]), plane.normal) >= 0.0
                   ? kFront
                   : kBack;
    }

    /// The plane through edge k of triangle t that contains the triangle's normal: separates
    /// coplanar neighbours (a subdivided floor) that the triangle's own plane cannot.
    bool edge_plane_of(uint32_t t, size_t k, BspPlane& plane) const {
        const StaticTriangle& tri = geometry_.triangles[t];
        const glm::dvec3& a = geometry_.vertices[tri.v[k]].position;
        const glm::dvec3& b = geometry_.vertices[tri.v[(k + 1) % 3]].position;
        const glm::dvec3 n = glm::cross(b - a, area_vector(geometry_, tri));
        const double length = glm::length(n);
        if (!(length > 0.0) || !std::isfinite(length)) return false;
        plane.normal = n / length;
        plane.distance = glm::dot(plane.normal, a);
        return true;
    }

    void score_plane(const std::vector<uint32_t>& triangles, const BspPlane& plane,
                     double& best_score, BspPlane& best) const {
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
        const double score = options_.split_weight * static_cast<double>(splits) +
                             std::abs(static_cast<double>(front) - static_cast<double>(back));
        if (score < best_score) {
            best_score = score;
            best = plane;
        }
    }

    /// Candidates: the planes of a spread of the node's triangles, then planes through their
    /// edges; the lowest split_weight * splits + |front - back| wins.
    bool choose_plane(const std::vector<uint32_t>& triangles, BspPlane& best) const {
        const size_t count = std::min<size_t>(options_.candidate_planes, triangles.size());
        const size_t stride = triangles.size() / count;
        double best_score = std::numeric_limits<double>::infinity();
        for (size_t c = 0; c < count; ++c) {
            BspPlane plane;
            if (plane_of(triangles[c * stride + stride / 2], plane))
                score_plane(triangles, plane, best_score, best);
        }
        // Edge planes when the face planes leave the node badly unbalanced (coplanar sets).
        if (best_score > 0.25 * static_cast<double>(triangles.size())) {
            const size_t edge_count = std::max<size_t>(1, count / 3);
            const size_t edge_stride = triangles.size() / edge_count;
            for (size_t c = 0; c < edge_count; ++c) {
                for (size_t k = 0; k < 3; ++k) {
                    BspPlane plane;
                    if (edge_plane_of(triangles[c * edge_stride + edge_stride / 2], k, plane))
                        score_plane(triangles, plane, best_score, best);
                }
            }
        }
        return std::isfinite(best_score);
    }

    uint32_t cut_point(uint32_t a, uint32_t b, const BspPlane& plane) {
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

    void emit_polygon(const std::vector<uint32_t>& polygon, const StaticTriangle& source,
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
            std::vector<uint32_t> front_polygon, back_polygon;
            for (size_t k = 0; k < 3; ++k) {
                const uint32_t a = source.v[k], b = source.v[(k + 1) % 3];
                const int sa = side_of(plane, a), sb = side_of(plane, b);
                if (sa != kBack) front_polygon.push_back(a);
                if (sa != kFront) back_polygon.push_back(a);
                if ((sa == kFront && sb == kBack) || (sa == kBack && sb == kFront)) {
                    const uint32_t cut = cut_point(a, b, plane);
                    front_polygon.push_back(cut);
                    back_polygon.push_back(cut);
                }
            }
            // The cut triangle's slot is reused by its first front piece.
            StaticTriangle first = source;
            first.v = {front_polygon[0], front_polygon[1], front_polygon[2]};
            geometry_.triangles[t] = first;
            front.push_back(t);
            for (size_t i = 2; i + 1 < front_polygon.size(); ++i) {
                StaticTriangle extra = source;
                extra.v = {front_polygon[0], front_polygon[i], front_polygon[i + 1]};
                geometry_.triangles.push_back(extra);
                front.push_back(static_cast<uint32_t>(geometry_.triangles.size() - 1));
            }
            emit_polygon(back_polygon, source, back);
        }
    }

    StaticGeometry& geometry_;
    const BspOptions& options_;
    BspBuild& out_;
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> cuts_;
};

}  // namespace

BspBuild build_bsp(StaticGeometry& geometry, const BspOptions& options) {
    BspBuild out;
    double max_abs = 0.0;
    for (const CompileVertex& v : geometry.vertices)
        max_abs = std::max(
            {max_abs, std::abs(v.position.x), std::abs(v.position.y), std::abs(v.position.z)});
    out.epsilon = bsp_build_epsilon(max_abs);
    BspBuilder builder(geometry, options, out);
    std::vector<uint32_t> all(geometry.triangles.size());
    for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    builder.build(std::move(all), 0);

    // Reorder triangles leaf by leaf.
    std::vector<StaticTriangle> ordered;
    ordered.reserve(geometry.triangles.size());
    for (size_t leaf = 0; leaf < out.leaves.size(); ++leaf) {
        out.leaves[leaf].first_triangle = static_cast<uint32_t>(ordered.size());
        out.leaves[leaf].triangle_count =
            static_cast<uint32_t>(builder.leaf_triangles[leaf].size());
        for (uint32_t t : builder.leaf_triangles[leaf]) ordered.push_back(geometry.triangles[t]);
    }
    geometry.triangles = std::move(ordered);
    return out;
}

}  // namespace onelight::world
