// Lightmap density per chart from a pilot pass (bake/lightmap/chart_density.hpp): a chart whose
// light is uniform gets a thirty-second of the texels per axis, one with a hard shadow keeps
// them all, and the choice does not depend on threads.
#include <algorithm>
#include <cstdint>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "bake/lightmap/chart_density.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "bake_scenes.hpp"

namespace onelight::bake {
namespace {

/// A 30 x 30 m floor under a sun and a black sky; with a plate 1 m over it when `plate`.
world::SourceLevel openFloor(bool plate) {
    world::SourceLevel level;
    const uint32_t m = test::addLambertMaterial(level, 0.5f);
    test::addQuad(level, {-15, -15, 0}, {15, -15, 0}, {15, 15, 0}, {-15, 15, 0}, m, "floor");
    if (plate) {
        test::addQuad(level, {-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}, {1, -1, 1}, m, "plate_bottom");
        test::addQuad(level, {-1, -1, 1.01f}, {1, -1, 1.01f}, {1, 1, 1.01f}, {-1, 1, 1.01f}, m,
                      "plate_top");
    }
    level.lights.push_back(test::sunLight({0.3f, 0.2f, -1.0f}, 20000.0f));
    return level;
}

// The index of the chart with the most texels.
size_t largestChart(const world::CompiledLevel& level) {
    size_t largest = 0;
    for (size_t c = 0; c < level.charts.size(); ++c)
        if (level.charts[c].width * level.charts[c].height >
            level.charts[largest].width * level.charts[largest].height)
            largest = c;
    return largest;
}

BakeOptions adaptive(float texelsPerMetre) {
    BakeOptions o = test::testOptions(texelsPerMetre, BakeQuality::kDraft);
    o.compile.charts.atlasSize = 1024;
    o.adaptiveDensity = true;
    return o;
}

// The floor with its plate, baked at the requested density, and its texels.
struct PlateOverFloor {
    world::SourceLevel level = openFloor(true);
    BakeResult full = bakeLevel(level, [] {
        BakeOptions options = adaptive(8.0f);
        options.adaptiveDensity = false;
        return options;
    }());
    test::LevelScene scene{level};
    std::vector<TexelSample> samples = placeTexels(full.level);
};

// The open floor's light is the same everywhere (the sun, unshadowed; nothing to bounce off):
// its chart gets the largest reduction, 32 per axis, so ~1/1000 of the texels, and every texel
// still holds the exact answer: the mask 255 and no secondary light.
TEST(ChartDensity, AnOpenFloorUnderTheSunGetsAThousandthOfTheTexels) {
    const BakeResult coarse = bakeLevel(openFloor(false), adaptive(16.0f));
    std::printf("open floor: %llu texels sampled instead of %llu, %u charts reduced\n",
                static_cast<unsigned long long>(coarse.report.texelsSampled),
                static_cast<unsigned long long>(coarse.report.texelsBeforeDensity),
                coarse.report.chartsReduced);
    EXPECT_EQ(coarse.report.chartsReduced, 1u);
    EXPECT_GT(coarse.report.texelsBeforeDensity, 200000u);
    EXPECT_LT(coarse.report.texelsSampled * 500, coarse.report.texelsBeforeDensity);
    for (const TexelSample& s : placeTexels(coarse.level)) {
        ASSERT_EQ(coarse.baked.shadowMask[s.texel], 255);
        ASSERT_EQ(coarse.baked.texels[s.texel].irradiance, glm::vec3(0.0f));
    }
}

// A plate's hard shadow on the floor: the floor's chart keeps its density (a shadow edge is a
// second difference of the whole light), while the plate's own charts, uniformly lit (its top)
// or dark (its underside, lit only by the floor's bounce, whose distance is 1 m), may coarsen.
TEST(ChartDensity, AHardShadowKeepsItsChartsDensity) {
    const PlateOverFloor p;
    const auto& [level, full, scene, samples] = std::tie(p.level, p.full, p.scene, p.samples);
    const std::vector<float> scales =
        chartDensityScales(scene.scene, scene.lights, full.level, samples, {});
    ASSERT_EQ(scales.size(), full.level.charts.size());
    const size_t floor = largestChart(full.level);  // the floor
    EXPECT_EQ(scales[floor], 1.0f);
    // And the same scales on one thread.
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_EQ(chartDensityScales(scene.scene, scene.lights, full.level, samples, {}), scales);
}

// An error budget judges the floor from its views: seen only within the runtime's shadow reach,
// the plate's shadow on it is the runtime's shadow map's, not the mask's, so the floor may
// coarsen (its lightmap holds the sun's bounce off the plate's underside, smooth at this
// tolerance); seen from farther, the mask shows and the floor keeps its density.
TEST(ChartDensity, ABudgetJudgesAShadowByWhetherAnyViewSeesItsMask) {
    const PlateOverFloor p;
    const auto& [level, full, scene, samples] = std::tie(p.level, p.full, p.scene, p.samples);
    const size_t floor = largestChart(full.level);
    ChartDensitySettings near;
    near.curvatureTolerance = 0.1f;
    near.distanceQuantile = 0.02f;
    near.views = {glm::vec3(0.0f, -3.0f, 1.7f)};  // 3 m from the plate; the floor within 22 m
    near.maskDistance = 32.0f;
    ChartDensitySettings far = near;
    far.views.push_back(glm::vec3(60.0f, 0.0f, 10.0f));  // 45 m and more from the floor
    const float nearScale =
        chartDensityScales(scene.scene, scene.lights, full.level, samples, near)[floor];
    const float farScale =
        chartDensityScales(scene.scene, scene.lights, full.level, samples, far)[floor];
    std::printf("floor's density scale: %g seen near, %g seen from afar\n", double(nearScale),
                double(farScale));
    EXPECT_LT(nearScale, 1.0f);
    EXPECT_EQ(farScale, 1.0f);
}

}  // namespace
}  // namespace onelight::bake
