#include <gtest/gtest.h>

#include <cmath>

#include "shading.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/compile/static_split.hpp"
#include "world/import/gltf_import.hpp"
#include "world/regions/region_split.hpp"

namespace onelight::test {
namespace {

using namespace onelight::world;

StaticGeometry floorGeometry(int cells, double size) {
    GltfBuilder gltf;
    gltf.addNode({{"name", "floor"}, {"mesh", gltf.addMesh(gridMesh("floor", cells, size, 0.0))}});
    const SourceLevel source = importGltf(gltf.write(freshFolder("regions"), "regions"));
    return splitStaticDynamic(source).staticGeometry;
}

Light pointLight(glm::vec3 position, float intensity) {
    Light l;
    l.type = LightType::kPoint;
    l.position = position;
    l.intensity = intensity;
    return l;
}

/// Two equal lamps at x = -5 and x = +5: the dominant primary switches on the plane x = 0.
PrimaryIlluminanceFn twoLamps() {
    return makeUnshadowedPrimaryIlluminance(
        {pointLight({-5, 2, 0}, 100), pointLight({5, 2, 0}, 100)});
}

/// The shaders' light model (shaders/lighting.glsl, evaluatePunctualLight) on a surface facing
/// unit `n`, in luminance: what the runtime shader and the baker evaluate.
double shaderIlluminance(const Light& l, glm::vec3 p, glm::vec3 n) {
    const glsl::LightSample s =
        glsl::evaluatePunctualLight(int(l.type), l.color, l.intensity, l.range, l.position,
                                    l.direction, std::cos(l.innerCone), std::cos(l.outerCone), p);
    return double(glsl::luminance(s.illuminance) * glsl::max(0.0f, glm::dot(n, s.l)));
}

TEST(Regions, UnshadowedIlluminanceIsTheShadersLightModel) {
    // A hard-edged spot: its cone cosines differ by about 2e-4, less than the shader's floor of
    // 0.001 on that difference (an older copy of the model in the compile floored at 1e-4, and
    // so could pick another dominant primary than the bake near the cone's edge).
    Light spot;
    spot.type = LightType::kSpot;
    spot.position = glm::vec3(0, 4, 0);
    spot.direction = glm::vec3(0, -1, 0);
    spot.color = glm::vec3(1.0f, 0.8f, 0.6f);
    spot.intensity = 500.0f;
    spot.range = 20.0f;
    spot.innerCone = 0.5f;
    spot.outerCone = 0.5004f;
    Light bulb = spot;  // the spot without its cone
    bulb.type = LightType::kPoint;
    Light point = pointLight({-3, 2, 1}, 80.0f);
    point.range = 6.0f;
    Light sun;
    sun.type = LightType::kDirectional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    sun.color = glm::vec3(1.0f, 0.9f, 0.7f);
    sun.intensity = 2000.0f;
    const PrimaryIlluminanceFn compile = makeUnshadowedPrimaryIlluminance({spot, point, sun, bulb});
    const glm::vec3 up(0, 1, 0);
    // Floor points at angles from the spot's axis inside the cone, across its edge and beyond.
    const float offsets[] = {-0.3f, -0.01f,  -0.001f, -0.0004f, -0.0002f, -0.0001f,
                             0.0f,  0.0001f, 0.0002f, 0.001f,   0.01f,    0.3f};
    int edgeSamples = 0;
    for (const float offset : offsets) {
        const float angle = spot.outerCone + offset;
        const glm::vec3 p(4.0f * std::tan(angle), 0.0f, 0.0f);
        double e[4];
        compile(glm::dvec3(p), up, e);
        EXPECT_EQ(e[0], shaderIlluminance(spot, p, up)) << "spot at offset " << offset;
        EXPECT_EQ(e[1], shaderIlluminance(point, p, up)) << "point at offset " << offset;
        EXPECT_EQ(e[2], shaderIlluminance(sun, p, up)) << "sun at offset " << offset;
        if (offset >= 0.0f) {
            EXPECT_EQ(e[0], 0.0) << "outside the cone at offset " << offset;
        }
        if (offset > -0.0004f && offset < 0.0f) {
            // Between the cones: a small part of the beam, where the old floor gave 1/4 or more.
            EXPECT_GT(e[0], 0.0);
            EXPECT_LT(e[0], 0.1 * e[3]) << "at offset " << offset;
            ++edgeSamples;
        }
    }
    EXPECT_EQ(edgeSamples, 2);
    // The point light beyond its range, and a zero normal (no cosine term).
    double e[4];
    compile(glm::dvec3(-3, -5, 1), glm::vec3(0.0f), e);
    EXPECT_EQ(e[1], 0.0);
    const glm::vec3 q(1.0f, 0.0f, 2.0f);
    compile(glm::dvec3(q), glm::vec3(0.0f), e);
    EXPECT_EQ(e[1],
              double(glsl::luminance(glsl::evaluatePunctualLight(
                                         int(point.type), point.color, point.intensity, point.range,
                                         point.position, point.direction, 1.0f, 1.0f, q)
                                         .illuminance)));
    EXPECT_EQ(e[2], double(glsl::luminance(sun.color * sun.intensity)));
}

TEST(Regions, SplittingNeverLosesArea) {
    StaticGeometry geometry = floorGeometry(7, 20.0);  // odd: cell edges straddle x = 0
    const double before = totalArea(geometry);
    RegionOptions options;
    options.minFragmentArea = 0.0;
    const RegionStats stats = assignPrimaryRegions(geometry, 2, twoLamps(), options);
    EXPECT_GT(stats.edgesCut, 0u);
    EXPECT_GT(stats.trianglesAdded, 0u);
    EXPECT_NEAR(totalArea(geometry), before, 1e-6 * before);
}

TEST(Regions, NoTriangleStraddlesTwoPrimaries) {
    StaticGeometry geometry = floorGeometry(7, 20.0);
    RegionOptions options;
    options.minFragmentArea = 0.0;
    const PrimaryIlluminanceFn light = twoLamps();
    assignPrimaryRegions(geometry, 2, light, options);
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
            if (std::abs(p.x) < 2.0 * options.boundaryTolerance) continue;  // on the switch line
            light(p, glm::vec3(0, 1, 0), e);
            ASSERT_EQ(dominantPrimary(e), t.primary) << "at x = " << p.x;
        }
    }
    EXPECT_GT(owned[0], 0);
    EXPECT_GT(owned[1], 0);
}

TEST(Regions, RegionInsideOneTriangleIsFound) {
    StaticGeometry geometry = floorGeometry(1, 40.0);  // two big triangles
    Light spot;
    spot.type = LightType::kSpot;
    spot.position = glm::vec3(3, 5, 2);
    spot.direction = glm::vec3(0, -1, 0);
    spot.intensity = 1e5f;
    spot.outerCone = 0.5f;
    spot.innerCone = 0.1f;
    Light sun;
    sun.type = LightType::kDirectional;
    sun.direction = glm::vec3(0, -1, 0);
    sun.intensity = 1000.0f;
    const double before = totalArea(geometry);
    RegionOptions options;
    options.minFragmentArea = 0.0;
    const RegionStats stats =
        assignPrimaryRegions(geometry, 2, makeUnshadowedPrimaryIlluminance({sun, spot}), options);
    EXPECT_GT(stats.facesCentreSplit + stats.edgesCut, 0u);
    double spotArea = 0.0;
    for (const StaticTriangle& t : geometry.triangles)
        if (t.primary == 1) spotArea += triangleArea(geometry, t);
    EXPECT_GT(spotArea, 0.0);
    EXPECT_NEAR(totalArea(geometry), before, 1e-6 * before);
}

TEST(Regions, TinyFragmentsMergeIntoTheirNeighbour) {
    StaticGeometry geometry = floorGeometry(7, 20.0);
    RegionOptions options;
    options.minFragmentArea = 1e4;  // every fragment is "tiny": all merge into one primary
    const RegionStats stats = assignPrimaryRegions(geometry, 2, twoLamps(), options);
    EXPECT_GT(stats.fragmentsMerged, 0u);
    for (const StaticTriangle& t : geometry.triangles)
        ASSERT_EQ(t.primary, geometry.triangles[0].primary);
}

TEST(Regions, GivenUpListsTheOtherPrimaries) {
    StaticGeometry geometry = floorGeometry(4, 20.0);
    assignPrimaryRegions(geometry, 2, twoLamps(), {});
    const std::vector<uint32_t> givenUp = givenUpPrimaries(
        geometry, geometry.triangles, geometry.triangles[0].primary, 2, twoLamps());
    ASSERT_EQ(givenUp.size(), 1u);
    EXPECT_NE(givenUp[0], geometry.triangles[0].primary);
}

TEST(Regions, NoPrimariesMeansNoAssignment) {
    StaticGeometry geometry = floorGeometry(2, 4.0);
    const size_t count = geometry.triangles.size();
    assignPrimaryRegions(geometry, 0, makeUnshadowedPrimaryIlluminance({}), {});
    ASSERT_EQ(geometry.triangles.size(), count);
    for (const StaticTriangle& t : geometry.triangles) EXPECT_EQ(t.primary, kNoIndex);
}

TEST(Regions, UnlitSurfacesStillGetAPrimary) {
    StaticGeometry geometry = floorGeometry(2, 4.0);
    // The lamp is below the floor: its cosine term is zero everywhere.
    assignPrimaryRegions(geometry, 1,
                         makeUnshadowedPrimaryIlluminance({pointLight({0, -3, 0}, 10)}), {});
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
    geometry.instanceHasUv1 = {0};
    geometry.instanceNames = {"fin"};
    for (const std::array<uint32_t, 3>& t :
         {std::array<uint32_t, 3>{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}) {
        StaticTriangle tri;
        tri.v = t;
        tri.material = 0;
        tri.instance = 0;
        geometry.triangles.push_back(tri);
    }
    const double before = totalArea(geometry);
    RegionOptions options;
    options.minFragmentArea = 0.0;
    assignPrimaryRegions(geometry, 2, twoLamps(), options);
    EXPECT_NEAR(totalArea(geometry), before, 1e-9);
    for (const StaticTriangle& t : geometry.triangles) EXPECT_LT(t.primary, 2u);
}

}  // namespace
}  // namespace onelight::test
