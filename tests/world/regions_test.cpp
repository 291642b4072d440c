#include <gtest/gtest.h>

#include "tests/world/world_test_support.hpp"
#include "world/compile/static_split.hpp"
#include "world/import/gltf_import.hpp"
#include "world/regions/region_split.hpp"

namespace onelight::test {
namespace {

using namespace onelight::world;

StaticGeometry floor_geometry(int cells, double size) {
    GltfBuilder gltf;
    gltf.add_node(
        {{"name", "floor"}, {"mesh", gltf.add_mesh(grid_mesh("floor", cells, size, 0.0))}});
    const SourceLevel source = import_gltf(gltf.write(fresh_folder("regions"), "regions"));
    return split_static_dynamic(source).static_geometry;
}

Light point_light(glm::vec3 position, float intensity) {
    Light l;
    l.type = LightType::point;
    l.position = position;
    l.intensity = intensity;
    return l;
}

/// Two equal lamps at x = -5 and x = +5: the dominant primary switches on the plane x = 0.
PrimaryIlluminanceFn two_lamps() {
    return make_unshadowed_primary_illuminance(
        {point_light({-5, 2, 0}, 100), point_light({5, 2, 0}, 100)});
}

TEST(Regions, SplittingNeverLosesArea) {
    StaticGeometry geometry = floor_geometry(7, 20.0);  // odd: cell edges straddle x = 0
    const double before = total_area(geometry);
    RegionOptions options;
    options.min_fragment_area = 0.0;
    const RegionStats stats = assign_primary_regions(geometry, 2, two_lamps(), options);
    EXPECT_GT(stats.edges_cut, 0u);
    EXPECT_GT(stats.triangles_added, 0u);
    EXPECT_NEAR(total_area(geometry), before, 1e-6 * before);
}

TEST(Regions, NoTriangleStraddlesTwoPrimaries) {
    StaticGeometry geometry = floor_geometry(7, 20.0);
    RegionOptions options;
    options.min_fragment_area = 0.0;
    const PrimaryIlluminanceFn light = two_lamps();
    assign_primary_regions(geometry, 2, light, options);
    std::vector<double> e(2);
    const double bary[4][3] = {
        {0.6, 0.2, 0.2}, {0.2, 0.6, 0.2}, {0.2, 0.2, 0.6}, {1 / 3.0, 1 / 3.0, 1 / 3.0}};
    int owned[2] = {0, 0};
    for (const StaticTriangle& t : geometry.triangles) {
        ASSERT_LT(t.primary, 2u);
        ++owned[t.primary];
        for (const auto& w : bary) {
            const glm::dvec3 p = w[0] * geometry.vertices[t.v[0]].position +
                                 w[1] * geometry.vertices[t.v[1]].position +
                                 w[2] * geometry.vertices[t.v[2]].position;
            if (std::abs(p.x) < 2.0 * options.boundary_tolerance) continue;  // on the switch line
            light(p, glm::vec3(0, 1, 0), e);
            ASSERT_EQ(dominant_primary(e), t.primary) << "at x = " << p.x;
        }
    }
    EXPECT_GT(owned[0], 0);
    EXPECT_GT(owned[1], 0);
}

TEST(Regions, RegionInsideOneTriangleIsFound) {
    StaticGeometry geometry = floor_geometry(1, 40.0);  // two big triangles
    Light spot;
    spot.type = LightType::spot;
    spot.position = glm::vec3(3, 5, 2);
    spot.direction = glm::vec3(0, -1, 0);
    spot.intensity = 1e5f;
    spot.outer_cone = 0.5f;
    spot.inner_cone = 0.1f;
    Light sun;
    sun.type = LightType::directional;
    sun.direction = glm::vec3(0, -1, 0);
    sun.intensity = 1000.0f;
    const double before = total_area(geometry);
    RegionOptions options;
    options.min_fragment_area = 0.0;
    const RegionStats stats = assign_primary_regions(
        geometry, 2, make_unshadowed_primary_illuminance({sun, spot}), options);
    EXPECT_GT(stats.faces_centre_split + stats.edges_cut, 0u);
    double spot_area = 0.0;
    for (const StaticTriangle& t : geometry.triangles)
        if (t.primary == 1) spot_area += triangle_area(geometry, t);
    EXPECT_GT(spot_area, 0.0);
    EXPECT_NEAR(total_area(geometry), before, 1e-6 * before);
}

TEST(Regions, TinyFragmentsMergeIntoTheirNeighbour) {
    StaticGeometry geometry = floor_geometry(7, 20.0);
    RegionOptions options;
    options.min_fragment_area = 1e4;  // every fragment is "tiny": all merge into one primary
    const RegionStats stats = assign_primary_regions(geometry, 2, two_lamps(), options);
    EXPECT_GT(stats.fragments_merged, 0u);
    for (const StaticTriangle& t : geometry.triangles)
        ASSERT_EQ(t.primary, geometry.triangles[0].primary);
}

TEST(Regions, GivenUpListsTheOtherPrimaries) {
    StaticGeometry geometry = floor_geometry(4, 20.0);
    assign_primary_regions(geometry, 2, two_lamps(), {});
    const std::vector<uint32_t> given_up = given_up_primaries(
        geometry, geometry.triangles, geometry.triangles[0].primary, 2, two_lamps());
    ASSERT_EQ(given_up.size(), 1u);
    EXPECT_NE(given_up[0], geometry.triangles[0].primary);
}

TEST(Regions, NoPrimariesMeansNoAssignment) {
    StaticGeometry geometry = floor_geometry(2, 4.0);
    const size_t count = geometry.triangles.size();
    assign_primary_regions(geometry, 0, make_unshadowed_primary_illuminance({}), {});
    ASSERT_EQ(geometry.triangles.size(), count);
    for (const StaticTriangle& t : geometry.triangles) EXPECT_EQ(t.primary, kNoIndex);
}

TEST(Regions, UnlitSurfacesStillGetAPrimary) {
    StaticGeometry geometry = floor_geometry(2, 4.0);
    // The lamp is below the floor: its cosine term is zero everywhere.
    assign_primary_regions(geometry, 1,
                           make_unshadowed_primary_illuminance({point_light({0, -3, 0}, 10)}), {});
    for (const StaticTriangle& t : geometry.triangles) EXPECT_EQ(t.primary, 0u);
}

TEST(Regions, NonManifoldFinKeepsArea) {
    StaticGeometry geometry;
    const glm::dvec3 p[5] = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    for (const glm::dvec3& q : p) {
        CompileVertex v;
        v.position = q;
        v.normal = glm::vec3(0, 0, 1);
        geometry.vertices.push_back(v);
    }
    geometry.instance_has_uv1 = {0};
    geometry.instance_names = {"fin"};
    for (const std::array<uint32_t, 3>& t :
         {std::array<uint32_t, 3>{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}) {
        StaticTriangle tri;
        tri.v = t;
        tri.material = 0;
        tri.instance = 0;
        geometry.triangles.push_back(tri);
    }
    const double before = total_area(geometry);
    RegionOptions options;
    options.min_fragment_area = 0.0;
    assign_primary_regions(geometry, 2, two_lamps(), options);
    EXPECT_NEAR(total_area(geometry), before, 1e-9);
    for (const StaticTriangle& t : geometry.triangles) EXPECT_LT(t.primary, 2u);
}

}  // namespace
}  // namespace onelight::test
