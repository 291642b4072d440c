// Emissive surfaces are lights (bake/lighting/emitters.hpp): next-event estimation of emissive
// triangles by power, combined with the gathering directions by multiple importance sampling,
// against the closed forms of a differential area facing a rectangle and a disk.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bake/embree/bake_scene.hpp"
#include "bake/grid/light_grid.hpp"
#include "bake/lighting/radiance.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "bake/reference/path_tracer.hpp"
#include "bake_scenes.hpp"
#include "world/compile/static_split.hpp"

namespace onelight::bake {
namespace {

constexpr double kPiD = 3.14159265358979323846;

// View factor from a differential area to a parallel rectangle [0, a] x [0, b] at height c with
// a corner straight above it (Howell, "A Catalog of Radiation Heat Transfer Configuration
// Factors", B-3):  F = 1/(2 pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2)
// atan(A/sqrt(1+B^2))]
double cornerFactor(double a, double b, double c) {
    const double A = a / c, B = b / c;
    const double sa = std::sqrt(1.0 + A * A), sb = std::sqrt(1.0 + B * B);
    return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2.0 * kPiD);
}
double signedCorner(double x, double y, double c) {
    return (x < 0.0 ? -1.0 : 1.0) * (y < 0.0 ? -1.0 : 1.0) *
           cornerFactor(std::fabs(x), std::fabs(y), c);
}
// Irradiance at (px, pz) on the floor from a Lambertian rectangle [x0, x1] x [z0, z1] of
// luminance L at height c: pi L F, F by superposition of the four corner rectangles.
double rectangleIrradiance(double L, double x0, double x1, double z0, double z1, double c,
                           double px, double pz) {
    x0 -= px, x1 -= px, z0 -= pz, z1 -= pz;
    const double f = signedCorner(x1, z1, c) - signedCorner(x0, z1, c) - signedCorner(x1, z0, c) +
                     signedCorner(x0, z0, c);
    return kPiD * L * f;
}
// Irradiance at radial offset r on a plane parallel to a Lambertian disk of radius R and
// luminance L at height h (Howell B-13): E = (pi L / 2) (1 - (h^2 + r^2 - R^2) /
// sqrt((h^2 + r^2 + R^2)^2 - 4 r^2 R^2)).
double diskIrradiance(double L, double R, double h, double r) {
    const double s = h * h + r * r + R * R;
    return 0.5 * kPiD * L *
           (1.0 - (h * h + r * r - R * R) / std::sqrt(s * s - 4.0 * r * r * R * R));
}

// A 2 x 2 m floor at y = 0 (albedo 0.5) under an emitter facing down (black, emission L).
world::SourceLevel floorUnder(float luminance, uint32_t& emitterMaterial) {
    world::SourceLevel level;
    const uint32_t floor = test::addLambertMaterial(level, 0.5f);
    test::addQuad(level, {-1.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 1.0f}, {1.0f, 0.0f, -1.0f},
                  {-1.0f, 0.0f, -1.0f}, floor, "floor");
    emitterMaterial = test::addLambertMaterial(level, 0.0f);
    level.materials[emitterMaterial].emissive = glm::vec3(luminance);
    return level;
}

// A square of side s at height h, facing down.
world::SourceLevel squareLevel(float luminance, float side, float height) {
    uint32_t m = 0;
    world::SourceLevel level = floorUnder(luminance, m);
    const float s = 0.5f * side;
    test::addQuad(level, {-s, height, -s}, {s, height, -s}, {s, height, s}, {-s, height, s}, m,
                  "panel");
    return level;
}

// A disk of radius R at height h, facing down: a fan of `segments` triangles.
world::SourceLevel diskLevel(float luminance, float radius, float height, uint32_t segments) {
    uint32_t m = 0;
    world::SourceLevel level = floorUnder(luminance, m);
    world::MeshInstance disk;
    disk.nodeName = disk.meshName = "disk";
    disk.material = m;
    world::Vertex centre;
    centre.position = {0.0f, height, 0.0f};
    centre.normal = {0.0f, -1.0f, 0.0f};
    disk.vertices.push_back(centre);
    for (uint32_t i = 0; i < segments; ++i) {
        const double phi = 2.0 * kPiD * double(i) / double(segments);
        world::Vertex v = centre;
        v.position = {radius * float(std::cos(phi)), height, radius * float(std::sin(phi))};
        disk.vertices.push_back(v);
        // Counter-clockwise seen from below (-y): centre, this, next.
        disk.indices.insert(disk.indices.end(), {0u, 1u + i, 1u + (i + 1) % segments});
    }
    level.instances.push_back(disk);
    return level;
}

struct Scene {
    EmbreeDevice device;
    std::unique_ptr<BakeScene> scene;
    BakeLights lights;
    explicit Scene(const world::SourceLevel& level) {
        const world::SplitLevel split = world::splitStaticDynamic(level);
        scene =
            std::make_unique<BakeScene>(device, split.staticGeometry, loadSceneMaterials(level));
        lights = makeBakeLights(*scene, level.lights, {}, glm::vec3(0.0f));
    }
};

// The lightmap's texels of the floor against a closed form of (x, z): their mean signed error
// (the bias) within `tolerance` / 2 and their RMS error (bias and noise) within `tolerance`.
template <class Exact>
BakeResult expectLightmapMatches(const world::SourceLevel& level, uint32_t samples, Exact exact,
                                 double tolerance, const char* name) {
    BakeOptions options = test::testOptions(16.0f);
    options.indirectSamples = samples;
    options.gridCellSize = 2.0f / 3.0f;  // a cell centre at (0, 1, 0)
    options.gridSamples = 1024;
    BakeResult result = bakeLevel(level, options);
    EXPECT_TRUE(test::allFiniteNonNegative(result.baked));
    double worst = 0.0, sum = 0.0, sumSq = 0.0;
    int checked = 0;
    for (const TexelSample& s : placeTexels(result.level)) {
        // Texels two or more from the floor's edge: the indirect filter (a tent of 1..3 texels)
        // pairs an edge texel with padding texels sampled on the edge itself, which lifts a
        // falling field there by about half a texel's gradient.
        if (!s.centreInside || s.normal.y < 0.99f || std::fabs(s.position.x) > 0.875f ||
            std::fabs(s.position.z) > 0.875f)
            continue;
        const double want = exact(double(s.position.x), double(s.position.z));
        const double got = double(result.baked.texels[s.texel].irradiance.x);
        const double error = (got - want) / want;
        worst = std::max(worst, std::fabs(error));
        sum += error;
        sumSq += error * error;
        ++checked;
    }
    const double bias = sum / checked, rms = std::sqrt(sumSq / checked);
    std::printf(
        "[ %s ] lightmap, %u paths: %d floor texels, relative error mean %+.4f, RMS "
        "%.4f, worst %.4f\n",
        name, samples, checked, bias, rms, worst);
    EXPECT_GT(checked, 500);
    EXPECT_LT(std::fabs(bias), 0.5 * tolerance);
    EXPECT_LT(rms, tolerance);
    return result;
}

// Far field: a 10 cm square of luminance L at 2 m. A facing patch below its centre gets
// L A cos^2 / d^2 (the exact rectangle form differs by 0.06%); off axis the exact form holds.
TEST(Emitters, AFarSquareLightsAFacingPatchWithLACos2OverD2) {
    const float L = 2000.0f, side = 0.1f, height = 2.0f;
    const world::SourceLevel level = squareLevel(L, side, height);
    const Scene s(level);
    ASSERT_EQ(s.lights.emitters.triangles.size(), 2u);
    TransportSettings transport;
    RayCounts rays;
    const double farField =
        double(L) * double(side) * double(side) / (double(height) * double(height));
    const glm::vec3 e = referenceIrradiance(*s.scene, s.lights, {0.0f, 0.0f, 0.0f},
                                            {0.0f, 1.0f, 0.0f}, 4096, 3, transport, rays);
    std::printf("[ square ] reference %.5f lux below the centre, far field L A / d^2 = %.5f\n",
                double(e.x), farField);
    EXPECT_NEAR(double(e.x), farField, 0.01 * farField);
    // 40 degrees off axis: cos^2 theta at distance d / cos theta, i.e. L A cos^4 / h^2.
    const double offset = std::tan(40.0 * kPiD / 180.0) * double(height);
    const double c = std::cos(40.0 * kPiD / 180.0);
    const glm::vec3 off = referenceIrradiance(*s.scene, s.lights, {float(offset), 0.0f, 0.0f},
                                              {0.0f, 1.0f, 0.0f}, 4096, 5, transport, rays);
    EXPECT_NEAR(double(off.x), farField * c * c * c * c, 0.01 * farField * c * c * c * c);
    const double h = double(side) / 2.0;
    const BakeResult result = expectLightmapMatches(
        level, 64,
        [&](double x, double z) { return rectangleIrradiance(L, -h, h, -h, h, height, x, z); },
        0.01, "square");
    // The light grid: the cell at (0, 1, 0) facing up sees the panel 1 m above.
    const world::LightGrid& grid = result.baked.grid;
    ASSERT_EQ(grid.dims, glm::uvec3(3u));
    const glm::vec3 centre = grid.origin + 1.5f * grid.cellSize;
    ASSERT_LT(glm::length(centre - glm::vec3(0.0f, 1.0f, 0.0f)), 1e-4f);
    const double up = double(ambientCubeIrradiance(grid.cells[13], {0.0f, 1.0f, 0.0f}).x);
    const double wantUp = rectangleIrradiance(L, -h, h, -h, h, double(height) - 1.0, 0.0, 0.0);
    std::printf("[ square ] grid cell 1 m below: %.4f lux facing up, exact %.4f\n", up, wantUp);
    EXPECT_NEAR(up, wantUp, 0.01 * wantUp);
}

// Near field: a disk of radius 1 m half a metre above the floor fills 80% of the patch's
// hemisphere's cosine weight: the parallel-disk closed form, on and off axis.
TEST(Emitters, ANearDiskMatchesTheParallelDiskClosedForm) {
    const float L = 100.0f, radius = 1.0f, height = 0.5f;
    const world::SourceLevel level = diskLevel(L, radius, height, 256);
    const Scene s(level);
    TransportSettings transport;
    RayCounts rays;
    for (float r : {0.0f, 0.5f, 0.9f, 1.2f}) {
        const glm::vec3 e = referenceIrradiance(*s.scene, s.lights, {r, 0.0f, 0.0f},
                                                {0.0f, 1.0f, 0.0f}, 65536, 11, transport, rays);
        const double want = diskIrradiance(L, radius, height, r);
        std::printf("[ disk ] reference at r = %.1f: %.3f lux, closed form %.3f\n", double(r),
                    double(e.x), want);
        EXPECT_NEAR(double(e.x), want, 0.01 * want) << "r = " << r;
    }
    // The fan's area is (n / 2) sin(2 pi / n) R^2: 1e-4 below the disk's, inside the tolerance.
    expectLightmapMatches(
        level, 1024,
        [&](double x, double z) { return diskIrradiance(L, radius, height, std::hypot(x, z)); },
        0.01, "disk");
}

// The three estimators of the irradiance at one point, sample by sample: the emitter points
// alone (L cos / p_e), the cosine directions alone (pi L of what they hit), and the lightmap's
// MIS of both (radiance.hpp). All three are unbiased; MIS has the smallest variance.
struct Variances {
    double mean[3] = {0, 0, 0}, variance[3] = {0, 0, 0};
};
Variances estimatorVariances(const Scene& s, const glm::vec3& p, uint32_t n) {
    const glm::vec3 normal(0.0f, 1.0f, 0.0f);
    const glm::vec3 origin = p + normal * s.scene->rayOffset();
    Rng rng{seedFrom(17)};
    RayCounts rays;
    const TransportSettings transport;
    const Frame frame = frameAround(normal);
    double sum[3] = {0, 0, 0}, sumSq[3] = {0, 0, 0};
    for (uint32_t i = 0; i < n; ++i) {
        const glm::vec3 w =
            glm::normalize(frame.toWorld(sampleCosineHemisphere({rng.next(), rng.next()})));
        const float pdf = glm::dot(normal, w) / glsl::PI;
        const EmissionEstimate e = sampleEmission(*s.scene, s.lights, origin, normal, rng, rays);
        const float cosE = glm::dot(normal, e.direction);
        const double nee = e.pdf > 0.0f ? double(e.radianceOverPdf.x * cosE) : 0.0;
        const double cosine = double(
            glsl::PI * traceRadiance(*s.scene, s.lights, transport, origin, w, {}, rng, rays).x);
        const double mis =
            double(glsl::PI * traceRadiance(*s.scene, s.lights, transport, origin, w, {}, rng, rays,
                                            nullptr, pdf)
                                  .x) +
            (e.pdf > 0.0f ? nee * double(powerHeuristic(e.pdf, cosE / glsl::PI)) : 0.0);
        const double x[3] = {nee, cosine, mis};
        for (int k = 0; k < 3; ++k) {
            sum[k] += x[k];
            sumSq[k] += x[k] * x[k];
        }
    }
    Variances v;
    for (int k = 0; k < 3; ++k) {
        v.mean[k] = sum[k] / n;
        v.variance[k] = sumSq[k] / n - v.mean[k] * v.mean[k];
    }
    return v;
}

TEST(Emitters, MultipleImportanceSamplingHasLessVarianceThanEitherStrategy) {
    // A disk of radius 1 m at 0.5 m seen from 0.8 m off its axis: emitter points near the
    // grazing rim (p_e large in d^2 / cos) and cosine directions that miss both matter.
    const float L = 100.0f;
    const world::SourceLevel level = diskLevel(L, 1.0f, 0.5f, 256);
    const Scene s(level);
    const Variances v = estimatorVariances(s, {0.8f, 0.0f, 0.0f}, 200000);
    const double want = diskIrradiance(L, 1.0, 0.5, 0.8);
    const char* names[3] = {"emitters alone", "cosine alone", "MIS"};
    for (int k = 0; k < 3; ++k) {
        std::printf("[ MIS ] %-14s mean %.3f (closed form %.3f), variance %.1f\n", names[k],
                    v.mean[k], want, v.variance[k]);
        EXPECT_NEAR(v.mean[k], want, 0.01 * want) << names[k];
    }
    EXPECT_LT(v.variance[2], v.variance[0]);
    EXPECT_LT(v.variance[2], v.variance[1]);
}

// A glowing integrating sphere: a closed Lambert sphere of albedo rho whose whole wall emits L.
// The radiance inside is L (1 + rho + rho^2 + ...) = L / (1 - rho) everywhere, so every path
// vertex's emitter sampling and chance hits (MIS in traceRadiance) must add up to it.
TEST(Emitters, AGlowingIntegratingSphereReachesLOverOneMinusRho) {
    world::SourceLevel level;
    const float rho = 0.5f, L = 10.0f;
    const uint32_t m = test::addLambertMaterial(level, rho);
    level.materials[m].emissive = glm::vec3(L);
    test::addInwardSphere(level, glm::vec3(0.0f), 2.0f, 48, 96, m);
    const Scene s(level);
    TransportSettings transport;
    transport.maxDepth = 200;
    RayCounts rays;
    const glm::vec3 p(0.0f, 0.0f, -1.98f);  // near the wall's pole, facing in
    const glm::vec3 e =
        referenceIrradiance(*s.scene, s.lights, p, {0.0f, 0.0f, 1.0f}, 20000, 9, transport, rays);
    const double want = kPiD * double(L) / (1.0 - double(rho));
    std::printf("[ sphere ] irradiance %.3f lux, closed form pi L / (1 - rho) = %.3f\n",
                double(e.x), want);
    EXPECT_NEAR(double(e.x), want, 0.01 * want);
}

// A level with emitters and with punctual lights bakes without NaN, and an emitter behind a
// wall lights nothing through it.
TEST(Emitters, AnEmitterBehindAWallLightsNothingThroughIt) {
    const float L = 1000.0f;
    world::SourceLevel level = squareLevel(L, 0.5f, 1.0f);
    const uint32_t wall = test::addLambertMaterial(level, 0.5f);
    // A double-sided blocker between the panel and the floor, larger than the floor.
    level.materials[wall].doubleSided = true;
    test::addQuad(level, {-3.0f, 0.5f, 3.0f}, {3.0f, 0.5f, 3.0f}, {3.0f, 0.5f, -3.0f},
                  {-3.0f, 0.5f, -3.0f}, wall, "wall");
    const Scene s(level);
    TransportSettings transport;
    transport.maxDepth = 1;  // direct light only: the panel's light must not pass the wall
    RayCounts rays;
    const glm::vec3 e = referenceIrradiance(*s.scene, s.lights, {0.0f, 0.0f, 0.0f},
                                            {0.0f, 1.0f, 0.0f}, 1024, 3, transport, rays);
    EXPECT_EQ(e.x, 0.0f);
}

}  // namespace
}  // namespace onelight::bake
