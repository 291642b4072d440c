// The sun's shadow in cascades (runtime/render/shadows.hpp): a straight shadow edge on a floor,
// seen from straight above at 3, 10 and 30 m, falls in cascades 0, 1 and 2. At each distance
// the edge lies where the geometry puts it and is as sharp as that cascade's texels allow; with
// one map over the whole radius (sunCascades 1) the near edge is several times wider.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "render/shadows.hpp"
#include "test_scene.hpp"
#include "world/light_model.hpp"

namespace {

using namespace onelight;

constexpr uint32_t kWidth = 64, kHeight = 360;
constexpr float kYfov = 0.3f;                  // radians: 5 mm a pixel row at 3 m, 5 cm at 30 m
constexpr float kWallTop = 3.0f;               // metres
constexpr float kWallFar = 0.2f;               // the wall's far face, z
constexpr float kEdgeZ = kWallFar + kWallTop;  // the sun at 45 degrees: the shadow's edge

// A 120 m floor and a wall along x, 3 m high, lit by a 45-degree sun travelling towards +z: the
// wall's shadow covers z in [0.2, 3.2], its far edge a straight line along x.
assets::LoadedLevel wallInTheSun() {
    test::Scene s;
    s.materials = {{{0.5f, 0.5f, 0.5f, 1.0f}, 0.0f, 1.0f}};
    test::addFloor(s, 0.0f, 0.0f, 60.0f, 0.0f, 0);
    test::addBox(s, {-60.0f, 0.0f, 0.0f}, {60.0f, kWallTop, kWallFar}, 0);
    test::SceneLight sun;
    sun.type = 0;
    sun.intensity = 10000.0f;
    sun.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 1.0f));
    s.lights.push_back(sun);
    const std::string gltf = test::outputDir() + "/sun_cascades.gltf";
    test::writeGltf(s, gltf);
    return test::compileAndLoad(gltf, test::outputDir() + "/sun_cascades.olpak");
}

struct Edge {
    float position = 0.0f;  // z where the floor is half way from shadow to sun
    float width = 0.0f;     // metres from 10% to 90% of the way
    float contrast = 0.0f;  // sunlit over shadowed luminance, 1 m either side of the edge
};

// The edge under a camera `height` metres above (0, height, kEdgeZ), looking straight down:
// the centre column's luminance against z (row r at z = kEdgeZ + (r + 0.5 - H / 2) pixel, the
// image's top towards -z).
Edge edgeSeenFrom(const assets::LoadedLevel& level, float height, uint32_t cascades) {
    render::RendererOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.sunCascades = cascades;
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({0.0f, height, kEdgeZ}, 0.0f, -90.0f);
    inputs.camera.yfov = kYfov;
    const test::RenderedFrame r = test::renderOnce(level, options, inputs);
    EXPECT_EQ(r.validationErrors, 0u);
    const float pixel = 2.0f * height * std::tan(0.5f * kYfov) / float(kHeight);
    std::vector<float> z(kHeight), lum(kHeight);
    for (uint32_t row = 0; row < kHeight; ++row) {
        const float* px = &r.frame.linearRgba[(size_t(row) * kWidth + kWidth / 2) * 4];
        z[row] = kEdgeZ + (float(row) + 0.5f - 0.5f * float(kHeight)) * pixel;
        lum[row] = 0.2126f * px[0] + 0.7152f * px[1] + 0.0722f * px[2];
    }
    auto at = [&](float zw) {
        const int row = std::clamp(int(std::floor((zw - kEdgeZ) / pixel + 0.5f * float(kHeight))),
                                   0, int(kHeight) - 1);
        return lum[size_t(row)];
    };
    const float shadowed = at(kEdgeZ - 1.0f), lit = at(kEdgeZ + 1.0f);
    Edge e;
    e.contrast = lit / std::max(shadowed, 1e-9f);
    // The first row, going towards +z from 1 m inside the shadow, past each fraction.
    auto crossing = [&](float fraction) {
        const float target = shadowed + fraction * (lit - shadowed);
        for (uint32_t row = 1; row < kHeight; ++row)
            if (z[row] > kEdgeZ - 1.0f && lum[row - 1] < target && lum[row] >= target) {
                const float t = (target - lum[row - 1]) / (lum[row] - lum[row - 1]);
                return z[row - 1] + t * (z[row] - z[row - 1]);
            }
        return 1e30f;
    };
    e.position = crossing(0.5f);
    e.width = crossing(0.9f) - crossing(0.1f);
    return e;
}

// The world size of a texel of the cascade that covers view distance `d`.
float cascadeTexel(float d, float levelDiagonal) {
    const std::vector<float> splits =
        render::sunCascadeSplits(world::kRuntimeShadowRadius, 3, levelDiagonal);
    size_t k = 0;
    while (k + 1 < splits.size() && d > splits[k]) ++k;
    return 2.0f * render::sunCascadeExtent(splits[k], levelDiagonal) / 1024.0f;
}

TEST(SunCascades, TheShadowEdgeIsWhereTheGeometryPutsItAndAsSharpAsItsCascade) {
    const assets::LoadedLevel level = wallInTheSun();
    const float diagonal = glm::length(glm::vec3(120.0f, 3.0f, 120.0f));
    ASSERT_EQ(render::sunCascadeSplits(world::kRuntimeShadowRadius, 3, diagonal).size(), 3u);
    float nearTexel = 0.0f;
    Edge nearEdge;
    for (const float height : {3.0f, 10.0f, 30.0f}) {
        const Edge e = edgeSeenFrom(level, height, 3);
        const float texel = cascadeTexel(height, diagonal);
        const float pixel = 2.0f * height * std::tan(0.5f * kYfov) / float(kHeight);
        std::printf(
            "[ sun cascades ] %4.0f m: texel %.2f cm, pixel %.2f cm; edge at %+.2f cm "
            "from the geometry's, 10-90%% width %.2f cm, contrast %.1f\n",
            double(height), 100.0 * double(texel), 100.0 * double(pixel),
            100.0 * double(e.position - kEdgeZ), 100.0 * double(e.width), double(e.contrast));
        EXPECT_GT(e.contrast, 5.0f) << height << " m: no shadow, or no sun";
        // The filter is a 3-texel tent (10-90%: about 2 texels), plus a pixel's footprint.
        EXPECT_LT(e.width, 2.5f * texel + 2.0f * pixel) << height << " m";
        // The receiver's lookup moves up to 1.5 texels along the normal (forward_shading.glsl),
        // which at 45 degrees moves the edge as far; the depth bias a little more.
        EXPECT_LT(std::fabs(e.position - kEdgeZ), 2.5f * texel + pixel) << height << " m";
        if (height == 3.0f) {
            nearTexel = texel;
            nearEdge = e;
        }
    }
    // One map over the whole radius: the near edge blurred over its 10 cm texels.
    const Edge single = edgeSeenFrom(level, 3.0f, 1);
    std::printf("[ sun cascades ] one map: near edge 10-90%% width %.2f cm (cascades: %.2f cm)\n",
                100.0 * double(single.width), 100.0 * double(nearEdge.width));
    EXPECT_GT(single.width, 3.0f * nearEdge.width);
    EXPECT_GT(single.width, 5.0f * nearTexel);
}

// Over the last tenth of a cascade's range the lookup blends into the next cascade's: an edge
// seen from just inside the band is wider than just before it and narrower than just past the
// split (without the blend it jumps from cascade 0's width to cascade 1's at the split).
TEST(SunCascades, AnEdgeSoftensGraduallyAcrossASplit) {
    const assets::LoadedLevel level = wallInTheSun();
    const float diagonal = glm::length(glm::vec3(120.0f, 3.0f, 120.0f));
    const float split = render::sunCascadeSplits(world::kRuntimeShadowRadius, 3, diagonal)[0];
    const Edge before = edgeSeenFrom(level, 0.89f * split, 3);
    const Edge inBand = edgeSeenFrom(level, 0.95f * split, 3);
    const Edge past = edgeSeenFrom(level, 1.01f * split, 3);
    std::printf(
        "[ sun cascades ] across the split at %.2f m: 10-90%% width %.2f cm at 0.89 of "
        "it, %.2f cm at 0.95, %.2f cm at 1.01\n",
        double(split), 100.0 * double(before.width), 100.0 * double(inBand.width),
        100.0 * double(past.width));
    EXPECT_GT(inBand.width, 1.4f * before.width);
    EXPECT_LT(inBand.width, 0.9f * past.width);
}

// A level smaller than the near cascades needs only the one map that already spans it.
TEST(SunCascades, ALevelSmallerThanACascadeHasOnlyOne) {
    EXPECT_EQ(render::sunCascadeSplits(40.0f, 3, 4.0f).size(), 1u);
    EXPECT_EQ(render::sunCascadeSplits(40.0f, 3, 4.0f).back(), 40.0f);
    EXPECT_EQ(render::sunCascadeSplits(40.0f, 3, 10.0f).size(), 2u);
    EXPECT_EQ(render::sunCascadeSplits(40.0f, 3, 1000.0f).size(), 3u);
    EXPECT_EQ(render::sunCascadeSplits(40.0f, 1, 1000.0f).size(), 1u);
    EXPECT_EQ(render::sunCascadeSplits(40.0f, 0, 1000.0f).size(), 1u);
}

}  // namespace
