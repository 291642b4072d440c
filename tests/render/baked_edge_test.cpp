// A baked sun's shadow edge on a lightmapped floor (bake/lightmap/direct_edges.hpp): a wall turned
// 30 degrees to the floor's 20 cm texels casts a straight edge, baked into the lightmap's direct
// part (the sun is a baked light, no surface's primary). Seen from straight above, the edge
// drawn from the texels' distance field lies along the geometry's line, within a few
// millimetres along its whole length, as wide as the sun's penumbra; the texels' bilinear
// visibility (the runtime's FEATURE_DIRECT_EDGE off, as before the field) stair-steps about it
// by centimetres.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/gpu_types.hpp"
#include "render/scene.hpp"
#include "shading.hpp"
#include "test_scene.hpp"
#include "world/baked_lighting.hpp"

namespace {

using namespace onelight;

constexpr uint32_t kWidth = 256, kHeight = 384;
constexpr float kYfov = 0.6f;  // radians: 1.0 cm a pixel 6 m down
constexpr float kHeightAbove = 6.0f;
constexpr float kWallTop = 3.0f;  // metres
constexpr float kHalfThick = 0.1f;
constexpr float kTurn = 0.5235988f;  // 30 degrees
constexpr float kTexelsPerMetre = 5.0f;

// The wall's direction along the floor and its normal towards the shadow (y up).
const glm::vec3 kAlong{std::cos(kTurn), 0.0f, std::sin(kTurn)};
const glm::vec3 kAcross{-std::sin(kTurn), 0.0f, std::cos(kTurn)};
// The sun at 45 degrees, square to the wall: the shadow's far edge kHalfThick + kWallTop from the
// wall's centre line.
constexpr float kEdgeOffset = kHalfThick + kWallTop;

// The second light over the wall's scene (every light baked, no surface's primary).
enum class SecondSun {
    kNone,
    // 5 klx straight down, over both sides of the edge: it goes from 0.41 of the direct light to
    // all of it.
    kOverhead,
    // 8.64 klx straight down but under a roof over the shadow's side, which the first sun passes
    // under: the edge goes from none of the direct light to 0.45 of it, every texel's visibility
    // below one half.
    kRoofed,
};

assets::LoadedLevel wallTurnedInABakedSun(SecondSun second) {
    test::Scene s;
    s.materials = {{{0.5f, 0.5f, 0.5f, 1.0f}, 0.0f, 1.0f}};
    test::addFloor(s, 0.0f, 0.0f, 8.0f, 0.0f, 0);
    test::addBox(s, {-5.0f, 0.0f, -kHalfThick}, {5.0f, kWallTop, kHalfThick}, 0);
    if (second == SecondSun::kRoofed) test::addBox(s, {-5.0f, 8.0f, 0.0f}, {5.0f, 8.3f, 12.0f}, 0);
    for (test::SceneMesh& mesh : s.meshes) {
        if (&mesh == &s.meshes.front()) continue;  // the floor
        for (glm::vec3& p : mesh.positions)
            p = p.x * kAlong + p.y * glm::vec3(0, 1, 0) + p.z * kAcross;
        for (glm::vec3& n : mesh.normals)
            n = n.x * kAlong + n.y * glm::vec3(0, 1, 0) + n.z * kAcross;
    }
    test::SceneLight sun;
    sun.type = 0;
    sun.intensity = 10000.0f;
    sun.direction = glm::normalize(kAcross - glm::vec3(0.0f, 1.0f, 0.0f));
    sun.role = "baked";
    s.lights.push_back(sun);
    if (second != SecondSun::kNone) {
        // Roofed: 10 klx at 45 degrees gives the floor 7071 lux, and 7071 / (7071 + 8642) = 0.45.
        sun.intensity = second == SecondSun::kOverhead ? 5000.0f : 8642.0f;
        sun.direction = glm::vec3(0.0f, -1.0f, 0.0f);
        s.lights.push_back(sun);
    }
    const std::string name = second == SecondSun::kNone       ? "baked_edge"
                             : second == SecondSun::kOverhead ? "baked_edge_overhead"
                                                              : "baked_edge_roofed";
    const std::string gltf = test::outputDir() + "/" + name + ".gltf";
    test::writeGltf(s, gltf);
    return test::bakeAndLoad(
        gltf, test::outputDir() + "/" + name + ".olpak",
        "--texels-per-metre " + std::to_string(kTexelsPerMetre) + " --uniform-density");
}

struct EdgeMeasure {
    double offset = 0.0;  // metres: the mean distance of the 50% line from the geometry's, + lit
    double wander = 0.0;  // metres: the standard deviation of that distance along the edge
    double width = 0.0;   // metres across the edge, 10% to 90%, mean over the columns
    int columns = 0;
};

// The floor seen from `above` metres straight over `centre` (image rows along +z, columns along
// +x), and the floor's size of a pixel there.
struct TopView {
    test::RenderedFrame frame;
    float pixel = 0.0f;  // metres
};
TopView topView(const assets::LoadedLevel& level, glm::vec3 centre, float above,
                uint32_t featuresOff) {
    render::RendererOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.featuresOff = featuresOff;
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({centre.x, above, centre.z}, 0.0f, -90.0f);
    inputs.camera.yfov = kYfov;
    TopView v{test::renderOnce(level, options, inputs),
              2.0f * above * std::tan(0.5f * kYfov) / float(kHeight)};
    EXPECT_EQ(v.frame.validationErrors, 0u);
    return v;
}

// Each image column crosses the edge once; z rows are towards +z (the image's top towards -z),
// x columns towards +x. Distances are across the edge (along kAcross).
EdgeMeasure measureEdge(const assets::LoadedLevel& level, uint32_t featuresOff) {
    const glm::vec3 centre = kEdgeOffset * kAcross;
    const TopView view = topView(level, centre, kHeightAbove, featuresOff);
    const test::RenderedFrame& r = view.frame;
    const float pixel = view.pixel;
    std::vector<double> offsets, widths;
    for (uint32_t col = 8; col + 8 < kWidth; ++col) {
        const float x = centre.x + (float(col) + 0.5f - 0.5f * float(kWidth)) * pixel;
        // The geometric edge's z at this x: points e + t kAlong, e = kEdgeOffset kAcross.
        const float t = (x - centre.x) / kAlong.x;
        const float zEdge = centre.z + t * kAlong.z;
        std::vector<float> z(kHeight), lum(kHeight);
        for (uint32_t row = 0; row < kHeight; ++row) {
            const float* px = &r.frame.linearRgba[(size_t(row) * kWidth + col) * 4];
            z[row] = centre.z + (float(row) + 0.5f - 0.5f * float(kHeight)) * pixel;
            lum[row] = 0.2126f * px[0] + 0.7152f * px[1] + 0.0722f * px[2];
        }
        const auto rowAt = [&](float zw) {
            return std::clamp(int(std::floor((zw - centre.z) / pixel + 0.5f * float(kHeight))), 0,
                              int(kHeight) - 1);
        };
        // 40 cm either side along z (35 cm across): beyond a texel and a half of the edge.
        const int from = rowAt(zEdge - 0.4f), to = rowAt(zEdge + 0.4f);
        if (from <= 0 || to >= int(kHeight) - 1) continue;
        const float shadowed = lum[size_t(from)], lit = lum[size_t(to)];
        if (!(lit > 2.0f * shadowed)) continue;
        const auto crossing = [&](float fraction) {
            const float target = shadowed + fraction * (lit - shadowed);
            for (int row = from + 1; row <= to; ++row)
                if (lum[size_t(row) - 1] < target && lum[size_t(row)] >= target) {
                    const float u =
                        (target - lum[size_t(row) - 1]) / (lum[size_t(row)] - lum[size_t(row) - 1]);
                    return z[size_t(row) - 1] + u * pixel;
                }
            return 1e30f;
        };
        const float half = crossing(0.5f);
        if (half > 1e29f) continue;
        offsets.push_back(double((half - zEdge) * kAcross.z));
        widths.push_back(double((crossing(0.9f) - crossing(0.1f)) * kAcross.z));
    }
    EdgeMeasure m;
    m.columns = int(offsets.size());
    if (offsets.empty()) return m;
    double sum = 0.0, sum2 = 0.0, widthSum = 0.0;
    for (size_t i = 0; i < offsets.size(); ++i) {
        sum += offsets[i];
        sum2 += offsets[i] * offsets[i];
        widthSum += widths[i];
    }
    const double n = double(offsets.size());
    m.offset = sum / n;
    m.wander = std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)));
    m.width = widthSum / n;
    return m;
}

// Texels of 20 cm, pixels of 1 cm. The sun's penumbra at the edge (the wall's top 4.2 m away,
// 0.27 degrees in radius) is about 4 cm from 10% to 90% across the edge; the field draws the
// width it measured there (3.6 cm). Its line lies 0.15 cm from the geometry's and wanders 0.25 cm
// about it (bake/lightmap/direct_edges.cpp: crossings placed to 1/32 texel, 0.6 cm, a line
// fitted through them, and the mask's 8 bits over 32 penumbra widths, 0.5 cm steps here): kept
// under 0.5 and 0.4 cm, a fortieth and a fiftieth of a texel. The
// bilinear visibility stair-steps by about a quarter texel either way: its wander is 2.7 cm, and
// it must stay at least five times the field's.
void expectStraightEdge(bool overhead) {
    const assets::LoadedLevel level =
        wallTurnedInABakedSun(overhead ? SecondSun::kOverhead : SecondSun::kNone);
    const EdgeMeasure field = measureEdge(level, 0);
    const EdgeMeasure bilinear = measureEdge(level, uint32_t(glsl::FEATURE_DIRECT_EDGE));
    std::printf(
        "[ baked edge ] %s\n  distance field: offset %+.2f cm, wander %.2f cm, 10-90%% width "
        "%.2f cm (%d columns)\n  bilinear:       offset %+.2f cm, wander %.2f cm, 10-90%% width "
        "%.2f cm (%d columns)\n",
        overhead ? "with a second sun over both sides" : "one sun", 100.0 * field.offset,
        100.0 * field.wander, 100.0 * field.width, field.columns, 100.0 * bilinear.offset,
        100.0 * bilinear.wander, 100.0 * bilinear.width, bilinear.columns);
    ASSERT_GT(field.columns, 200);
    ASSERT_GT(bilinear.columns, 200);
    EXPECT_LT(std::abs(field.offset), 0.005);
    EXPECT_LT(field.wander, 0.004);
    EXPECT_GT(field.width, 0.025);  // the penumbra, not a hard step
    EXPECT_LT(field.width, 0.055);
    EXPECT_GT(bilinear.wander, 5.0 * field.wander);
}

TEST(BakedEdge, ASunsEdgeAcrossTheTexelsIsAStraightLineWhereTheGeometryPutsIt) {
    expectStraightEdge(false);
}

TEST(BakedEdge, AnEdgeOfOneLightAmongOthersIsDrawnToo) {
    expectStraightEdge(true);
}

// Every texel's visibility below one half (the edge from none of the direct light to 0.45 of it,
// a second sun roofed over): the texels beyond the field's reach were signed by V >= 0.5, dark,
// next to the field's lit texels, and the filtered distance crossed zero between them, a second
// edge drawn 2-3 texels into the lit side at the levels' mean (half the light there). The lit side
// from 30 cm to 1.3 m past the edge (1.5 to 6.5 texels), the columns' mean at each distance, must
// be flat: within 5% of its median (its light is the first sun's, even, and the bounce light's,
// which changes by a few percent over the metre).
TEST(BakedEdge, TexelsBelowHalfOnTheLitSideDrawNoSecondEdge) {
    const assets::LoadedLevel level = wallTurnedInABakedSun(SecondSun::kRoofed);
    const glm::vec3 centre = (kEdgeOffset + 0.8f) * kAcross;
    const TopView view = topView(level, centre, kHeightAbove, 0);
    const auto luminanceAt = [&](glm::vec3 p) {
        const int col = int(std::floor((p.x - centre.x) / view.pixel + 0.5f * float(kWidth)));
        const int row = int(std::floor((p.z - centre.z) / view.pixel + 0.5f * float(kHeight)));
        if (col < 0 || row < 0 || col >= int(kWidth) || row >= int(kHeight)) return -1.0f;
        const float* px = &view.frame.frame.linearRgba[(size_t(row) * kWidth + size_t(col)) * 4];
        return 0.2126f * px[0] + 0.7152f * px[1] + 0.0722f * px[2];
    };
    std::vector<double> profile;
    for (float past = 0.3f; past <= 1.3f; past += 0.01f) {
        double sum = 0.0;
        int count = 0;
        for (float along = -1.0f; along <= 1.0f; along += 0.01f) {
            const float l = luminanceAt(along * kAlong + (kEdgeOffset + past) * kAcross);
            if (l < 0.0f) continue;
            sum += double(l);
            ++count;
        }
        ASSERT_GT(count, 50);
        profile.push_back(sum / count);
    }
    std::vector<double> sorted = profile;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted[sorted.size() / 2];
    std::printf(
        "[ baked edge ] the lit side of an edge from 0 to 0.45, 30 cm to 1.3 m past it: from "
        "%.3f to %.3f of its median\n",
        sorted.front() / median, sorted.back() / median);
    EXPECT_GT(sorted.front(), 0.95 * median);
    EXPECT_LT(sorted.back(), 1.05 * median);
}

// The wall's foot: the floor texels under the wall were moved out of the solid and traced their
// light from one side, often the sunlit one, and the bilinear filter carried it past the foot onto
// the shadow, as a bright sawtooth at the texels' pitch. Along the foot, in 20 cm stretches, the
// floor from 1 to 6 cm off the wall's face against the same side's floor 30 to 60 cm off it, on
// the side `side` (+1 the shadow, -1 the sunlit side): the stretch furthest from the reference's
// ratio (`onelight-bake reference` of this scene from the same view, 256 paths: 0.19-0.32 in the
// shadow, where the wall hides half of what lights the foot; 1.04-1.07 on the sunlit side, where
// the wall's lit face adds to the sun). The field takes the sun's part of the leak away; the
// moved texels' bounce light is their neighbours' on both sides, weighted by the inverse of
// each one's whole light (lightmap_denoise.hpp movedTexelIndirect).
struct FootRatio {
    double least = 1e30, most = 0.0;  // over the stretches
};
FootRatio footOverBeyond(const assets::LoadedLevel& level, float side, uint32_t featuresOff) {
    const glm::vec3 centre = side * (kHalfThick + 0.4f) * kAcross;
    const TopView view = topView(level, centre, kHeightAbove, featuresOff);
    const test::RenderedFrame& r = view.frame;
    const float pixel = view.pixel;
    // The luminance of the pixel over floor point p.
    const auto luminanceAt = [&](glm::vec3 p) {
        const int col = int(std::floor((p.x - centre.x) / pixel + 0.5f * float(kWidth)));
        const int row = int(std::floor((p.z - centre.z) / pixel + 0.5f * float(kHeight)));
        if (col < 0 || row < 0 || col >= int(kWidth) || row >= int(kHeight)) return -1.0f;
        const float* px = &r.frame.linearRgba[(size_t(row) * kWidth + size_t(col)) * 4];
        return 0.2126f * px[0] + 0.7152f * px[1] + 0.0722f * px[2];
    };
    const auto meanOver = [&](float from, float to, float across0, float across1) {
        double sum = 0.0;
        int count = 0;
        for (float a = from; a < to; a += 0.005f)
            for (float off = across0; off <= across1; off += 0.005f) {
                const float l = luminanceAt(a * kAlong + side * (kHalfThick + off) * kAcross);
                if (l < 0.0f) continue;
                sum += double(l);
                ++count;
            }
        return count ? sum / count : -1.0;
    };
    FootRatio ratio;
    int stretches = 0;
    for (float along = -1.0f; along < 1.0f; along += 0.2f) {
        const double foot = meanOver(along, along + 0.2f, 0.01f, 0.06f);
        const double beyond = meanOver(along, along + 0.2f, 0.3f, 0.6f);
        if (foot < 0.0 || beyond <= 0.0) continue;
        ratio.least = std::min(ratio.least, foot / beyond);
        ratio.most = std::max(ratio.most, foot / beyond);
        ++stretches;
    }
    EXPECT_GE(stretches, 8);
    return ratio;
}

// In the shadow the foot must not be brighter than the floor beyond it (0.19-0.32 in the
// reference; the bilinear visibility made it 19 times, and the moved texels' sunlit bounce light
// 6.5 times after the field); what is left is the 20 cm texels' resolution of the wall's
// occlusion over a few centimetres (0.5-0.8). On the sunlit side, the bounce light the moved
// texels now share with the shadow costs the foot's first centimetres (their whole light 0.8-0.9
// of the reference's): kept above 0.75 of the floor beyond.
TEST(BakedEdge, TheSunDoesNotLeakUnderTheWallIntoItsShadow) {
    const assets::LoadedLevel level = wallTurnedInABakedSun(SecondSun::kNone);
    const FootRatio shadow = footOverBeyond(level, 1.0f, 0);
    const FootRatio bilinear = footOverBeyond(level, 1.0f, uint32_t(glsl::FEATURE_DIRECT_EDGE));
    const FootRatio lit = footOverBeyond(level, -1.0f, 0);
    std::printf(
        "[ baked edge ] the wall's foot over the floor beyond, the 20 cm stretches: in its shadow "
        "%.2f-%.2f (bilinear visibility: %.2f-%.2f), on its sunlit side %.2f-%.2f\n",
        shadow.least, shadow.most, bilinear.least, bilinear.most, lit.least, lit.most);
    EXPECT_GT(bilinear.most, 10.0);  // the leak the field is for
    EXPECT_LT(shadow.most, 1.0);
    EXPECT_GT(lit.least, 0.75);
    EXPECT_LT(lit.most, 1.2);
}

// The shadow mask holds every distance the baker writes: its reach over the narrowest penumbra
// the baker measures (two of its gradient's steps of 1/16 texel) is within the mask's range.
TEST(BakedEdge, TheMaskHoldsEveryDistanceTheBakerWrites) {
    EXPECT_LE(world::kDirectEdgeReach / glsl::DIRECT_EDGE_MIN_WIDTH, glsl::DIRECT_EDGE_RAMPS);
    world::LightmapTexel t;
    t.directEdgeDistance = -world::kDirectEdgeReach;
    t.directEdgeWidth = 0.0f;
    t.directVisibility = 0.2f;
    t.directEdgeLow = 0.1f;
    t.directEdgeHigh = 0.9f;
    t.directEdgeSharpness = 0.0f;
    const render::DirectEdgeMask flat = render::directEdgeMask(t);
    EXPECT_FLOAT_EQ(flat.low, 0.2f);  // no edge drawn: one level, the texel's
    EXPECT_FLOAT_EQ(flat.high, 0.2f);
    t.directEdgeSharpness = 1.0f;
    const render::DirectEdgeMask edge = render::directEdgeMask(t);
    EXPECT_FLOAT_EQ(edge.low, 0.1f);
    EXPECT_FLOAT_EQ(edge.high, 0.9f);
    EXPECT_GE(edge.ramps, 0.0f);
    EXPECT_LT(edge.ramps, 0.5f);
}

}  // namespace
