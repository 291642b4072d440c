// Seams between lightmap charts show no visible step (issue 5, "seams between charts show no
// visible step"). A floor of coplanar pieces (separate meshes, so separate charts) lit by two
// primaries (the region splitter cuts charts where the primary changes) and a baked spot, with
// a block casting a shadow across a border. At points along every chart border the runtime's
// reconstruction (bilinear lightmap and shadow-mask lookup at the same world point, own primary
// x mask + secondary) is read from the charts on both sides and compared.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include <gtest/gtest.h>

#include "bake/lightmap/lightmap_bake.hpp"
#include "bake_scenes.hpp"

namespace onelight::bake {
namespace {

using world::LightRole;

constexpr float kTexelsPerMetre = 8.0f;

/// The floor: an L of three coplanar quads (three meshes), plus a wall of two coplanar pieces
/// at its back and a block standing across the first border.
world::SourceLevel seamLevel() {
    world::SourceLevel level;
    const uint32_t floor = test::addLambertMaterial(level, 0.6f);
    const uint32_t block = test::addLambertMaterial(level, 0.4f);
    test::addQuad(level, {-2, 0, 0}, {0, 0, 0}, {0, 2, 0}, {-2, 2, 0}, floor, "floor_a");
    test::addQuad(level, {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, floor, "floor_b");
    test::addQuad(level, {-2, -2, 0}, {0, -2, 0}, {0, 0, 0}, {-2, 0, 0}, floor, "floor_c");
    // Wall at y = 2 facing -y, in two pieces split at x = 0.
    test::addQuad(level, {-2, 2, 0}, {0, 2, 0}, {0, 2, 1.5f}, {-2, 2, 1.5f}, floor, "wall_a");
    test::addQuad(level, {0, 2, 0}, {2, 2, 0}, {2, 2, 1.5f}, {0, 2, 1.5f}, floor, "wall_b");
    test::addBox(level, {-0.25f, 0.9f, 0.0f}, {0.25f, 1.3f, 0.4f}, block, false, "block");
    level.lights.push_back(test::pointLight({-1.2f, 1.0f, 1.6f}, 40.0f, LightRole::kPrimary));
    level.lights.push_back(test::pointLight({1.3f, 0.6f, 1.4f}, 30.0f, LightRole::kPrimary));
    level.lights.push_back(test::spotLight({0.5f, -1.5f, 1.8f}, {-0.3f, 0.5f, -1.0f}, 60.0f, 0.3f,
                                           0.8f, LightRole::kBaked));
    return level;
}

/// A triangle of the compiled level with the surface it belongs to.
struct LevelTriangle {
    uint32_t surface = 0;
    uint32_t firstIndex = 0;  // into level.indices
};

std::vector<LevelTriangle> levelTriangles(const world::CompiledLevel& level) {
    std::vector<LevelTriangle> out;
    for (uint32_t s = 0; s < level.surfaces.size(); ++s) {
        const world::Surface& surface = level.surfaces[s];
        if (surface.chart == world::kNoIndex) continue;
        for (uint32_t i = surface.firstIndex; i < surface.firstIndex + surface.indexCount; i += 3)
            out.push_back({s, i});
    }
    return out;
}

/// Barycentrics of p in the triangle when p lies on it (within `tolerance` metres of its plane
/// and of its edges); Ericson 2005, "Real-Time Collision Detection", sec. 3.4.
std::optional<glm::dvec3> barycentricsOn(const world::CompiledLevel& level, const LevelTriangle& t,
                                         const glm::dvec3& p, double tolerance) {
    const glm::dvec3 a(level.vertices[level.indices[t.firstIndex]].position);
    const glm::dvec3 b(level.vertices[level.indices[t.firstIndex + 1]].position);
    const glm::dvec3 c(level.vertices[level.indices[t.firstIndex + 2]].position);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double area2 = glm::length(n);
    if (area2 <= 0.0) return std::nullopt;
    if (std::abs(glm::dot(p - a, n / area2)) > tolerance) return std::nullopt;
    const double u = glm::dot(glm::cross(c - b, p - b), n) / (area2 * area2);
    const double v = glm::dot(glm::cross(a - c, p - c), n) / (area2 * area2);
    const double w = 1.0 - u - v;
    // An edge's barycentric is its distance over the triangle's height to it.
    const double slack =
        tolerance * area2 / std::max({glm::length(c - b), glm::length(a - c), glm::length(b - a)});
    if (u < -slack || v < -slack || w < -slack) return std::nullopt;
    return glm::dvec3(u, v, w);
}

glm::vec3 triangleNormal(const world::CompiledLevel& level, const LevelTriangle& t) {
    const glm::vec3 a = level.vertices[level.indices[t.firstIndex]].position;
    const glm::vec3 b = level.vertices[level.indices[t.firstIndex + 1]].position;
    const glm::vec3 c = level.vertices[level.indices[t.firstIndex + 2]].position;
    return glm::normalize(glm::cross(b - a, c - a));
}

/// What the runtime shows at a point of a static surface at its geometric normal: the lightmap
/// and the shadow mask read with bilinear filtering (texel centres at (x + 0.5) / width, as a
/// GPU samples) at the point's uv1, the own primary evaluated per pixel.
struct Reconstructed {
    float total = 0.0f;            // luminance, lux
    float texelNeighbourStep = 0;  // largest luminance difference between the 4 texels read
};

Reconstructed reconstruct(const world::CompiledLevel& level, const world::BakedLighting& baked,
                          const BakeLights& lights, const LevelTriangle& t,
                          const glm::dvec3& barycentrics, const glm::vec3& position) {
    const world::Surface& surface = level.surfaces[t.surface];
    const world::Atlas& atlas = level.atlases[surface.atlas];
    glm::dvec2 uv(0.0);
    for (int k = 0; k < 3; ++k)
        uv += barycentrics[k] * glm::dvec2(level.vertices[level.indices[t.firstIndex + k]].uv1);
    const glm::dvec2 texel = uv * glm::dvec2(atlas.width, atlas.height) - 0.5;
    const int x0 = static_cast<int>(std::floor(texel.x)),
              y0 = static_cast<int>(std::floor(texel.y));
    const float fx = static_cast<float>(texel.x - x0), fy = static_cast<float>(texel.y - y0);
    const uint64_t base = world::atlasTexelOffset(level, surface.atlas);
    const glm::vec3 normal = triangleNormal(level, t);
    const BakeLight* own = nullptr;
    for (const BakeLight& l : lights.lights)
        if (l.levelIndex == surface.primaryLight) own = &l;
    glm::vec3 ownDirect(0.0f);
    if (own) {
        const LightIncidence incidence = lightIncidence(*own, position);
        ownDirect = incidence.irradiance * std::max(0.0f, glm::dot(normal, incidence.direction));
    }
    glm::vec3 secondary(0.0f);
    float mask = 0.0f, lowest = INFINITY, highest = -INFINITY;
    for (int dy = 0; dy <= 1; ++dy) {
        for (int dx = 0; dx <= 1; ++dx) {
            const int x = std::clamp(x0 + dx, 0, int(atlas.width) - 1);
            const int y = std::clamp(y0 + dy, 0, int(atlas.height) - 1);
            const uint64_t i = base + uint64_t(y) * atlas.width + uint64_t(x);
            const float w = (dx ? fx : 1.0f - fx) * (dy ? fy : 1.0f - fy);
            const float m = static_cast<float>(baked.shadowMask[i]) / 255.0f;
            secondary += w * baked.texels[i].irradiance;
            mask += w * m;
            const float texelTotal = luminance(baked.texels[i].irradiance + ownDirect * m);
            lowest = std::min(lowest, texelTotal);
            highest = std::max(highest, texelTotal);
        }
    }
    return {luminance(secondary + ownDirect * mask), highest - lowest};
}

/// A point on a border between two charts, reconstructed from each side.
struct SeamPoint {
    glm::vec3 position{0.0f};
    Reconstructed sideA, sideB;
};

/// Points along every triangle edge that lie on a coplanar triangle of another chart.
std::vector<SeamPoint> seamPoints(const world::CompiledLevel& level,
                                  const world::BakedLighting& baked, const BakeLights& lights) {
    const std::vector<LevelTriangle> triangles = levelTriangles(level);
    constexpr int kPointsPerEdge = 24;
    constexpr double kOnTriangle = 1e-5;  // metres
    std::vector<SeamPoint> out;
    for (const LevelTriangle& t : triangles) {
        const uint32_t chart = level.surfaces[t.surface].chart;
        const glm::vec3 normal = triangleNormal(level, t);
        for (int e = 0; e < 3; ++e) {
            const glm::dvec3 p0(level.vertices[level.indices[t.firstIndex + e]].position);
            const glm::dvec3 p1(level.vertices[level.indices[t.firstIndex + (e + 1) % 3]].position);
            for (int k = 0; k < kPointsPerEdge; ++k) {
                const double s = (k + 0.5) / kPointsPerEdge;
                const glm::dvec3 p = glm::mix(p0, p1, s);
                for (const LevelTriangle& o : triangles) {
                    if (level.surfaces[o.surface].chart == chart) continue;
                    if (glm::dot(triangleNormal(level, o), normal) < 0.999f) continue;
                    const std::optional<glm::dvec3> bo = barycentricsOn(level, o, p, kOnTriangle);
                    if (!bo) continue;
                    const std::optional<glm::dvec3> bt = barycentricsOn(level, t, p, kOnTriangle);
                    SeamPoint point;
                    point.position = glm::vec3(p);
                    point.sideA = reconstruct(level, baked, lights, t, *bt, point.position);
                    point.sideB = reconstruct(level, baked, lights, o, *bo, point.position);
                    out.push_back(point);
                    break;
                }
            }
        }
    }
    return out;
}

/// The floor under the block is never seen (the block's base covers it).
bool underBlock(const glm::vec3& p) {
    return p.z < 1e-3f && std::abs(p.x) <= 0.25f && p.y >= 0.9f && p.y <= 1.3f;
}

// Tolerances. A sharp luminance step becomes visible at about 1-2% (Weber fraction).
//  - smooth light (the 2x2 texels read on either side differ by less than 10% of the value,
//    i.e. no shadow edge nearby): the step must stay below 1%. Noise: the secondary's
//    estimated noise at 4096 paths is ~1% per texel before the 3x3 filter (x0.375 after it),
//    on ~60% of the value: ~0.25% per texel of the total; the two sides are independent, so
//    they differ by ~0.35% (1 sigma) and 1% is ~3 sigma. (At 1024-2048 paths the worst point
//    reaches 1.2%: noise, not the seam.) The smooth part of the direct light is exact at the
//    border (texels evaluate it at their centres) and every texel a bilinear lookup on a
//    triangle reads is sampled (texel_placement.hpp); before those two, steps of ~2.3% (one
//    texel's gradient) and ~1.2% (dilated texels in the lookup at diagonal borders) showed.
//  - everywhere (shadow edges included): the step must be at most half the largest difference
//    between the 2x2 texels read on either side, so a seam is never a bigger jump than half a
//    texel of the chart's own grid.
constexpr float kSmoothNeighbourFraction = 0.10f;
constexpr float kSmoothStep = 0.01f;
constexpr float kStepOverTexelStep = 0.5f;

TEST(LightmapSeams, ChartBordersShowNoVisibleStep) {
    const world::SourceLevel source = seamLevel();
    BakeOptions options = test::testOptions(kTexelsPerMetre, BakeQuality::kDefault);
    options.indirectSamples = 4096;
    options.shadowSamples = 64;
    const BakeResult r = bakeLevel(source, options);
    const BakeLights lights = makePunctualLights(source.lights, options.lightSizes,
                                                 options.skyRadiance.value_or(source.skyRadiance));
    const std::vector<SeamPoint> points = seamPoints(r.level, r.baked, lights);
    const bool verbose = std::getenv("ONELIGHT_VERBOSE") != nullptr;
    double sumSq = 0.0, worstSmooth = 0.0, worstRatio = 0.0;
    size_t smooth = 0, shadowed = 0;
    for (const SeamPoint& p : points) {
        if (underBlock(p.position)) continue;
        const float a = p.sideA.total, b = p.sideB.total;
        const float mean = 0.5f * (a + b);
        ASSERT_GT(mean, 1.0f) << "every seam point is lit";
        const float step = std::abs(a - b);
        const float gridStep = std::max(p.sideA.texelNeighbourStep, p.sideB.texelNeighbourStep);
        if (verbose)
            std::printf("%6.3f %6.3f %6.3f  a %8.3f b %8.3f step %.4f (%.2f%%) texels %.4f\n",
                        double(p.position.x), double(p.position.y), double(p.position.z), double(a),
                        double(b), double(step), 100.0 * double(step / mean), double(gridStep));
        worstRatio = std::max(worstRatio, double(step / gridStep));
        EXPECT_LE(step, kStepOverTexelStep * gridStep)
            << "at " << p.position.x << ", " << p.position.y << ", " << p.position.z << ": " << a
            << " vs " << b;
        if (gridStep < kSmoothNeighbourFraction * mean) {
            const double rel = step / mean;
            EXPECT_LT(rel, kSmoothStep) << "at " << p.position.x << ", " << p.position.y << ", "
                                        << p.position.z << ": " << a << " vs " << b;
            sumSq += rel * rel;
            worstSmooth = std::max(worstSmooth, rel);
            ++smooth;
        } else {
            ++shadowed;
        }
    }
    std::printf(
        "seams: %zu points where the light is smooth (RMS step %.3f%%, worst %.3f%%), "
        "%zu near shadow edges; worst step / texel step %.2f; estimated texel noise "
        "%.2f%%\n",
        smooth, 100.0 * std::sqrt(sumSq / double(std::max<size_t>(smooth, 1))), 100.0 * worstSmooth,
        shadowed, worstRatio, 100.0 * r.report.lightmapMeanRelativeNoise);
    EXPECT_GT(smooth, 100u);
    EXPECT_GT(shadowed, 5u);
}

}  // namespace
}  // namespace onelight::bake
