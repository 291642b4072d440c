#include "world/charts/chart_pack.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace onelight::world {
namespace {

uint32_t next_power_of_two(uint32_t v) {
    uint32_t p = 1;
    while (p < v && p < (1u << 30)) p <<= 1;
    return p;
}

/// Shelf packer over square atlases of one size.
struct ShelfPacker {
    uint32_t size;
    std::vector<Atlas>& atlases;
    uint32_t x = 0, y = 0, shelf_height = 0;
    bool open = false;

    void place(uint32_t width, uint32_t height, uint32_t& atlas, uint32_t& px, uint32_t& py) {
        if (open && x + width > size) {
            y += shelf_height;
            x = 0;
            shelf_height = 0;
        }
        if (!open || y + height > size) {
            atlases.push_back({size, size});
            open = true;
            x = y = shelf_height = 0;
        }
        atlas = static_cast<uint32_t>(atlases.size() - 1);
        px = x;
        py = y;
        x += width;
        shelf_height = std::max(shelf_height, height);
    }
    /// Trims the last atlas to the rows it uses (rounded up to a multiple of 4).
    void close() {
        if (!open) return;
        atlases.back().height = std::min(size, (y + shelf_height + 3) / 4 * 4);
    }
};

}  // namespace

ChartLayout pack_charts(StaticGeometry& geometry, const std::vector<ChartShape>& shapes,
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
    ShelfPacker packer{options.atlas_size, layout.atlases};
    for (uint32_t i : order) {
        const ChartShape& s = shapes[i];
        Chart& c = layout.charts[i];
        packer.place(s.width, s.height, c.atlas, c.x, c.y);
        c.width = s.width;
        c.height = s.height;
        c.padding = options.padding;
        c.texels_per_metre = static_cast<float>(s.texels_per_metre);
        c.axis_u = glm::vec3(s.axis_u);
        c.axis_v = glm::vec3(s.axis_v);
        const glm::dvec3 some_point =
            geometry.vertices[geometry.triangles[s.triangles.front()].v[0]].position;
        const double plane = glm::dot(some_point, s.normal);
        c.origin = glm::vec3(s.normal * plane + s.axis_u * s.min_uv.x + s.axis_v * s.min_uv.y);
    }
    packer.close();
    // Authored charts: a page each, sized from the mesh's area at the requested density.
    for (uint32_t i = 0; i < shapes.size(); ++i) {
        if (!shapes[i].authored) continue;
        double area = 0.0;
        for (uint32_t t : shapes[i].triangles)
            area += triangle_area(geometry, geometry.triangles[t]);
        const double side = std::ceil(std::sqrt(area) * options.texels_per_metre);
        const uint32_t size =
            std::clamp(next_power_of_two(static_cast<uint32_t>(std::min(side, 65536.0))), 16u,
                       options.atlas_size);
        layout.atlases.push_back({size, size});
        Chart& c = layout.charts[i];
        c.atlas = static_cast<uint32_t>(layout.atlases.size() - 1);
        c.x = c.y = 0;
        c.width = c.height = size;
        c.padding = 0;
        c.authored = true;
        c.texels_per_metre = static_cast<float>(area > 0.0 ? size / std::sqrt(area) : 0.0);
    }

    // Give each vertex one chart, then its lightmap coordinates.
    std::vector<uint32_t> vertex_chart(geometry.vertices.size(), kNoIndex);
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> copies;
    double texel_area = 0.0;
    for (StaticTriangle& t : geometry.triangles) {
        const ChartShape& s = shapes[t.chart];
        const Chart& c = layout.charts[t.chart];
        const Atlas& atlas = layout.atlases[c.atlas];
        glm::dvec2 texel[3];
        for (size_t k = 0; k < 3; ++k) {
            uint32_t& id = t.v[k];
            if (vertex_chart[id] == kNoIndex) {
                vertex_chart[id] = t.chart;
            } else if (vertex_chart[id] != t.chart) {
                const auto [it, inserted] = copies.emplace(
                    std::make_pair(id, t.chart), static_cast<uint32_t>(geometry.vertices.size()));
                if (inserted) {
                    geometry.vertices.push_back(geometry.vertices[id]);
                    vertex_chart.push_back(t.chart);
                }
                id = it->second;
            }
            CompileVertex& v = geometry.vertices[id];
            if (s.authored) {
                texel[k] = glm::dvec2(v.uv1) * glm::dvec2(atlas.width, atlas.height);
                continue;
            }
            const glm::dvec2 q(glm::dot(v.position, s.axis_u) - s.min_uv.x,
                               glm::dot(v.position, s.axis_v) - s.min_uv.y);
            texel[k] = glm::dvec2(c.x + c.padding, c.y + c.padding) + q * s.texels_per_metre;
            v.uv1 = glm::vec2(texel[k] / glm::dvec2(atlas.width, atlas.height));
        }
        const glm::dvec2 e1 = texel[1] - texel[0], e2 = texel[2] - texel[0];
        texel_area += 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x);
    }
    for (const Atlas& a : layout.atlases) layout.texel_count += uint64_t(a.width) * a.height;
    layout.fill_ratio =
        layout.texel_count > 0 ? texel_area / static_cast<double>(layout.texel_count) : 0.0;
    return layout;
}

ChartLayout build_lightmap_charts(StaticGeometry& geometry, const ChartOptions& options) {
    const std::vector<ChartShape> shapes = build_chart_shapes(geometry, options);
    return pack_charts(geometry, shapes, options);
}

}  // namespace onelight::world
