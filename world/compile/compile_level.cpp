#include "world/compile/compile_level.hpp"

#include <algorithm>
#include <chrono>
#include <numeric>

#include "world/compile/static_split.hpp"
#include "world/features/feature_analysis.hpp"

namespace onelight::world {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

void grow(glm::vec3& lo, glm::vec3& hi, const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
}

Vertex to_vertex(const CompileVertex& v) {
    Vertex out;
    out.position = glm::vec3(v.position);
    out.normal = v.normal;
    out.tangent = v.tangent;
    out.uv0 = v.uv0;
    out.uv1 = v.uv1;
    return out;
}

/// Leaf by leaf: triangles sorted by (material, primary, chart) and grouped into surfaces;
/// vertices compacted in order of first use.
void build_surfaces(const StaticGeometry& geometry, const BspBuild& bsp,
                    const std::vector<uint32_t>& light_of_primary, uint32_t primary_count,
                    const PrimaryIlluminanceFn& illuminance, const ChartLayout& charts,
                    CompiledLevel& level) {
    std::vector<uint32_t> new_index(geometry.vertices.size(), kNoIndex);
    level.bsp_leaves = bsp.leaves;
    for (size_t leaf = 0; leaf < level.bsp_leaves.size(); ++leaf) {
        BspLeaf& l = level.bsp_leaves[leaf];
        std::vector<uint32_t> order(l.triangle_count);
        std::iota(order.begin(), order.end(), l.first_triangle);
        std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
            const StaticTriangle &x = geometry.triangles[a], &y = geometry.triangles[b];
            return std::tie(x.material, x.primary, x.chart) <
                   std::tie(y.material, y.primary, y.chart);
        });
        l.first_surface = static_cast<uint32_t>(level.surfaces.size());
        l.bounds_min = glm::vec3(INFINITY);
        l.bounds_max = glm::vec3(-INFINITY);
        for (size_t i = 0; i < order.size();) {
            const StaticTriangle& first = geometry.triangles[order[i]];
            size_t j = i;
            Surface s;
            s.first_index = static_cast<uint32_t>(level.indices.size());
            s.material = first.material;
            s.primary_light = first.primary == kNoIndex ? kNoIndex : light_of_primary[first.primary];
            s.chart = first.chart;
            const Chart& c = charts.charts[first.chart];
            s.atlas = c.atlas;
            s.lightmap_x = c.x;
            s.lightmap_y = c.y;
            s.lightmap_width = c.width;
            s.lightmap_height = c.height;
            s.leaf = static_cast<uint32_t>(leaf);
            s.bounds_min = glm::vec3(INFINITY);
            s.bounds_max = glm::vec3(-INFINITY);
            std::vector<StaticTriangle> members;
            for (; j < order.size(); ++j) {
                const StaticTriangle& t = geometry.triangles[order[j]];
                if (t.material != first.material || t.primary != first.primary ||
                    t.chart != first.chart)
                    break;
                members.push_back(t);
                for (uint32_t id : t.v) {
                    if (new_index[id] == kNoIndex) {
                        new_index[id] = static_cast<uint32_t>(level.vertices.size());
                        level.vertices.push_back(to_vertex(geometry.vertices[id]));
                    }
                    level.indices.push_back(new_index[id]);
                    grow(s.bounds_min, s.bounds_max, level.vertices[new_index[id]].position);
                }
            }
            s.index_count = static_cast<uint32_t>(level.indices.size()) - s.first_index;
            if (primary_count > 0) {
                s.first_given_up = static_cast<uint32_t>(level.given_up_lights.size());
                for (uint32_t p : given_up_primaries(geometry, members, first.primary,
                                                     primary_count, illuminance))
                    level.given_up_lights.push_back(light_of_primary[p]);
                s.given_up_count =
                    static_cast<uint32_t>(level.given_up_lights.size()) - s.first_given_up;
            } else {
                s.first_given_up = static_cast<uint32_t>(level.given_up_lights.size());
            }
            grow(l.bounds_min, l.bounds_max, s.bounds_min);
            grow(l.bounds_min, l.bounds_max, s.bounds_max);
            level.surfaces.push_back(s);
            i = j;
        }
        l.surface_count = static_cast<uint32_t>(level.surfaces.size()) - l.first_surface;
        if (l.triangle_count == 0) l.bounds_min = l.bounds_max = glm::vec3(0.0f);
    }
}

void bound_nodes(CompiledLevel& level) {
    // Children have larger indices than their parent: fill from the back.
    for (size_t i = level.bsp_nodes.size(); i-- > 0;) {
        BspNode& n = level.bsp_nodes[i];
        n.bounds_min = glm::vec3(INFINITY);
        n.bounds_max = glm::vec3(-INFINITY);
        for (int32_t child : {n.front, n.back}) {
            glm::vec3 lo, hi;
            bool empty;
            if (child >= 0) {
                const BspNode& c = level.bsp_nodes[static_cast<size_t>(child)];
                lo = c.bounds_min;
                hi = c.bounds_max;
                empty = lo.x > hi.x;
            } else {
                const BspLeaf& c = level.bsp_leaves[static_cast<size_t>(-child - 1)];
                lo = c.bounds_min;
                hi = c.bounds_max;
                empty = c.triangle_count == 0;
            }
            if (!empty) {
                grow(n.bounds_min, n.bounds_max, lo);
                grow(n.bounds_min, n.bounds_max, hi);
            }
        }
        if (n.bounds_min.x > n.bounds_max.x) n.bounds_min = n.bounds_max = glm::vec3(0.0f);
    }
}

}  // namespace

CompileResult compile_level(const SourceLevel& source, const CompileOptions& options,
                            const PrimaryIlluminanceFn* illuminance) {
    CompileResult result;
    CompileStats& stats = result.stats;
    CompiledLevel& level = result.level;

    Clock::time_point start = Clock::now();
    SplitLevel split = split_static_dynamic(source);
    StaticGeometry& geometry = split.static_geometry;
    stats.degenerate_removed = split.degenerate_removed;
    stats.duplicates_removed = split.duplicates_removed;
    stats.source_triangles =
        geometry.triangles.size() + split.degenerate_removed + split.duplicates_removed;
    stats.dynamic_triangles = split.dynamic_indices.size() / 3;
    stats.seconds_split = seconds_since(start);

    std::vector<Light> primaries;
    std::vector<uint32_t> light_of_primary;
    for (size_t i = 0; i < source.lights.size(); ++i) {
        if (source.lights[i].role != LightRole::primary) continue;
        primaries.push_back(source.lights[i]);
        light_of_primary.push_back(static_cast<uint32_t>(i));
    }
    const uint32_t primary_count = static_cast<uint32_t>(primaries.size());
    stats.primary_candidates = primary_count;
    const PrimaryIlluminanceFn unshadowed = make_unshadowed_primary_illuminance(primaries);
    const PrimaryIlluminanceFn& light_at = illuminance ? *illuminance : unshadowed;

    start = Clock::now();
    stats.regions = assign_primary_regions(geometry, primary_count, light_at, options.regions);
    stats.seconds_regions = seconds_since(start);

    start = Clock::now();
    ChartOptions chart_options = options.charts;
    if (source.texels_per_metre > 0.0f && !chart_options.density_from_command_line)
        chart_options.texels_per_metre = source.texels_per_metre;
    const ChartLayout charts = build_lightmap_charts(geometry, chart_options);
    stats.seconds_charts = seconds_since(start);

    start = Clock::now();
    const BspBuild bsp = build_bsp(geometry, options.bsp);
    stats.seconds_bsp = seconds_since(start);

    start = Clock::now();
    level.materials = source.materials;
    level.textures = source.textures;
    level.images = source.images;
    level.lights = source.lights;
    level.cameras = source.cameras;
    level.charts = charts.charts;
    level.atlases = charts.atlases;
    level.bsp_planes = bsp.planes;
    level.bsp_nodes = bsp.nodes;
    build_surfaces(geometry, bsp, light_of_primary, primary_count, light_at, charts, level);
    bound_nodes(level);
    level.dynamic_vertices = std::move(split.dynamic_vertices);
    level.dynamic_indices = std::move(split.dynamic_indices);
    level.dynamic_meshes = std::move(split.dynamic_meshes);
    level.entities = std::move(split.entities);

    LevelSettings& settings = level.settings;
    settings.exposure_ev100 = source.exposure_ev100;
    settings.has_exposure = source.has_exposure;
    settings.texels_per_metre = static_cast<float>(chart_options.texels_per_metre);
    settings.probe_spacing = source.probe_spacing;
    settings.sky_radiance = source.sky_radiance;
    if (!level.vertices.empty()) {
        settings.bounds_min = glm::vec3(INFINITY);
        settings.bounds_max = glm::vec3(-INFINITY);
        for (const Vertex& v : level.vertices)
            grow(settings.bounds_min, settings.bounds_max, v.position);
    }
    level.features =
        analyse_features(level, source.has_grid_bounds, source.grid_min, source.grid_max);
    stats.seconds_surfaces = seconds_since(start);

    stats.triangles = level.indices.size() / 3;
    stats.surfaces = level.surfaces.size();
    stats.bsp_depth = bsp.depth;
    stats.bsp_leaves = bsp.leaves.size();
    stats.bsp_nodes = bsp.nodes.size();
    stats.bsp_splits = bsp.splits;
    std::vector<uint8_t> used(source.lights.size(), 0);
    for (const Surface& s : level.surfaces)
        if (s.primary_light != kNoIndex) used[s.primary_light] = 1;
    stats.primaries_used = static_cast<uint32_t>(std::count(used.begin(), used.end(), 1));
    stats.charts = charts.charts.size();
    stats.authored_charts = static_cast<uint64_t>(std::count_if(
        charts.charts.begin(), charts.charts.end(), [](const Chart& c) { return c.authored; }));
    stats.atlases = charts.atlases.size();
    stats.texels = charts.texel_count;
    stats.fill_ratio = charts.fill_ratio;
    return result;
}

}  // namespace onelight::world
