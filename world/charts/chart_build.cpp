#include "world/charts/chart_build.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <tuple>

namespace onelight::world {
namespace {

/// Welded vertex ids: vertices at the same exact position share one id.
std::vector<uint32_t> weldPositions(const StaticGeometry& geometry) {
    std::vector<uint32_t> order(geometry.vertices.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto key = [&](uint32_t i) {
        const glm::dvec3& p = geometry.vertices[i].position;
        return std::make_tuple(p.x, p.y, p.z);
    };
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return key(a) < key(b) || (key(a) == key(b) && a < b);
    });
    std::vector<uint32_t> welded(geometry.vertices.size(), 0);
    uint32_t next = 0;
    for (size_t i = 0; i < order.size(); ++i) {
        if (i > 0 && key(order[i]) != key(order[i - 1])) ++next;
        welded[order[i]] = next;
    }
    return welded;
}

/// For each triangle, the triangles across each of its edges (by welded position).
std::vector<std::vector<uint32_t>> edgeNeighbours(const StaticGeometry& geometry) {
    const std::vector<uint32_t> welded = weldPositions(geometry);
    struct EdgeUse {
        uint32_t a, b, triangle;
    };
    std::vector<EdgeUse> uses;
    uses.reserve(geometry.triangles.size() * 3);
    for (uint32_t t = 0; t < geometry.triangles.size(); ++t) {
        for (size_t k = 0; k < 3; ++k) {
            uint32_t a = welded[geometry.triangles[t].v[k]],
                     b = welded[geometry.triangles[t].v[(k + 1) % 3]];
            if (a > b) std::swap(a, b);
            if (a != b) uses.push_back({a, b, t});
        }
    }
    std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
        return std::tie(x.a, x.b, x.triangle) < std::tie(y.a, y.b, y.triangle);
    });
    std::vector<std::vector<uint32_t>> neighbours(geometry.triangles.size());
    for (size_t i = 0; i < uses.size();) {
        size_t j = i;
        while (j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b) ++j;
        for (size_t p = i; p < j; ++p)
            for (size_t q = i; q < j; ++q)
                if (p != q && uses[p].triangle != uses[q].triangle)
                    neighbours[uses[p].triangle].push_back(uses[q].triangle);
        i = j;
    }
    return neighbours;
}

glm::dvec3 unitNormal(const StaticGeometry& geometry, const StaticTriangle& t) {
    const glm::dvec3 n = areaVector(geometry, t);
    const double length = glm::length(n);
    return length > 0.0 ? n / length : glm::dvec3(0.0, 0.0, 1.0);
}

/// A deterministic tangent frame for a plane normal.
void planeAxes(const glm::dvec3& n, glm::dvec3& u, glm::dvec3& v) {
    const glm::dvec3 a = std::abs(n.x) < 0.57   ? glm::dvec3(1, 0, 0)
                         : std::abs(n.y) < 0.57 ? glm::dvec3(0, 1, 0)
                                                : glm::dvec3(0, 0, 1);
    u = glm::normalize(glm::cross(a, n));
    v = glm::cross(n, u);
}

}  // namespace

std::vector<ChartShape> buildChartShapes(StaticGeometry& geometry, const ChartOptions& options) {
    std::vector<ChartShape> shapes;
    const double maxExtentTexels =
        static_cast<double>(options.atlasSize) - 2.0 * options.padding - 1.0;
    const double maxExtentMetres = maxExtentTexels / options.texelsPerMetre;
    const double cosLimit = std::cos(options.maxNormalAngleDegrees * std::numbers::pi / 180.0);

    // Authored: one chart per instance that has TEXCOORD_1.
    std::vector<uint32_t> authoredChart(geometry.instanceHasUv1.size(), kNoIndex);
    for (uint32_t t = 0; t < geometry.triangles.size(); ++t) {
        StaticTriangle& triangle = geometry.triangles[t];
        if (triangle.instance >= geometry.instanceHasUv1.size() ||
            !geometry.instanceHasUv1[triangle.instance])
            continue;
        uint32_t& chart = authoredChart[triangle.instance];
        if (chart == kNoIndex) {
            chart = static_cast<uint32_t>(shapes.size());
            ChartShape shape;
            shape.authored = true;
            shape.instance = triangle.instance;
            shapes.push_back(shape);
        }
        shapes[chart].triangles.push_back(t);
        triangle.chart = chart;
    }

    const std::vector<std::vector<uint32_t>> neighbours = edgeNeighbours(geometry);
    for (uint32_t seed = 0; seed < geometry.triangles.size(); ++seed) {
        if (geometry.triangles[seed].chart != kNoIndex) continue;
        ChartShape shape;
        shape.instance = geometry.triangles[seed].instance;
        shape.normal = unitNormal(geometry, geometry.triangles[seed]);
        planeAxes(shape.normal, shape.axisU, shape.axisV);
        const uint32_t chart = static_cast<uint32_t>(shapes.size());
        glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
        const auto project = [&](uint32_t t, glm::dvec2& tlo, glm::dvec2& thi) {
            tlo = lo;
            thi = hi;
            for (uint32_t id : geometry.triangles[t].v) {
                const glm::dvec3& p = geometry.vertices[id].position;
                const glm::dvec2 q(glm::dot(p, shape.axisU), glm::dot(p, shape.axisV));
                tlo = glm::min(tlo, q);
                thi = glm::max(thi, q);
            }
        };
        std::vector<uint32_t> queue{seed};
        geometry.triangles[seed].chart = chart;
        project(seed, lo, hi);
        const uint32_t primary = geometry.triangles[seed].primary;
        for (size_t head = 0; head < queue.size(); ++head) {
            const uint32_t t = queue[head];
            shape.triangles.push_back(t);
            for (uint32_t g : neighbours[t]) {
                const StaticTriangle& other = geometry.triangles[g];
                if (other.chart != kNoIndex || other.primary != primary ||
                    other.instance != shape.instance)
                    continue;
                if (glm::dot(unitNormal(geometry, other), shape.normal) < cosLimit) continue;
                glm::dvec2 glo, ghi;
                project(g, glo, ghi);
                if (ghi.x - glo.x > maxExtentMetres || ghi.y - glo.y > maxExtentMetres) continue;
                lo = glo;
                hi = ghi;
                geometry.triangles[g].chart = chart;
                queue.push_back(g);
            }
        }
        shape.minUv = lo;
        shape.maxUv = hi;
        // A single triangle larger than an atlas lowers its chart's density.
        const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
        shape.texelsPerMetre =
            std::min(options.texelsPerMetre,
                     extent > 0.0 ? maxExtentTexels / extent : options.texelsPerMetre);
        if (shapes.size() < options.densityScale.size())
            shape.texelsPerMetre *=
                std::clamp(double(options.densityScale[shapes.size()]), 1e-3, 1.0);
        shape.width = static_cast<uint32_t>(std::ceil((hi.x - lo.x) * shape.texelsPerMetre)) +
                      2 * options.padding;
        shape.height = static_cast<uint32_t>(std::ceil((hi.y - lo.y) * shape.texelsPerMetre)) +
                       2 * options.padding;
        shape.width = std::max(shape.width, 2 * options.padding + 1);
        shape.height = std::max(shape.height, 2 * options.padding + 1);
        shapes.push_back(std::move(shape));
    }
    return shapes;
}

}  // namespace onelight::world
