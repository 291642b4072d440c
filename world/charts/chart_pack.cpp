#include "world/charts/chart_pack.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace onelight::world {
namespace {

uint32_t nextPowerOfTwo(uint32_t v) {
    uint32_t p = 1;
    while (p < v && p < (1u << 30)) p <<= 1;
    return p;
}

/// Shelf packer over square atlases of one size.
struct ShelfPacker {
    uint32_t size;
    std::vector<Atlas>& atlases;
    uint32_t x = 0, y = 0, shelfHeight = 0;
    bool open = false;

    void place(uint32_t width, uint32_t height, uint32_t& atlas, uint32_t& px, uint32_t& py) {
        if (open && x + width > size) {
            y += shelfHeight;
            x = 0;
            shelfHeight = 0;
        }
        if (!open || y + height > size) {
            atlases.push_back({size, size});
            open = true;
            x = y = shelfHeight = 0;
        }
        atlas = static_cast<uint32_t>(atlases.size() - 1);
        px = x;
        py = y;
        x += width;
        shelfHeight = std::max(shelfHeight, height);
    }
    /// Trims the last atlas to the rows it uses (rounded up to a multiple of 4).
    void close() {
        if (!open) return;
        atlases.back().height = std::min(size, (y + shelfHeight + 3) / 4 * 4);
    }
};

}  // namespace

ChartLayout packCharts(StaticGeometry& geometry, const std::vector<ChartShape>& shapes,
                       const ChartOptions& options) {
    ChartLayout layout;
    layout.charts.resize(shapes.size());
    std::vector<uint32_t> order;
    for (uint32_t i = 0; i < shapes.size(); ++i)
        if (!shapes[i].authored) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return std::tie(shapes[b].height, shapes[b].width) <
               std::tie(shapes[a].height, shapes[a].width);
    });
    ShelfPacker packer{options.atlasSize, layout.atlases};
    for (uint32_t i : order) {
        const ChartShape& s = shapes[i];
        Chart& c = layout.charts[i];
        packer.place(s.width, s.height, c.atlas, c.x, c.y);
        c.width = s.width;
        c.height = s.height;
        c.padding = options.padding;
        c.texelsPerMetre = static_cast<float>(s.texelsPerMetre);
        c.axisU = glm::vec3(s.axisU);
        c.axisV = glm::vec3(s.axisV);
        const glm::dvec3 somePoint =
            geometry.vertices[geometry.triangles[s.triangles.front()].v[0]].position;
        const double plane = glm::dot(somePoint, s.normal);
        c.origin = glm::vec3(s.normal * plane + s.axisU * s.minUv.x + s.axisV * s.minUv.y);
    }
    packer.close();
    // Authored charts: a page each, sized from the mesh's area at the requested density.
    for (uint32_t i = 0; i < shapes.size(); ++i) {
        if (!shapes[i].authored) continue;
        double area = 0.0;
        for (uint32_t t : shapes[i].triangles)
            area += triangleArea(geometry, geometry.triangles[t]);
        const double side = std::ceil(std::sqrt(area) * options.texelsPerMetre);
        const uint32_t size = std::clamp(
            nextPowerOfTwo(static_cast<uint32_t>(std::min(side, 65536.0))), 16u, options.atlasSize);
        layout.atlases.push_back({size, size});
        Chart& c = layout.charts[i];
        c.atlas = static_cast<uint32_t>(layout.atlases.size() - 1);
        c.x = c.y = 0;
        c.width = c.height = size;
        c.padding = 0;
        c.authored = true;
        c.texelsPerMetre = static_cast<float>(area > 0.0 ? size / std::sqrt(area) : 0.0);
    }

    // Give each vertex one chart, then its lightmap coordinates.
    std::vector<uint32_t> vertexChart(geometry.vertices.size(), kNoIndex);
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> copies;
    double texelArea = 0.0;
    for (StaticTriangle& t : geometry.triangles) {
        const ChartShape& s = shapes[t.chart];
        const Chart& c = layout.charts[t.chart];
        const Atlas& atlas = layout.atlases[c.atlas];
        glm::dvec2 texel[3];
        for (size_t k = 0; k < 3; ++k) {
            uint32_t& id = t.v[k];
            if (vertexChart[id] == kNoIndex) {
                vertexChart[id] = t.chart;
            } else if (vertexChart[id] != t.chart) {
                const auto [it, inserted] = copies.emplace(
                    std::make_pair(id, t.chart), static_cast<uint32_t>(geometry.vertices.size()));
                if (inserted) {
                    geometry.vertices.push_back(geometry.vertices[id]);
                    vertexChart.push_back(t.chart);
                }
                id = it->second;
            }
            CompileVertex& v = geometry.vertices[id];
            if (s.authored) {
                texel[k] = glm::dvec2(v.uv1) * glm::dvec2(atlas.width, atlas.height);
                continue;
            }
            const glm::dvec2 q(glm::dot(v.position, s.axisU) - s.minUv.x,
                               glm::dot(v.position, s.axisV) - s.minUv.y);
            texel[k] = glm::dvec2(c.x + c.padding, c.y + c.padding) + q * s.texelsPerMetre;
            v.uv1 = glm::vec2(texel[k] / glm::dvec2(atlas.width, atlas.height));
        }
        const glm::dvec2 e1 = texel[1] - texel[0], e2 = texel[2] - texel[0];
        texelArea += 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x);
    }
    for (const Atlas& a : layout.atlases) layout.texelCount += uint64_t(a.width) * a.height;
    layout.fillRatio =
        layout.texelCount > 0 ? texelArea / static_cast<double>(layout.texelCount) : 0.0;
    return layout;
}

ChartLayout buildLightmapCharts(StaticGeometry& geometry, const ChartOptions& options) {
    const std::vector<ChartShape> shapes = buildChartShapes(geometry, options);
    return packCharts(geometry, shapes, options);
}

}  // namespace onelight::world
