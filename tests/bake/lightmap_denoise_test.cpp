// The lightmap denoiser (bake/lightmap/lightmap_denoise.hpp) on fields whose answer is known:
// uniform and linear fields laid on a room's texels (every chart border and corner of a closed
// room, where windows are cut), and a bake with a hard shadow edge.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "bake/lightmap/lightmap_bake.hpp"
#include "bake/lightmap/lightmap_denoise.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "bake_scenes.hpp"

namespace onelight::bake {
namespace {

using world::LightRole;

/// A closed 4 x 3 x 2.5 m room, compiled at 8 texels per metre, with its Embree scene and
/// texel samples: ~3.8k texels over six charts.
world::SourceLevel closedRoom() {
    world::SourceLevel level;
    const uint32_t m = test::addLambertMaterial(level, 0.5f);
    test::addBox(level, {-2.0f, -1.5f, 0.0f}, {2.0f, 1.5f, 2.5f}, m, true, "room");
    return level;
}

struct RoomTexels {
    const BakeResult result = bakeLevel(closedRoom(), test::testOptions(8.0f, BakeQuality::kDraft));
    const EmbreeDevice device;
    const BakeScene scene{device, result.level};
    const std::vector<TexelSample> samples = placeTexels(result.level);
    const TexelHash hash = makeTexelHash(samples);
};

/// Deterministic standard normal deviates (Box-Muller over a 64-bit LCG, so the field is the
/// same on every standard library).
struct Normal {
    uint64_t state;
    double uniform() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return (double(state >> 11) + 0.5) * 0x1.0p-53;
    }
    double next() {
        return std::sqrt(-2.0 * std::log(uniform())) * std::cos(6.283185307179586 * uniform());
    }
};

/// An estimate of `value` lux of indirect light (grey), declared to have relative standard
/// error `noise`, its rays started just off the surface and their hits 2 m away.
TexelEstimate estimateOf(const TexelSample& s, double value, double noise) {
    TexelEstimate e;
    e.origin = s.position + 1e-3f * s.normal;
    e.indirect = glm::dvec3(value);
    e.indirectLuminance = value;
    e.indirectDirection = value * glm::dvec3(s.normal);
    e.noise = noise * value;
    e.harmonicDistance = 2.0f;
    return e;
}

std::vector<DenoisedIndirect> denoiseAll(const RoomTexels& room,
                                         const std::vector<TexelEstimate>& estimates) {
    std::vector<DenoisedIndirect> out;
    RayCounts rays;
    for (size_t i = 0; i < room.samples.size(); ++i)
        out.push_back(denoiseTexel(room.scene, room.hash, room.samples, estimates, i,
                                   DenoiseSettings{}, rays));
    return out;
}

// A field that is exactly uniform, though each texel declares 10% noise so that every window
// opens to its widest: the filter's weights sum to one at every texel, cut windows at the
// room's edges and corners included, so the field stays uniform to rounding.
TEST(LightmapDenoise, AUniformFieldStaysExactlyUniformUpToTheRoomsEdges) {
    const RoomTexels room;
    ASSERT_GT(room.samples.size(), 3000u);
    std::vector<TexelEstimate> estimates;
    for (const TexelSample& s : room.samples) estimates.push_back(estimateOf(s, 40.0, 0.1));
    const std::vector<DenoisedIndirect> d = denoiseAll(room, estimates);
    size_t widest = 0;
    for (size_t i = 0; i < d.size(); ++i) {
        ASSERT_NEAR(d[i].indirectLuminance, 40.0, 40.0 * 1e-9) << "texel " << i;
        ASSERT_NEAR(d[i].indirect.g, 40.0, 40.0 * 1e-9) << "texel " << i;
        widest += d[i].radius == kDenoiseMaxRadius;
    }
    EXPECT_GT(widest, d.size() / 2);  // the windows did open
}

// A field linear in position on every wall (a + g . centre): the local-linear fit reproduces
// it, also where a chart's edge or a corner cuts the window on one side (a weighted mean
// would pull edge texels towards the inner ones by about half a window's slope).
TEST(LightmapDenoise, ALinearFieldIsKeptAtChartEdgesAndCorners) {
    const RoomTexels room;
    const glm::dvec3 g(3.0, -2.0, 4.0);  // lux per metre
    const auto field = [&](const TexelSample& s) {
        return 40.0 + glm::dot(g, glm::dvec3(s.centre));
    };
    std::vector<TexelEstimate> estimates;
    for (const TexelSample& s : room.samples) estimates.push_back(estimateOf(s, field(s), 0.1));
    const std::vector<DenoisedIndirect> d = denoiseAll(room, estimates);
    double worst = 0.0;
    for (size_t i = 0; i < d.size(); ++i)
        worst = std::max(worst, std::fabs(d[i].indirectLuminance - field(room.samples[i])));
    // The ridge on the slopes (1e-3 of the weight sum) leaves ~1e-3 of a window's slope
    // (g 5.4 lux/m over 0.7 m) at texels whose window is one texel wide: 0.01 lux.
    EXPECT_LT(worst, 0.01);
}

// A uniform field of 40 lux with 10% Gaussian noise per texel: the filter brings the spread
// down to about what its widest window promises (0.1 x 0.14) and keeps the mean within 0.1%
// of the input's. Each output is a weighted sum whose weights sum to one, so the mean moves
// only by how unevenly the texels are weighted across the room (edges count less than inner
// texels): ~0.03% expected at 10% noise over 3.8k texels; 0.1% is three times that.
TEST(LightmapDenoise, ANoisyUniformFieldKeepsItsMeanWithinATenthOfAPercent) {
    const RoomTexels room;
    Normal normal{12345};
    std::vector<TexelEstimate> estimates;
    double inputSum = 0.0, inputSq = 0.0;
    for (const TexelSample& s : room.samples) {
        const double value = 40.0 * (1.0 + 0.1 * normal.next());
        estimates.push_back(estimateOf(s, value, 0.1));
        inputSum += value;
        inputSq += (value - 40.0) * (value - 40.0);
    }
    const std::vector<DenoisedIndirect> d = denoiseAll(room, estimates);
    double outputSum = 0.0, outputSq = 0.0;
    for (const DenoisedIndirect& t : d) {
        ASSERT_TRUE(std::isfinite(t.indirectLuminance));
        outputSum += t.indirectLuminance;
        outputSq += (t.indirectLuminance - 40.0) * (t.indirectLuminance - 40.0);
    }
    const double n = double(d.size());
    const double inputMean = inputSum / n, outputMean = outputSum / n;
    std::printf("uniform field: mean %.4f -> %.4f, spread %.4f -> %.4f\n", inputMean, outputMean,
                std::sqrt(inputSq / n) / 40.0, std::sqrt(outputSq / n) / 40.0);
    EXPECT_LT(std::fabs(outputMean - inputMean) / inputMean, 1e-3);
    EXPECT_LT(std::sqrt(outputSq / n) / 40.0, 0.03);  // from 0.1
}

/// The x where a floor row's total irradiance first rises past `fraction` of the way from its
/// dark to its lit level (x increasing), by linear interpolation between texel centres.
double edgeCrossing(const std::vector<std::pair<double, double>>& row, double dark, double lit,
                    double fraction) {
    const double half = dark + fraction * (lit - dark);
    for (size_t k = 1; k < row.size(); ++k)
        if (row[k - 1].second < half && row[k].second >= half)
            return row[k - 1].first + (half - row[k - 1].second) /
                                          (row[k].second - row[k - 1].second) *
                                          (row[k].first - row[k - 1].first);
    return 1e9;
}

// A baked point light 2 m over an open floor, and a plate at 1 m covering x < 0: the floor's
// shadow edge lies at x = 0 with a penumbra of 2 x 0.05 m (the light's radius) x 1 / 1 = 0.1 m,
// under a texel (0.125 m). The denoiser filters the indirect part only (here what the plate's
// unlit underside returns of the floor's light), so the lightmap's edge, found row by row at
// half-way, stays where it was traced: within one texel of the undenoised bake's and of the
// geometric edge, and as sharp: its 10-90% rise within a texel and the penumbra, as wide as
// undenoised (a filter of the direct light would spread it over its window, up to 11 texels).
TEST(LightmapDenoise, AHardShadowEdgeStaysWithinOneTexel) {
    world::SourceLevel level;
    const uint32_t m = test::addLambertMaterial(level, 0.5f);
    test::addQuad(level, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}, m, "floor");
    test::addQuad(level, {-2, -2, 1}, {-2, 2, 1}, {0, 2, 1}, {0, -2, 1}, m, "plate_bottom");
    test::addQuad(level, {-2, -2, 1.01f}, {0, -2, 1.01f}, {0, 2, 1.01f}, {-2, 2, 1.01f}, m,
                  "plate_top");
    level.lights.push_back(test::pointLight({0, 0, 2}, 100.0f, LightRole::kBaked));
    BakeOptions options = test::testOptions(8.0f, BakeQuality::kDefault);
    const BakeLights lights = makePunctualLights(level.lights, options.lightSizes, glm::vec3(0.0f));
    const BakeResult denoised = bakeLevel(level, options);
    options.noDenoise = true;
    const BakeResult raw = bakeLevel(level, options);
    const std::vector<TexelSample> samples = placeTexels(denoised.level);
    ASSERT_EQ(samples.size(), placeTexels(raw.level).size());

    // Floor rows with |y| < 1 (where the light's cosine is still strong), keyed by y.
    std::map<int, std::vector<std::pair<double, double>>> rowsDenoised, rowsRaw;
    for (const TexelSample& s : samples) {
        if (!s.centreInside || s.position.z > 1e-3f || std::fabs(s.position.y) > 1.0f) continue;
        const int key = int(std::lround(s.position.y * 64.0f));
        rowsDenoised[key].push_back(
            {s.position.x,
             luminance(lightmapTotalIrradiance(lights, denoised.level, denoised.baked, s))});
        rowsRaw[key].push_back(
            {s.position.x, luminance(lightmapTotalIrradiance(lights, raw.level, raw.baked, s))});
    }
    ASSERT_GT(rowsDenoised.size(), 10u);
    const double texel = 1.0 / 8.0;
    size_t rows = 0;
    double worstShift = 0.0, worstEdge = 0.0, worstWidth = 0.0;
    for (auto& [key, row] : rowsDenoised) {
        std::vector<std::pair<double, double>>& other = rowsRaw[key];
        std::sort(row.begin(), row.end());
        std::sort(other.begin(), other.end());
        // Dark and lit levels two texels either side of the edge, from the undenoised bake.
        double dark = 0.0, lit = 0.0;
        for (const auto& [x, e] : other) {
            if (std::fabs(x + 2.5 * texel) < 0.5 * texel) dark = e;
            if (std::fabs(x - 2.5 * texel) < 0.5 * texel) lit = e;
        }
        ASSERT_GT(lit, 10.0 * dark) << "row " << key;
        const double edge = edgeCrossing(row, dark, lit, 0.5);
        const double edgeRaw = edgeCrossing(other, dark, lit, 0.5);
        // The rise from 10% to 90%: a filter of the direct light would widen it to its window.
        const double width = edgeCrossing(row, dark, lit, 0.9) - edgeCrossing(row, dark, lit, 0.1);
        const double widthRaw =
            edgeCrossing(other, dark, lit, 0.9) - edgeCrossing(other, dark, lit, 0.1);
        EXPECT_LT(width, texel + 0.1) << "row y " << key / 64.0;  // a texel and the penumbra
        EXPECT_LT(std::fabs(width - widthRaw), 0.1 * texel) << "row y " << key / 64.0;
        worstWidth = std::max(worstWidth, width);
        EXPECT_LT(std::fabs(edge - edgeRaw), texel) << "row y " << key / 64.0;
        EXPECT_LT(std::fabs(edge), texel) << "row y " << key / 64.0;
        worstShift = std::max(worstShift, std::fabs(edge - edgeRaw));
        worstEdge = std::max(worstEdge, std::fabs(edge));
        ++rows;
    }
    std::printf(
        "shadow edge over %zu rows: at most %.4f m from the undenoised bake's, %.4f m "
        "from x = 0, 10-90%% rise within %.4f m (a texel: %.3f m)\n",
        rows, worstShift, worstEdge, worstWidth, texel);
    EXPECT_GT(rows, 10u);
    EXPECT_LT(denoised.report.lightmapDenoisedRelativeNoise,
              denoised.report.lightmapMeanRelativeNoise);
}

}  // namespace
}  // namespace onelight::bake
