#include "bake/lightmap/texel_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "world/baked_lighting.hpp"

namespace onelight::bake {
namespace {

/// A bilinear lookup at lightmap point p reads the texels whose centres are less than one
/// texel from p in x and in y: every texel that a lookup on a triangle can read samples it.
constexpr double kBilinearReach = 1.0;  // texels
/// A touching texel's point moves this fraction towards the triangle's centroid, off the edge.
constexpr double kEdgeNudge = 1e-3;

/// Closest point of triangle abc to p, as barycentrics (Ericson 2005, "Real-Time Collision
/// Detection", sec. 5.1.5), in 2D.
glm::dvec3 closestBarycentrics(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    const glm::dvec2 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
    const glm::dvec2 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double v = d1 / (d1 - d3);
        return {1.0 - v, v, 0.0};
    }
    const glm::dvec2 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double w = d2 / (d2 - d6);
        return {1.0 - w, 0.0, w};
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {0.0, 1.0 - w, w};
    }
    const double denom = 1.0 / (va + vb + vc);
    const double v = vb * denom, w = vc * denom;
    return {1.0 - v - w, v, w};
}

/// Barycentrics of p in the plane of triangle abc (2D), negative outside it: the affine map
/// that carries a lightmap point to the triangle's plane in world space.
glm::dvec3 planeBarycentrics(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    const glm::dvec2 ab = b - a, ac = c - a, ap = p - a;
    const double det = ab.x * ac.y - ab.y * ac.x;
    if (det == 0.0) return {1.0, 0.0, 0.0};
    const double v = (ap.x * ac.y - ap.y * ac.x) / det;
    const double w = (ab.x * ap.y - ab.y * ap.x) / det;
    return {1.0 - v - w, v, w};
}

/// True when triangle abc overlaps the open square of half-size h around p (texel space).
/// Separating axis test (Ericson 2005, "Real-Time Collision Detection", sec. 5.2.9) on the
/// square's two axes and the triangle's three edge normals.
bool triangleOverlapsSquare(glm::dvec2 p, double h, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    if (std::max({a.x, b.x, c.x}) <= p.x - h || std::min({a.x, b.x, c.x}) >= p.x + h ||
        std::max({a.y, b.y, c.y}) <= p.y - h || std::min({a.y, b.y, c.y}) >= p.y + h)
        return false;
    const glm::dvec2 v[3] = {a, b, c};
    for (int e = 0; e < 3; ++e) {
        const glm::dvec2 edge = v[(e + 1) % 3] - v[e];
        const glm::dvec2 n(-edge.y, edge.x);
        const double onEdge = glm::dot(n, v[e]), opposite = glm::dot(n, v[(e + 2) % 3]);
        const double centre = glm::dot(n, p), radius = h * (std::abs(n.x) + std::abs(n.y));
        if (std::max(onEdge, opposite) <= centre - radius ||
            std::min(onEdge, opposite) >= centre + radius)
            return false;
    }
    return true;
}

struct Candidate {
    double distance = std::numeric_limits<double>::infinity();  // texels
    uint32_t surface = world::kNoIndex;
    uint32_t triangle = 0;  // index triple in level.indices
    glm::dvec3 barycentrics{0.0};
};

}  // namespace

int64_t sampleOfTexel(const std::vector<TexelSample>& samples, uint64_t texel) {
    const auto it = std::lower_bound(samples.begin(), samples.end(), texel,
                                     [](const TexelSample& s, uint64_t t) { return s.texel < t; });
    return it != samples.end() && it->texel == texel ? int64_t(it - samples.begin()) : -1;
}

int64_t sampleAtOffset(const world::CompiledLevel& level, const std::vector<TexelSample>& samples,
                       size_t i, int dx, int dy) {
    const TexelSample& s = samples[i];
    const world::Atlas& atlas = level.atlases[s.atlas];
    const int64_t x = int64_t(s.x) + dx, y = int64_t(s.y) + dy;
    if (x < 0 || y < 0 || x >= int64_t(atlas.width) || y >= int64_t(atlas.height)) return -1;
    return sampleOfTexel(samples, s.texel + uint64_t(int64_t(dy) * int64_t(atlas.width) + dx));
}

uint64_t totalTexels(const world::CompiledLevel& level) {
    return world::atlasTexelOffset(level, static_cast<uint32_t>(level.atlases.size()));
}

std::vector<TexelSample> placeTexels(const world::CompiledLevel& level) {
    std::vector<Candidate> best(totalTexels(level));
    for (uint32_t s = 0; s < level.surfaces.size(); ++s) {
        const world::Surface& surface = level.surfaces[s];
        if (surface.atlas >= level.atlases.size()) continue;
        const world::Atlas& atlas = level.atlases[surface.atlas];
        const uint64_t base = world::atlasTexelOffset(level, surface.atlas);
        const glm::dvec2 scale(atlas.width, atlas.height);
        for (uint32_t i = surface.firstIndex; i < surface.firstIndex + surface.indexCount; i += 3) {
            glm::dvec2 q[3];
            for (int k = 0; k < 3; ++k)
                q[k] = glm::dvec2(level.vertices[level.indices[i + k]].uv1) * scale;
            const glm::dvec2 lo = glm::min(q[0], glm::min(q[1], q[2])) - 1.0;
            const glm::dvec2 hi = glm::max(q[0], glm::max(q[1], q[2])) + 1.0;
            const int x0 = std::max<int>(static_cast<int>(surface.lightmapX),
                                         static_cast<int>(std::floor(lo.x)));
            const int y0 = std::max<int>(static_cast<int>(surface.lightmapY),
                                         static_cast<int>(std::floor(lo.y)));
            const int x1 =
                std::min<int>(static_cast<int>(surface.lightmapX + surface.lightmapWidth) - 1,
                              static_cast<int>(std::floor(hi.x)));
            const int y1 =
                std::min<int>(static_cast<int>(surface.lightmapY + surface.lightmapHeight) - 1,
                              static_cast<int>(std::floor(hi.y)));
            for (int y = y0; y <= y1; ++y) {
                for (int x = x0; x <= x1; ++x) {
                    const glm::dvec2 centre(x + 0.5, y + 0.5);
                    const glm::dvec3 b = closestBarycentrics(centre, q[0], q[1], q[2]);
                    const glm::dvec2 closest = b.x * q[0] + b.y * q[1] + b.z * q[2];
                    const double distance = glm::length(closest - centre);
                    if (distance > 0.0 &&
                        !triangleOverlapsSquare(centre, kBilinearReach, q[0], q[1], q[2]))
                        continue;
                    Candidate& c = best[base + uint64_t(y) * atlas.width + uint64_t(x)];
                    if (distance < c.distance) c = {distance, s, i, b};
                }
            }
        }
    }
    std::vector<TexelSample> samples;
    for (uint32_t a = 0; a < level.atlases.size(); ++a) {
        const uint64_t base = world::atlasTexelOffset(level, a);
        const world::Atlas& atlas = level.atlases[a];
        for (uint32_t y = 0; y < atlas.height; ++y) {
            for (uint32_t x = 0; x < atlas.width; ++x) {
                const uint64_t texel = base + uint64_t(y) * atlas.width + x;
                const Candidate& c = best[texel];
                if (c.surface == world::kNoIndex) continue;
                glm::dvec3 b = c.barycentrics;
                const bool inside = c.distance < 1e-9;  // rounding of an interior point
                if (!inside) b = b * (1.0 - kEdgeNudge) + glm::dvec3(kEdgeNudge / 3.0);
                const world::Vertex* v[3];
                for (int k = 0; k < 3; ++k) v[k] = &level.vertices[level.indices[c.triangle + k]];
                const glm::dvec3 p0(v[0]->position), p1(v[1]->position), p2(v[2]->position);
                const glm::dvec3 cross = glm::cross(p1 - p0, p2 - p0);
                const double worldArea = 0.5 * glm::length(cross);
                const glm::dvec2 t0 = glm::dvec2(v[0]->uv1) * glm::dvec2(atlas.width, atlas.height);
                const glm::dvec2 e1 =
                    glm::dvec2(v[1]->uv1) * glm::dvec2(atlas.width, atlas.height) - t0;
                const glm::dvec2 e2 =
                    glm::dvec2(v[2]->uv1) * glm::dvec2(atlas.width, atlas.height) - t0;
                const double texelArea = 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x);
                TexelSample sample;
                sample.texel = texel;
                sample.atlas = a;
                sample.x = x;
                sample.y = y;
                sample.surface = c.surface;
                sample.position = glm::vec3(b.x * p0 + b.y * p1 + b.z * p2);
                const glm::dvec3 u =
                    planeBarycentrics(glm::dvec2(x + 0.5, y + 0.5), t0, t0 + e1, t0 + e2);
                sample.centre =
                    inside ? sample.position : glm::vec3(u.x * p0 + u.y * p1 + u.z * p2);
                const double length = glm::length(cross);
                sample.normal = length > 0.0 ? glm::vec3(cross / length) : v[0]->normal;
                sample.texelSize =
                    texelArea > 0.0 ? static_cast<float>(std::sqrt(worldArea / texelArea)) : 0.0f;
                sample.centreInside = inside;
                samples.push_back(sample);
            }
        }
    }
    return samples;
}

}  // namespace onelight::bake
