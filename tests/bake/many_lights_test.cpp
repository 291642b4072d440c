// Many lights drawn by importance (issue 14): the light cells' probabilities, and a floor under
// 64 lights baked with lights drawn by importance against every light evaluated.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "bake/lighting/light_cells.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "bake_scenes.hpp"

namespace onelight::bake {
namespace {

LightBound pointBound(glm::vec3 p, float power, float range) {
    LightBound b;
    b.lo = b.hi = p;
    b.power = power;
    b.range = range;
    return b;
}

// In every cell the probabilities of its sources sum to 1, pickLight draws what
// lightProbability states, and a light whose range ends far from a cell is never drawn there.
TEST(LightCells, ProbabilitiesSumToOneAndRangesAreHonoured) {
    std::vector<LightBound> sources;
    for (int i = 0; i < 10; ++i)
        sources.push_back(pointBound({float(i) * 10.0f, 0, 0}, 100.0f, i % 2 ? 3.0f : 0.0f));
    const LightCells cells = buildLightCells(sources, {0, -5, -5}, {90, 5, 5});
    ASSERT_FALSE(cells.empty());
    for (size_t c = 0; c + 1 < cells.first.size(); ++c) {
        if (cells.first[c + 1] == cells.first[c]) continue;
        double total = 0.0;
        for (uint32_t e = cells.first[c]; e < cells.first[c + 1]; ++e)
            total += double(cells.entries[e].probability);
        EXPECT_NEAR(total, 1.0, 1e-5);
    }
    // Near light 1 (range 3): it is drawn, light 3 (range 3, 20 m away) never.
    const glm::vec3 x(10.5f, 0.5f, 0.0f);
    EXPECT_GT(lightProbability(cells, x, 1), 0.3f);
    EXPECT_EQ(lightProbability(cells, x, 3), 0.0f);
    // Unlimited lights far away are still drawn, with a small probability.
    EXPECT_GT(lightProbability(cells, x, 8), 0.0f);
    double sum = 0.0;
    for (uint32_t s = 0; s < sources.size(); ++s) sum += double(lightProbability(cells, x, s));
    EXPECT_NEAR(sum, 1.0, 1e-5);
    // The alias table draws each source with its stated probability: 100k stratified draws
    // land within 0.1% of it (stratified: the error is the table's rounding, not noise).
    std::vector<double> drawn(sources.size(), 0.0);
    constexpr int kDraws = 100000;
    for (int i = 0; i < kDraws; ++i) {
        const LightPick pick = pickLight(cells, x, (float(i) + 0.5f) / float(kDraws));
        ASSERT_GT(pick.probability, 0.0f);
        ASSERT_LT(pick.source, sources.size());
        EXPECT_EQ(pick.probability, lightProbability(cells, x, pick.source));
        drawn[pick.source] += 1.0 / kDraws;
    }
    for (uint32_t s = 0; s < sources.size(); ++s)
        EXPECT_NEAR(drawn[s], double(lightProbability(cells, x, s)), 1e-3) << "source " << s;
    EXPECT_EQ(drawn[3], 0.0);
    // Outside the grid every light with power can be drawn.
    EXPECT_GT(lightProbability(cells, {500, 0, 0}, 3), 0.0f);
}

// A spot's cone decides where it can be drawn: never behind it.
TEST(LightCells, SpotIsNotDrawnBehindItsCone) {
    LightBound spot = pointBound({0, 0, 0}, 100.0f, 0.0f);
    spot.axis = {1, 0, 0};
    spot.cosOuter = std::cos(0.4f);
    const std::vector<LightBound> sources = {spot, pointBound({0, 0, 0}, 1.0f, 0.0f)};
    const LightCells cells = buildLightCells(sources, {-20, -20, -20}, {20, 20, 20});
    EXPECT_GT(lightProbability(cells, {15, 0, 0}, 0), 0.9f);
    EXPECT_EQ(lightProbability(cells, {-15, 0, 0}, 0), 0.0f);
    EXPECT_EQ(lightProbability(cells, {-15, 0, 0}, 1), 1.0f);
}

// 64 baked point lights (8 x 8, 1 m apart, 1.2 m up) over an 8 x 8 m floor with three blocks
// that cast their shadows. Baked at default quality as the baker does (lights drawn by
// importance, cached bounces) and with every light evaluated along whole paths (each light
// with its 16 shadow rays at every texel and path vertex), the two lightmaps agree within 2%
// RMS of the mean irradiance: both direct estimators are unbiased, the cache's bias is small
// where the light is mostly direct, and the noise (the blocks' penumbrae and the indirect
// light) stays well below that at 4 texels/m. The importance-sampled bake traces at most 1/8
// of the shadow rays.
TEST(ManyLights, SampledLightsAgreeWithEveryLightAtAnEighthOfTheShadowRays) {
    const world::SourceLevel level = test::manyLightsFloor(8);
    BakeOptions options = test::testOptions(4.0f, BakeQuality::kDefault);
    options.gridCellSize = 4.0f;
    const BakeResult sampled = bakeLevel(level, options);
    options.allLights = true;
    options.pathsOnly = true;
    const BakeResult every = bakeLevel(level, options);

    const std::vector<TexelSample> samples = placeTexels(sampled.level);
    double sumSquares = 0.0, sum = 0.0;
    size_t count = 0;
    for (const TexelSample& s : samples) {
        if (!s.centreInside) continue;
        const glm::vec3 a = sampled.baked.texels[s.texel].irradiance;
        const glm::vec3 b = every.baked.texels[s.texel].irradiance;
        ASSERT_TRUE(std::isfinite(a.x + a.y + a.z));
        sumSquares += double(glm::dot(a - b, a - b)) / 3.0;
        sum += double(b.x + b.y + b.z) / 3.0;
        ++count;
    }
    ASSERT_GT(count, 1000u);
    const double rms = std::sqrt(sumSquares / double(count)) / (sum / double(count));
    EXPECT_LT(rms, 0.02) << "RMS difference " << rms;
    RecordProperty("rms", std::to_string(rms));
    const auto shadowRays = [](const BakeResult& r) {
        for (const StageReport& stage : r.report.stages)
            if (stage.name == "lightmaps") return stage.rays.shadow;
        return uint64_t(0);
    };
    EXPECT_GT(shadowRays(sampled), 0u);
    RecordProperty("shadow_ray_ratio",
                   std::to_string(double(shadowRays(sampled)) / double(shadowRays(every))));
    EXPECT_LE(shadowRays(sampled) * 8, shadowRays(every))
        << shadowRays(sampled) << " against " << shadowRays(every);
    EXPECT_TRUE(test::allFiniteNonNegative(sampled.baked));
}

}  // namespace
}  // namespace onelight::bake
