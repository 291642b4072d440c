// Normal-and-gloss mips (bake/textures): the gloss tables against closed forms and Monte Carlo
// sampling of the runtime NDF, the mip chains against brute-force recomputation from level 0,
// and the test: a tiled bump map on a glossy floor, each mip's shading against the
// average of the full-resolution shading it covers, for the blit, Black Ops and WWII methods.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "bake/textures/gloss_tables.hpp"
#include "bake/textures/mip_error.hpp"
#include "bake/textures/normal_gloss_mips.hpp"
#include "shading.hpp"

namespace onelight::test {
namespace {

using bake::GlossInversion;
using MipMethod = world::GlossMipMethod;
using bake::NormalGlossChain;
using bake::NormalGlossLevel;

constexpr double kPi = 3.14159265358979323846;
constexpr MipMethod kMethods[] = {MipMethod::kBlit, MipMethod::kBlackOps, MipMethod::kWwii,
                                  MipMethod::kClean};
const char* methodName(MipMethod m) {
    return m == MipMethod::kBlit       ? "blit"
           : m == MipMethod::kBlackOps ? "black ops"
           : m == MipMethod::kWwii     ? "wwii"
                                       : "clean";
}

// A small deterministic generator (splitmix64, Steele et al. 2014): uniform doubles in [0, 1).
struct Random {
    std::uint64_t state;
    double next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        z ^= z >> 31;
        return double(z >> 11) * 0x1.0p-53;
    }
};

// ---------------------------------------------------------------------------------------------
// Independent references for the gloss tables: the integrals in u = cos(theta) done in closed
// form. With b^2 = 1 - alpha^2 and D = alpha^2 / (pi (1 - b^2 u^2)^2) (Walter et al. 2007,
// eq. 33):
//   A = 2 alpha^2 integral_0^1 du / (1 - b^2 u^2)^2 = 1 + alpha^2 atanh(b) / b,
//   var = alpha^2 integral_0^1 (1 - t) / (1 - b^2 t)^2 dt = alpha^2 (alpha^2 - 1 - 2 ln alpha) /
//   b^4
// (t = u^2), with their limits 2 and 1/2 at alpha = 1 (gloss 0), where D = 1/pi.

double excessAreaClosedForm(double gloss) {
    double a = bake::ggxAlpha_fromGloss(gloss);
    double b2 = (1.0 - a) * (1.0 + a);
    if (b2 < 1e-8) return 1.0 + b2 / 3.0;  // atanh(b) / b = 1 + b^2 / 3 + O(b^4)
    double b = std::sqrt(b2);
    return a * a * std::atanh(b) / b;
}

double varianceClosedForm(double gloss) {
    double a = bake::ggxAlpha_fromGloss(gloss);
    double b2 = (1.0 - a) * (1.0 + a);
    if (b2 < 1e-8) return 0.5 - b2 / 6.0;  // (1 - e)(1/2 + e/3 + ...), e = b^2
    return a * a * (a * a - 1.0 - 2.0 * std::log(a)) / (b2 * b2);
}

double lengthDistanceClosedForm(double gloss) {
    double e = excessAreaClosedForm(gloss);
    return e / (1.0 + e);  // 1 - 1 / A
}

TEST(GlossTables, QuadratureMatchesClosedForms) {
    // The trapezoidal rule's error is ~exp(-pi^2 * 16), far below rounding; the closed forms
    // lose a few digits to cancellation near gloss 0. 1e-10 relative leaves room for both.
    for (int i = 0; i <= 1020; ++i) {
        double g = i / 1020.0;
        bake::GgxLobeStatistics s = bake::ggxLobeStatistics(g);
        EXPECT_NEAR(s.excessArea / excessAreaClosedForm(g), 1.0, 1e-10) << "gloss " << g;
        EXPECT_NEAR(s.normalVariance / varianceClosedForm(g), 1.0, 1e-10) << "gloss " << g;
    }
    const bake::GlossTable& lengths = bake::averageNormalLengthTable();
    const bake::GlossTable& variances = bake::normalVarianceTable();
    for (int i = 0; i < bake::GlossTable::kEntries; ++i) {
        double g = i / 255.0;
        EXPECT_NEAR(lengths.log2Distance[std::size_t(i)], std::log2(lengthDistanceClosedForm(g)),
                    1e-9);
        EXPECT_NEAR(variances.log2Distance[std::size_t(i)], std::log2(varianceClosedForm(g)), 1e-9);
    }
}

// Monte Carlo over the runtime NDF, as Chan 2018, Listing 6 measures the average normal: draw
// microfacet normals with pdf D cos (Walter et al. 2007, eq. 35: tan^2 = alpha^2 xi / (1 - xi)),
// stratified in xi, and weight each by D_runtime / (D cos): the runtime's own D (brdf.glsl,
// specularD, in float) over the density the sampler draws from. Each sample returns
// (microsurface area 1 / cos, sin^2) times that weight.
struct MonteCarloStatistics {
    double area, variance;
};

MonteCarloStatistics monteCarloStatistics(double gloss, int samples, std::uint64_t seed) {
    Random random{seed};
    double a = bake::ggxAlpha_fromGloss(gloss);
    double area = 0.0, variance = 0.0;
    for (int j = 0; j < samples; ++j) {
        double xi = std::min((j + random.next()) / samples, 1.0 - 0x1.0p-40);
        double tan2 = a * a * xi / (1.0 - xi);
        double cos2 = 1.0 / (1.0 + tan2), sin2 = tan2 / (1.0 + tan2);
        double density = a * a / (kPi * cos2 * cos2 * (tan2 + a * a) * (tan2 + a * a));  // D
        double runtime = double(glsl::specularD(NDF_GGX, float(sin2), float(gloss)));
        double weight = runtime / density;  // D_runtime / D, ~1
        area += weight / std::sqrt(cos2);
        variance += weight * sin2;
    }
    return {area / samples, variance / samples};
}

TEST(GlossTables, RuntimeNdfMonteCarloMatchesTables) {
    // Average normal length: 1 / cos is integrable but not square-integrable under D cos (it
    // is ~alpha / sqrt(1 - xi) as xi -> 1), so the stratified estimate's error sits in the last
    // stratum: alpha / sqrt(N) / sqrt(1 - u) for its jitter u; 10 alpha / sqrt(N) is exceeded
    // only for 1 - u < 1%, and the seed is fixed. Variance: sin^2 rises from 0 to 1 where
    // 1 - xi ~ alpha^2, inside the last strata at high gloss, each of which moves the estimate
    // by at most 1 / N: 2 / N absolute, plus 1e-5 relative for the float D. Both are far below
    // what a wrong weighting would do (at gloss 0, ns is 1/2, not 1, and var is 1/2, where
    // weighting by area instead gives 2/3).
    constexpr int kSamples = 1 << 18;
    for (double g : {0.0, 0.2, 0.4, 0.6, 0.8, 0.9, 1.0}) {
        MonteCarloStatistics mc = monteCarloStatistics(g, kSamples, 7);
        double a = bake::ggxAlpha_fromGloss(g);
        double area = 1.0 / bake::averageNormalLength_fromGloss(g);
        double variance = bake::normalVariance_fromGloss(g);
        double areaTolerance = 10.0 * a / std::sqrt(double(kSamples));
        double varianceTolerance = 2.0 / kSamples + 1e-5 * variance;
        EXPECT_NEAR(mc.area, area, areaTolerance) << "gloss " << g;
        EXPECT_NEAR(mc.variance, variance, varianceTolerance) << "gloss " << g;
    }
}

TEST(GlossTables, LimitsAtGlossZeroAndOne) {
    // Gloss 0: alpha = 1, D = 1/pi: A = 2 (length 1/2), var = integral of 2 sin^3 cos = 1/2.
    EXPECT_DOUBLE_EQ(bake::ggxAlpha_fromGloss(0.0), 1.0);
    EXPECT_NEAR(bake::averageNormalLength_fromGloss(0.0), 0.5, 1e-12);
    EXPECT_NEAR(bake::normalVariance_fromGloss(0.0), 0.5, 1e-12);
    // Gloss 1: alpha = sqrt(2 / (1 + 2^18)) = 0.00276; the limits alpha^2 ln(2 / alpha) of
    // 1 - length and alpha^2 (2 ln(1 / alpha) - 1) of var hold to O(alpha^2) relative.
    double a = bake::ggxAlpha_fromGloss(1.0);
    EXPECT_NEAR(a, 0.0027621, 1e-7);
    EXPECT_NEAR((1.0 - bake::averageNormalLength_fromGloss(1.0)) / (a * a * std::log(2.0 / a)), 1.0,
                1e-4);
    EXPECT_NEAR(bake::normalVariance_fromGloss(1.0) / (a * a * (2.0 * std::log(1.0 / a) - 1.0)),
                1.0, 1e-4);
    // Out of range and hostile inputs clamp.
    EXPECT_EQ(bake::gloss_fromAverageNormalLength(0.3), 0.0);  // shorter than any lobe's
    EXPECT_EQ(bake::gloss_fromAverageNormalLength(1.0), 1.0);
    EXPECT_EQ(bake::gloss_fromAverageNormalLength(std::nan("")), 0.0);
    EXPECT_EQ(bake::gloss_fromNormalVariance(0.9), 0.0);
    EXPECT_EQ(bake::gloss_fromNormalVariance(0.0), 1.0);
    EXPECT_EQ(bake::gloss_fromNormalVariance(1e-7), 1.0);
    // The double gloss conversions are the runtime's (float) ones.
    for (int i = 0; i <= 20; ++i) {
        double g = i / 20.0;
        EXPECT_NEAR(bake::ggxAlpha_fromGloss(g) / double(glsl::ggxAlpha_fromGloss(float(g))), 1.0,
                    1e-6);
        float back = glsl::gloss_fromRoughness(float(bake::roughness_fromGloss(g)));
        EXPECT_NEAR(double(back), g, 1e-5) << "gloss " << g;
    }
}

TEST(GlossTables, MonotoneAndInversionsRoundTrip) {
    for (const bake::GlossTable* t :
         {&bake::averageNormalLengthTable(), &bake::normalVarianceTable()})
        for (int i = 1; i < bake::GlossTable::kEntries; ++i)
            EXPECT_LT(t->log2Distance[std::size_t(i)], t->log2Distance[std::size_t(i) - 1]);
    // Forward and inverse interpolate one piecewise-linear curve: they invert each other to
    // rounding (the log2 / exp2 pair, ~1e-15).
    double previousLength = 0.0, previousVariance = 1.0;
    for (int i = 0; i <= 10000; ++i) {
        double g = i / 10000.0;
        double length = bake::averageNormalLength_fromGloss(g);
        double variance = bake::normalVariance_fromGloss(g);
        EXPECT_GT(length, previousLength);
        EXPECT_LT(variance, previousVariance);
        previousLength = length;
        previousVariance = variance;
        EXPECT_NEAR(bake::gloss_fromAverageNormalLength(length), g, 1e-12);
        EXPECT_NEAR(bake::gloss_fromNormalVariance(variance), g, 1e-12);
    }
    for (const bake::GlossTable* t :
         {&bake::averageNormalLengthTable(), &bake::normalVarianceTable()})
        for (int i = 0; i <= 1000; ++i) {
            double y = t->log2Distance.front() +
                       (t->log2Distance.back() - t->log2Distance.front()) * (i / 1000.0);
            double d = std::exp2(y);
            EXPECT_NEAR(bake::distance_fromGloss(*t, bake::gloss_fromDistance(*t, d)) / d, 1.0,
                        1e-12);
        }
}

TEST(GlossTables, InterpolationBetweenEntriesIsAccurate) {
    // Linear interpolation of the smooth log2(distance) at spacing 1/255 errs by
    // h^2 / 8 |y''|: measured 4.9e-5 relative in distance and 1.7e-5 in gloss; bounds 2x that,
    // well under the 8-bit gloss step 1/255 = 3.9e-3.
    double worstDistance = 0.0, worstGloss = 0.0;
    for (int i = 0; i < 2550; ++i) {
        double g = (i + 0.5) / 2550.0;
        double length = lengthDistanceClosedForm(g), variance = varianceClosedForm(g);
        worstDistance = std::max(
            {worstDistance,
             std::abs(bake::distance_fromGloss(bake::averageNormalLengthTable(), g) / length - 1),
             std::abs(bake::distance_fromGloss(bake::normalVarianceTable(), g) / variance - 1)});
        worstGloss = std::max(
            {worstGloss,
             std::abs(bake::gloss_fromDistance(bake::averageNormalLengthTable(), length) - g),
             std::abs(bake::gloss_fromDistance(bake::normalVarianceTable(), variance) - g)});
    }
    EXPECT_LT(worstDistance, 1e-4);
    EXPECT_LT(worstGloss, 4e-5);
}

TEST(GlossTables, RationalFits) {
    for (const bake::GlossFit* fit :
         {&bake::averageNormalLengthFit(), &bake::normalVarianceFit()}) {
        std::printf("gloss = P(x) / Q(x), x = (-log2(d) - %.6f) / %.6f\n  P:", fit->xMin,
                    fit->xMax - fit->xMin);
        for (double c : fit->p) std::printf(" %+.9e", c);
        std::printf("\n  Q:");
        for (double c : fit->q) std::printf(" %+.9e", c);
        std::printf("\n  error in gloss over the table: max %.2e, rms %.2e\n", fit->maxGlossError,
                    fit->rmsGlossError);
        // Under 1/8 of an 8-bit gloss step (measured 4.6e-4 and 3.0e-4 max, 1.1e-4 and 6e-5 RMS).
        EXPECT_LT(fit->maxGlossError, 5e-4);
        EXPECT_LT(fit->rmsGlossError, 1.5e-4);
        // Q has no zero on [0, 1].
        for (int i = 0; i <= 100; ++i) {
            double x = i / 100.0, q = 0.0;
            for (std::size_t k = fit->q.size(); k-- > 0;) q = q * x + fit->q[k];
            EXPECT_GT(q, 0.0);
        }
    }
    // Against the closed forms between entries too, and monotone.
    double worst = 0.0, previousLength = 1.0, previousVariance = 1.0;
    for (int i = 0; i <= 2550; ++i) {
        double g = i / 2550.0;
        double fromLength =
            bake::gloss_fromDistance(bake::averageNormalLengthFit(), lengthDistanceClosedForm(g));
        double fromVariance =
            bake::gloss_fromDistance(bake::normalVarianceFit(), varianceClosedForm(g));
        worst = std::max({worst, std::abs(fromLength - g), std::abs(fromVariance - g)});
        if (i > 0) {
            EXPECT_GE(fromLength, previousLength - 1e-12);
            EXPECT_GE(fromVariance, previousVariance - 1e-12);
        }
        previousLength = fromLength;
        previousVariance = fromVariance;
    }
    EXPECT_LT(worst, 5e-4);
}

// The runtime's fold of a filtered normal-map fetch into gloss (shaders/material.glsl), in float,
// against the double tables and closed forms of bake/textures.
TEST(GlossTables, ShaderFoldOfAFilteredNormal) {
    // The shader's excess area against the closed form; its fit against the fit.
    double worstArea = 0.0, worstFit = 0.0;
    for (int i = 0; i <= 1000; ++i) {
        const double g = i / 1000.0;
        const double area = double(glsl::ggxExcessArea(glsl::ggxAlpha_fromGloss(float(g))));
        worstArea = std::max(worstArea, std::abs(area / excessAreaClosedForm(g) - 1.0));
        const double d = std::exp2(-16.0 * g);  // 1 .. 2^-16, past both ends of the table
        worstFit = std::max(worstFit,
                            std::abs(double(glsl::gloss_fromAverageNormalDistance(float(d))) -
                                     bake::gloss_fromDistance(bake::averageNormalLengthFit(), d)));
    }
    std::printf("  ggxExcessArea: max relative error %.2e; fit in float: max %.2e in gloss\n",
                worstArea, worstFit);
    EXPECT_LT(worstArea, 2e-5);  // float alpha (exp2, sqrt) and log: a few ulps of alpha^2
    EXPECT_LT(worstFit, 2e-5);   // the same P3/Q2 in float
    EXPECT_EQ(glsl::gloss_fromAverageNormalDistance(0.0f), 1.0f);
    EXPECT_EQ(glsl::gloss_fromAverageNormalDistance(std::nanf("")), 0.0f);

    Random random{17};
    // Unit normals rounded to 8-bit texels, as the normal textures hold them, keep their gloss.
    for (int i = 0; i < 20000; ++i) {
        const double z = random.next(), phi = 2.0 * kPi * random.next();
        const double r = std::sqrt(1.0 - z * z);
        const glm::dvec3 n(r * std::cos(phi), r * std::sin(phi), z);
        glm::vec3 texel;
        for (int c = 0; c < 3; ++c)
            texel[c] = float(std::lround((0.5 + 0.5 * n[c]) * 255.0)) / 255.0f * 2.0f - 1.0f;
        const float g = float(random.next());
        ASSERT_EQ(glsl::gloss_withFilteredNormal(g, texel), g) << "texel " << i;
    }
    // A fetch that averages spread normals: the gloss of the lobe whose average normal is the
    // mixture's (the double tables), never glossier; and the offline WWII mip of the same texels
    // agrees where the spread is far above the quantization allowance.
    double worstTable = 0.0, worstMip = 0.0;
    for (int i = 0; i < 2000; ++i) {
        const float g = float(random.next());
        const double spread = 0.05 + 0.6 * random.next();  // slopes
        NormalGlossLevel level{2, 2, {}, {}, {}, {}};
        for (int k = 0; k < 4; ++k) {
            const double phi = 2.0 * kPi * random.next();
            level.normals.push_back(glm::normalize(
                glm::vec3(glm::dvec3(spread * std::cos(phi), spread * std::sin(phi), 1.0))));
            level.gloss.push_back(g);
        }
        const glm::vec3 mean =
            0.25f * (level.normals[0] + level.normals[1] + level.normals[2] + level.normals[3]);
        const float folded = glsl::gloss_withFilteredNormal(g, mean);
        EXPECT_LE(folded, g);
        const double allowance =
            double(std::abs(mean.x) + std::abs(mean.y) + std::abs(mean.z)) / 255.0;
        const double u = 1.0 - glm::length(glm::dvec3(mean)) - allowance;
        if (u > 0.0) {
            const double length = (1.0 - u) * bake::averageNormalLength_fromGloss(g);
            worstTable = std::max(
                worstTable, std::abs(double(folded) - bake::gloss_fromAverageNormalLength(length)));
        }
        if (1.0 - glm::length(glm::dvec3(mean)) > 10.0 * allowance) {
            const bake::NormalGlossChain chain =
                bake::buildNormalGlossMips(level, MipMethod::kWwii);
            worstMip = std::max(worstMip, std::abs(double(folded) - double(chain[1].gloss[0])));
        }
    }
    std::printf(
        "  fold against the tables: max %.2e in gloss; against the offline WWII mip "
        "(spread > 10x the allowance): max %.2e\n",
        worstTable, worstMip);
    EXPECT_LT(worstTable, 1e-3);  // the fit's 4.6e-4 and float
    // The allowance shortens d by at most a tenth: log2 of 0.9 over the table's slope of about
    // 13.3 units per gloss gives 0.011, with the fit's error 0.012.
    EXPECT_LT(worstMip, 0.012);
}

// ---------------------------------------------------------------------------------------------
// Mip chains

NormalGlossLevel constantLevel(int w, int h, glm::vec3 n, float gloss) {
    return {w,
            h,
            std::vector<glm::vec3>(std::size_t(w) * std::size_t(h), n),
            std::vector<float>(std::size_t(w) * std::size_t(h), gloss),
            {},
            {}};
}

// Random unit normals with slopes up to `slope` on each axis, gloss in [gMin, gMax].
NormalGlossLevel randomLevel(int w, int h, double slope, double gMin, double gMax,
                             std::uint64_t seed) {
    Random random{seed};
    NormalGlossLevel level{w, h, {}, {}, {}, {}};
    for (int i = 0; i < w * h; ++i) {
        double sx = slope * (2.0 * random.next() - 1.0), sy = slope * (2.0 * random.next() - 1.0);
        level.normals.push_back(glm::vec3(glm::normalize(glm::dvec3(-sx, -sy, 1.0))));
        level.gloss.push_back(float(gMin + (gMax - gMin) * random.next()));
    }
    return level;
}

// The floor: tiled bumps h = a sin(2 pi x / P) sin(2 pi y / P) (x, y in texels, at
// texel centres), slope up to `slope` = a 2 pi / P along each axis, normal (-dh/dx, -dh/dy, 1)
// normalised.
NormalGlossLevel bumpLevel(int size, int period, double slope, float gloss) {
    NormalGlossLevel level{size, size, {}, {}, {}, {}};
    const double k = 2.0 * kPi / period;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            double u = (x + 0.5) * k, v = (y + 0.5) * k;
            double dx = slope * std::cos(u) * std::sin(v), dy = slope * std::sin(u) * std::cos(v);
            level.normals.push_back(glm::vec3(glm::normalize(glm::dvec3(-dx, -dy, 1.0))));
            level.gloss.push_back(gloss);
        }
    return level;
}

bool sameBits(const NormalGlossLevel& a, const NormalGlossLevel& b) {
    return a.width == b.width && a.height == b.height && a.normals.size() == b.normals.size() &&
           a.gloss.size() == b.gloss.size() &&
           std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(glm::vec3)) ==
               0 &&
           std::memcmp(a.gloss.data(), b.gloss.data(), a.gloss.size() * sizeof(float)) == 0;
}

TEST(NormalGlossMips, ChainSizesAndFootprintsPartitionLevelZero) {
    const int sizes[][2] = {{1, 1}, {1, 7}, {9, 1}, {2, 2}, {5, 3}, {6, 10}, {37, 23}, {256, 256}};
    for (const auto& s : sizes) {
        int w = s[0], h = s[1];
        NormalGlossChain chain =
            bake::buildNormalGlossMips(constantLevel(w, h, {0, 0, 1}, 0.5f), MipMethod::kWwii);
        int expectedLevels = 1;
        while ((std::max(w, h) >> expectedLevels) > 0) ++expectedLevels;
        ASSERT_EQ(int(chain.size()), expectedLevels) << w << "x" << h;
        EXPECT_EQ(bake::mipLevelCount(w, h), expectedLevels);
        EXPECT_EQ(chain.back().width, 1);
        EXPECT_EQ(chain.back().height, 1);
        for (int k = 0; k < expectedLevels; ++k) {
            EXPECT_EQ(chain[std::size_t(k)].width, std::max(1, w >> k));
            EXPECT_EQ(chain[std::size_t(k)].height, std::max(1, h >> k));
            for (int size : {w, h}) {
                // Along each axis, the footprints of mip k are consecutive, cover [0, size) and
                // are 2^k wide, the last up to 2^(k+1) - 1 (the odd texels it took).
                int n = bake::mipSize(size, k), next = 0;
                for (int x = 0; x < n; ++x) {
                    bake::TexelRange r = bake::mipFootprint(size, k, x);
                    EXPECT_EQ(r.begin, next);
                    int width = r.end - r.begin;
                    if (x + 1 < n)
                        EXPECT_EQ(width, 1 << k);
                    else
                        EXPECT_TRUE(width >= std::min(size, 1 << k) && width < (2 << k));
                    next = r.end;
                }
                EXPECT_EQ(next, size);
            }
        }
    }
    EXPECT_THROW((void)bake::buildNormalGlossMips(NormalGlossLevel{}, MipMethod::kBlit),
                 std::invalid_argument);
    NormalGlossLevel wrong = constantLevel(3, 3, {0, 0, 1}, 0.5f);
    wrong.gloss.pop_back();
    EXPECT_THROW((void)bake::buildNormalGlossMips(wrong, MipMethod::kBlit), std::invalid_argument);
}

TEST(NormalGlossMips, MipZeroIsTheInput) {
    NormalGlossLevel level0 = randomLevel(13, 8, 0.8, 0.0, 1.0, 3);
    for (MipMethod m : kMethods)
        for (GlossInversion inversion : {GlossInversion::Table, GlossInversion::Fit})
            EXPECT_TRUE(sameBits(bake::buildNormalGlossMips(level0, m, inversion)[0], level0))
                << methodName(m);
}

TEST(NormalGlossMips, FlatMapKeepsItsGloss) {
    // A flat footprint of gloss g: Blit averages equal roughnesses, BlackOps finds v = 0 and
    // var(g), Wwii finds length(g); each inverts its own forward curve. Table: the same
    // piecewise-linear curve both ways, so only rounding remains (double sums, float output):
    // 1e-6. Blit: the runtime's float gloss_fromRoughness, 1e-5 (as in LimitsAtGlossZeroAndOne).
    // Fit: its error over the table, plus the table's between entries (InterpolationBetween...).
    const double fitTolerance = std::max(bake::averageNormalLengthFit().maxGlossError,
                                         bake::normalVarianceFit().maxGlossError) +
                                4e-5;
    for (float g : {0.0f, 0.1f, 0.25f, 0.5f, 0.8f, 0.9f, 0.97f, 1.0f})
        for (MipMethod m : kMethods)
            for (GlossInversion inversion : {GlossInversion::Table, GlossInversion::Fit}) {
                double tolerance = m == MipMethod::kBlit                ? 1e-5
                                   : inversion == GlossInversion::Table ? 1e-6
                                                                        : fitTolerance;
                NormalGlossChain chain =
                    bake::buildNormalGlossMips(constantLevel(16, 11, {0, 0, 1}, g), m, inversion);
                for (const NormalGlossLevel& level : chain)
                    for (std::size_t i = 0; i < level.gloss.size(); ++i) {
                        ASSERT_NEAR(double(level.gloss[i]), double(g), tolerance)
                            << methodName(m) << " gloss " << g << " mip " << level.width;
                        ASSERT_EQ(level.normals[i], glm::vec3(0, 0, 1));
                    }
            }
}

TEST(NormalGlossMips, BumpsAtGlossZeroAndOne) {
    NormalGlossLevel rough = bumpLevel(32, 16, 0.5, 0.0f);
    NormalGlossLevel mirror = bumpLevel(32, 16, 0.5, 1.0f);
    for (MipMethod m : kMethods) {
        NormalGlossChain roughChain = bake::buildNormalGlossMips(rough, m);
        NormalGlossChain mirrorChain = bake::buildNormalGlossMips(mirror, m);
        for (std::size_t k = 1; k < roughChain.size(); ++k) {
            float sharpest = 0.0f;
            for (std::size_t i = 0; i < roughChain[k].gloss.size(); ++i) {
                // Nothing gets rougher than gloss 0; the blit's roughness 1 stays 1.
                EXPECT_EQ(roughChain[k].gloss[i], 0.0f) << methodName(m);
                sharpest = std::max(sharpest, mirrorChain[k].gloss[i]);
            }
            // The blit keeps the mirror (the bug); the others see the bumps (1 - (n.nbar)^2 is
            // ~1e-3 already in a 2x2 footprint here, 10x var(1)).
            if (m == MipMethod::kBlit)
                EXPECT_NEAR(double(sharpest), 1.0, 1e-5);
            else
                EXPECT_LT(sharpest, 0.95f) << methodName(m) << " mip " << k;
        }
    }
}

TEST(NormalGlossMips, NormalVariationOnlyRoughens) {
    // BlackOps: v' = v + var(g) >= var(g). Wwii: |sum n_i / cos_i| <= sum 1 / cos_i, so
    // |average| <= 1 / A(g) = length(g). Clean: alpha^2 = alpha(g)^2 + the slopes' variance
    // >= alpha(g)^2. Each way gloss <= g, up to rounding.
    for (float g : {0.3f, 0.8f, 0.95f}) {
        NormalGlossLevel level0 = randomLevel(24, 17, 0.3, g, g, 11);
        for (MipMethod m : {MipMethod::kBlackOps, MipMethod::kWwii, MipMethod::kClean})
            for (const NormalGlossLevel& level : bake::buildNormalGlossMips(level0, m))
                for (float mipGloss : level.gloss) EXPECT_LE(mipGloss, g + 1e-6f);
    }
}

TEST(NormalGlossMips, BaseGlossIsTheTexelsOwnLobesAndCleanAddsTheSlopesVariance) {
    // Level 0's base is its gloss. A mip texel's base is the gloss of its footprint's mean
    // alpha^2, whatever the method, and never rougher than the texel's gloss. With CLEAN the
    // difference of the two alpha^2 is the slopes' variance over both axes (the share the
    // runtime shades as facets, shaders/material.glsl), computed here straight from the
    // footprint. Tolerances: float gloss, and alpha^2 = 2 / (1 + 2^(18 g)) has a slope of at
    // most 12.5 alpha^2 per unit gloss, so 1e-6 in gloss is 1.3e-5 relative in alpha^2.
    auto alpha2 = [](double g) { return 2.0 / (1.0 + std::exp2(18.0 * g)); };
    NormalGlossLevel level0 = randomLevel(37, 23, 0.3, 0.3, 1.0, 29);
    for (MipMethod m : kMethods) {
        NormalGlossChain chain = bake::buildNormalGlossMips(level0, m);
        ASSERT_EQ(chain[0].baseGloss, level0.gloss) << methodName(m);
        for (std::size_t k = 1; k < chain.size(); ++k) {
            const NormalGlossLevel& mip = chain[k];
            ASSERT_EQ(mip.baseGloss.size(), mip.gloss.size());
            for (int y = 0; y < mip.height; ++y)
                for (int x = 0; x < mip.width; ++x) {
                    const bake::TexelRange cols = bake::mipFootprint(37, int(k), x);
                    const bake::TexelRange rows = bake::mipFootprint(23, int(k), y);
                    double sumAlpha2 = 0.0, count = 0.0, s2 = 0.0;
                    glm::dvec2 s(0.0);
                    for (int py = rows.begin; py < rows.end; ++py)
                        for (int px = cols.begin; px < cols.end; ++px) {
                            const std::size_t j = std::size_t(py) * 37 + std::size_t(px);
                            const glm::dvec3 n(level0.normals[j]);
                            const glm::dvec2 slope = glm::dvec2(n.x, n.y) / n.z;
                            sumAlpha2 += alpha2(double(level0.gloss[j]));
                            s += slope;
                            s2 += glm::dot(slope, slope);
                            count += 1.0;
                        }
                    const std::size_t i = std::size_t(y) * std::size_t(mip.width) + std::size_t(x);
                    const double base = double(mip.baseGloss[i]);
                    ASSERT_GE(base, double(mip.gloss[i])) << methodName(m);
                    if (m != MipMethod::kBlit) {  // the blit's gloss can be the rougher of the two
                        ASSERT_NEAR(alpha2(base) / (sumAlpha2 / count), 1.0, 2e-5) << methodName(m);
                    }
                    if (m == MipMethod::kClean) {
                        const glm::dvec2 mean = s / count;
                        const double variance = s2 / count - glm::dot(mean, mean);
                        ASSERT_NEAR((alpha2(double(mip.gloss[i])) - alpha2(base)) / variance, 1.0,
                                    1e-3)
                            << "mip " << k;
                    }
                }
        }
    }
}

// One mip texel straight from its level-0 footprint, by the formulas of the header written out
// directly (Black Ops in the slide's form, sum of 1 - (n_i.nbar)^2, not through moments).
struct DirectTexel {
    glm::dvec3 normal;
    double gloss;
};

DirectTexel directTexel(const NormalGlossLevel& l0, bake::TexelRange xs, bake::TexelRange ys,
                        MipMethod m) {
    glm::dvec3 sumN(0.0), sumNOverCos(0.0);
    double sumRoughness = 0.0, sumVariance = 0.0, sumAreaOverCos = 0.0, k = 0.0;
    double sumAlpha2 = 0.0;
    std::vector<glm::dvec2> slopes;
    for (int y = ys.begin; y < ys.end; ++y)
        for (int x = xs.begin; x < xs.end; ++x) {
            std::size_t i = std::size_t(y) * std::size_t(l0.width) + std::size_t(x);
            glm::dvec3 n = glm::normalize(glm::dvec3(l0.normals[i]));
            double g = double(l0.gloss[i]), c = std::max(n.z, bake::kMinCos);
            sumN += n;
            sumNOverCos += n / c;
            sumRoughness += bake::roughness_fromGloss(g);
            sumVariance += bake::normalVariance_fromGloss(g);
            sumAreaOverCos += 1.0 / bake::averageNormalLength_fromGloss(g) / c;
            sumAlpha2 += bake::ggxAlpha_fromGloss(g) * bake::ggxAlpha_fromGloss(g);
            slopes.push_back(glm::dvec2(n.x, n.y) / c);
            k += 1.0;
        }
    if (m == MipMethod::kClean) {
        // The mixture's variance about its mean, in two passes, and the gloss of its alpha
        // from Chan 2018, eq. 2: alpha^2 = 2 / (1 + 2^(18 g)).
        glm::dvec2 mean(0.0);
        for (const glm::dvec2& s : slopes) mean += s / k;
        double spread = 0.0;
        for (const glm::dvec2& s : slopes) spread += glm::dot(s - mean, s - mean) / k;
        const double alpha2 = sumAlpha2 / k + spread;
        return {glm::normalize(glm::dvec3(mean, 1.0)),
                std::clamp(std::log2(2.0 / alpha2 - 1.0) / 18.0, 0.0, 1.0)};
    }
    if (m == MipMethod::kBlit)
        return {glm::normalize(sumN), double(glsl::gloss_fromRoughness(float(sumRoughness / k)))};
    if (m == MipMethod::kBlackOps) {
        glm::dvec3 nbar = glm::normalize(sumN);
        double v = 0.0;
        for (int y = ys.begin; y < ys.end; ++y)
            for (int x = xs.begin; x < xs.end; ++x) {
                glm::dvec3 n = glm::normalize(glm::dvec3(
                    l0.normals[std::size_t(y) * std::size_t(l0.width) + std::size_t(x)]));
                v += 1.0 - glm::dot(n, nbar) * glm::dot(n, nbar);
            }
        return {nbar, bake::gloss_fromNormalVariance(v / k + sumVariance / k)};
    }
    glm::dvec3 average = sumNOverCos / sumAreaOverCos;
    return {glm::normalize(average), bake::gloss_fromAverageNormalLength(glm::length(average))};
}

// Level 0 of a tileable map whose slopes are `slopes(u, v)` at texel centres (u, v in [0, 1)).
template <typename Slopes>
NormalGlossLevel slopeLevel(int size, Slopes slopes) {
    NormalGlossLevel level{size, size, {}, {}, {}, {}};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const glm::dvec2 s = slopes((x + 0.5) / size, (y + 0.5) / size);
            level.normals.push_back(glm::vec3(glm::normalize(glm::dvec3(-s.x, -s.y, 1.0))));
            level.gloss.push_back(0.8f);
        }
    return level;
}

TEST(NormalGlossMips, SlopeKurtosisOfKnownShapes) {
    // The coarsest mip covers the whole map, so its kurtosis is the map's. Closed forms:
    // - slopes of one length turning (a ring): 1;
    // - an egg crate, s = 0.6 (cos u sin w, sin u cos w): E|s|^4 / (E|s|^2)^2 = (2 (3/8)^2 +
    //   2 (1/8)^2) / (4 (1/4)^2) = 1.25;
    // - two values only, 0 on 3/4 of the texels and a slope on the rest, about their mean:
    //   for a Bernoulli share p = 1/4 of a vector of length L the central kurtosis is
    //   (1 - 3 p + 3 p^2) / (p (1 - p)) = 7/3.
    // Tolerances: the texel-centre sums of a 64 x 64 map are exact for these trigonometric
    // polynomials up to rounding (1e-4 in float normals).
    const double tau = 2.0 * std::numbers::pi;
    const auto ring = [&](double u, double w) {
        return glm::dvec2(std::cos(tau * (u + w)), std::sin(tau * (u + w))) * 0.3;
    };
    const auto egg = [&](double u, double w) {
        return glm::dvec2(std::cos(tau * u) * std::sin(tau * w),
                          std::sin(tau * u) * std::cos(tau * w)) *
               0.6;
    };
    const auto steps = [&](double u, double w) {
        return (u < 0.5 && w < 0.5) ? glm::dvec2(0.4, 0.1) : glm::dvec2(0.0);
    };
    const std::pair<const char*, double> expected[] = {
        {"ring", 1.0}, {"egg crate", 1.25}, {"steps", 7.0 / 3.0}};
    const NormalGlossLevel levels[] = {slopeLevel(64, ring), slopeLevel(64, egg),
                                       slopeLevel(64, steps)};
    for (int k = 0; k < 3; ++k) {
        const NormalGlossChain chain = bake::buildNormalGlossMips(levels[k], MipMethod::kClean);
        ASSERT_EQ(chain.back().slopeKurtosis.size(), 1u);
        EXPECT_NEAR(chain.back().slopeKurtosis[0], expected[k].second, 1e-3) << expected[k].first;
        // Level 0 spreads nothing: the Gaussian's 2, the shader's neutral shape.
        EXPECT_EQ(chain[0].slopeKurtosis.front(), 2.0f);
        for (const NormalGlossLevel& mip : chain)
            for (float value : mip.slopeKurtosis)
                EXPECT_TRUE(std::isfinite(value) && value >= 1.0f);
    }
    // Gaussian slopes: 2, within the sampling of 4096 of them (|s|^2 is exponential, so the
    // estimate's standard error is about 0.1; three of them).
    std::mt19937 random(7);
    std::normal_distribution<double> normal(0.0, 0.2);
    const NormalGlossChain gaussian = bake::buildNormalGlossMips(
        slopeLevel(64, [&](double, double) { return glm::dvec2(normal(random), normal(random)); }),
        MipMethod::kClean);
    EXPECT_NEAR(gaussian.back().slopeKurtosis[0], 2.0, 0.3);
}

TEST(NormalGlossMips, OddAndNonSquareSizesMatchDirectFootprints) {
    // Sums in another order and Black Ops without the moments differ by ~1e-15 before the
    // float output; the gloss inversions are Lipschitz (<= 0.2 gloss per unit of log2(distance)),
    // and distances here are >= 1e-4: 1e-6 is ~10 float ulps.
    const int sizes[][2] = {{1, 1}, {1, 9}, {13, 1}, {5, 3}, {3, 5}, {37, 23}, {64, 7}};
    for (const auto& s : sizes) {
        NormalGlossLevel level0 = randomLevel(s[0], s[1], 0.25, 0.3, 1.0, 17);
        for (MipMethod m : kMethods) {
            NormalGlossChain chain = bake::buildNormalGlossMips(level0, m);
            for (std::size_t k = 1; k < chain.size(); ++k) {
                const NormalGlossLevel& mip = chain[k];
                for (int y = 0; y < mip.height; ++y)
                    for (int x = 0; x < mip.width; ++x) {
                        DirectTexel d = directTexel(level0, bake::mipFootprint(s[0], int(k), x),
                                                    bake::mipFootprint(s[1], int(k), y), m);
                        std::size_t i = std::size_t(y) * std::size_t(mip.width) + std::size_t(x);
                        glm::dvec3 n(mip.normals[i]);
                        ASSERT_LT(glm::length(n - d.normal), 1e-6)
                            << methodName(m) << " " << s[0] << "x" << s[1] << " mip " << k;
                        ASSERT_NEAR(double(mip.gloss[i]), d.gloss, 1e-6)
                            << methodName(m) << " " << s[0] << "x" << s[1] << " mip " << k;
                    }
            }
        }
    }
}

TEST(NormalGlossMips, HostileTexelsGiveFiniteMips) {
    NormalGlossLevel level0 = randomLevel(9, 6, 3.0, -0.5, 1.5, 5);  // slopes up to 72 degrees
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    level0.normals[0] = {0, 0, -1};  // into the surface
    level0.normals[1] = {1, 0, 0};   // at the horizon
    level0.normals[2] = {0, 0, 0};
    level0.normals[3] = {nan, 0, 1};
    level0.normals[4] = {inf, 0, 1};
    level0.normals[5] = {1e30f, 1e30f, 1e30f};
    level0.normals[6] = {1e-30f, 0, 0};
    level0.gloss[7] = nan;
    level0.gloss[8] = inf;
    level0.gloss[9] = -inf;
    NormalGlossLevel opposite = constantLevel(2, 1, {0, 0, 1}, 0.5f);
    opposite.normals[1] = {0, 0, -1};  // cancels: a mean normal of length 0
    for (const NormalGlossLevel* input : {&level0, &opposite})
        for (MipMethod m : kMethods)
            for (GlossInversion inversion : {GlossInversion::Table, GlossInversion::Fit}) {
                NormalGlossChain chain = bake::buildNormalGlossMips(*input, m, inversion);
                EXPECT_TRUE(sameBits(chain[0], *input));
                for (std::size_t k = 1; k < chain.size(); ++k)
                    for (std::size_t i = 0; i < chain[k].gloss.size(); ++i) {
                        glm::vec3 n = chain[k].normals[i];
                        float g = chain[k].gloss[i];
                        ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z))
                            << methodName(m);
                        ASSERT_NEAR(double(glm::length(n)), 1.0, 1e-6) << methodName(m);
                        ASSERT_TRUE(g >= 0.0f && g <= 1.0f) << methodName(m) << " " << g;
                    }
            }
}

TEST(NormalGlossMips, BitIdenticalAtAnyThreadCount) {
    NormalGlossLevel level0 = randomLevel(97, 61, 0.4, 0.2, 1.0, 23);
    std::vector<bake::ViewLight> sweep = bake::incidencePlaneSweep({{35.0f, 20.0f}}, 16);
    std::vector<NormalGlossChain> serial, parallel;
    std::vector<std::vector<bake::MipLevelError>> serialErrors, parallelErrors;
    {
        tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        for (MipMethod m : kMethods) serial.push_back(bake::buildNormalGlossMips(level0, m));
        serialErrors = bake::mipErrors(level0, serial, sweep);
    }
    for (MipMethod m : kMethods) parallel.push_back(bake::buildNormalGlossMips(level0, m));
    parallelErrors = bake::mipErrors(level0, parallel, sweep);
    for (std::size_t c = 0; c < serial.size(); ++c) {
        for (std::size_t k = 0; k < serial[c].size(); ++k)
            EXPECT_TRUE(sameBits(serial[c][k], parallel[c][k])) << methodName(kMethods[c]);
        for (std::size_t k = 0; k < serialErrors[c].size(); ++k) {
            EXPECT_EQ(serialErrors[c][k].rmsDifference, parallelErrors[c][k].rmsDifference);
            EXPECT_EQ(serialErrors[c][k].rmsReference, parallelErrors[c][k].rmsReference);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Mip error

double lobe(glm::vec3 n, float gloss, const bake::ViewLight& p) {
    return double(glsl::specularLobe(NDF_GGX, VIS_SMITH_CORRELATED, FRESNEL_SCHLICK,
                                     glsl::vec3(0.04f), gloss, glsl::brdfDots(n, p.view, p.light))
                      .x);
}

TEST(MipError, MatchesTheDefinitionTexelByTexel) {
    // The header's sums, written out over each mip texel's level-0 footprint; only the order of
    // additions differs from the library's level-by-level sums: 1e-12 relative.
    NormalGlossLevel level0 = randomLevel(7, 5, 0.3, 0.5, 0.95, 29);
    NormalGlossChain chain = bake::buildNormalGlossMips(level0, MipMethod::kWwii);
    std::vector<bake::ViewLight> sweep = bake::incidencePlaneSweep({{40.0f, 10.0f}}, 9);
    std::vector<bake::MipLevelError> errors = bake::mipError(level0, chain, sweep);
    ASSERT_EQ(errors.size(), chain.size());
    for (std::size_t k = 0; k < chain.size(); ++k) {
        double reference2 = 0.0, difference2 = 0.0, weight = 0.0;
        const NormalGlossLevel& mip = chain[k];
        for (const bake::ViewLight& pair : sweep)
            for (int y = 0; y < mip.height; ++y)
                for (int x = 0; x < mip.width; ++x) {
                    bake::TexelRange xs = bake::mipFootprint(7, int(k), x);
                    bake::TexelRange ys = bake::mipFootprint(5, int(k), y);
                    double sum = 0.0, texels = 0.0;
                    for (int ty = ys.begin; ty < ys.end; ++ty)
                        for (int tx = xs.begin; tx < xs.end; ++tx) {
                            std::size_t i = std::size_t(ty) * 7 + std::size_t(tx);
                            sum += lobe(level0.normals[i], level0.gloss[i], pair);
                            texels += 1.0;
                        }
                    std::size_t t = std::size_t(y) * std::size_t(mip.width) + std::size_t(x);
                    double reference = sum / texels;
                    double shaded = lobe(mip.normals[t], mip.gloss[t], pair);
                    reference2 += texels * reference * reference;
                    difference2 += texels * (shaded - reference) * (shaded - reference);
                    weight += texels;
                }
        EXPECT_EQ(errors[k].width, mip.width);
        EXPECT_EQ(errors[k].height, mip.height);
        EXPECT_NEAR(errors[k].rmsReference / std::sqrt(reference2 / weight), 1.0, 1e-12);
        if (k == 0) {
            EXPECT_EQ(errors[k].rmsDifference, 0.0);
        } else {
            EXPECT_NEAR(errors[k].rmsDifference / std::sqrt(difference2 / weight), 1.0, 1e-12);
            EXPECT_NEAR(errors[k].relativeError,
                        std::sqrt(difference2 / weight) / std::sqrt(reference2 / weight), 1e-12);
        }
    }
    NormalGlossChain shortChain(chain.begin(), chain.end() - 1);
    EXPECT_THROW((void)bake::mipError(level0, shortChain, sweep), std::invalid_argument);
}

TEST(MipError, FlatFloorHasNoError) {
    // Every mip keeps normal (0, 0, 1) and the gloss to 1e-5 (FlatMapKeepsItsGloss); the lobe's
    // log-derivative in gloss is at most ~2 * 18 ln 2 = 25 at its peak: relative error < 1e-3.
    std::vector<bake::ViewLight> sweep = bake::incidencePlaneSweep({{30.0f, 0.0f}}, 90);
    for (float g : {0.0f, 0.5f, 0.8f, 1.0f}) {
        NormalGlossLevel level0 = constantLevel(12, 9, {0, 0, 1}, g);
        std::vector<NormalGlossChain> chains;
        for (MipMethod m : kMethods) chains.push_back(bake::buildNormalGlossMips(level0, m));
        std::vector<std::vector<bake::MipLevelError>> errors =
            bake::mipErrors(level0, chains, sweep);
        for (std::size_t c = 0; c < chains.size(); ++c)
            for (const bake::MipLevelError& e : errors[c]) {
                EXPECT_GT(e.rmsReference, 0.0);
                EXPECT_LT(e.relativeError, 1e-3) << methodName(kMethods[c]) << " gloss " << g;
            }
    }
}

// The test. A glossy floor (gloss 0.8, GGX alpha 0.0096) with tiled bumps (period 32
// texels, slopes up to 0.3, 17 degrees), 128 x 128 texels, seen from the near field (mip 0, one
// texel per pixel) to many texels per pixel (mip 7, the whole texture). For each mip, the
// shading of each mip texel under a sweep of lights (1 degree steps through the plane of
// incidence of three views) against the mean over the texels it covers of the full-resolution
// shading (mip_error.hpp). The blit keeps a sharp lobe about the mean normal: a mirror where the
// truth is a wide highlight. Black Ops and WWII must cut its error by at least 2x from mip 4
// (16 x 16 texels, half a bump period) on.
TEST(TextureMips, BumpyGlossyFloorAgainstFullResolution) {
    auto start = std::chrono::steady_clock::now();
    NormalGlossLevel level0 = bumpLevel(128, 32, 0.3, 0.8f);
    std::vector<NormalGlossChain> chains;
    for (MipMethod m : kMethods) chains.push_back(bake::buildNormalGlossMips(level0, m));
    std::vector<bake::ViewLight> sweep =
        bake::incidencePlaneSweep({{25.0f, 0.0f}, {45.0f, 30.0f}, {65.0f, 60.0f}}, 180);
    std::vector<std::vector<bake::MipLevelError>> errors = bake::mipErrors(level0, chains, sweep);
    // CLEAN's chain shaded as the runtime's footprint: the bumps' share of its lobe as facets.
    const std::vector<bake::MipLevelError> footprint =
        bake::mipErrors(level0, std::span<const NormalGlossChain>(&chains[3], 1), sweep, 0.04f,
                        bake::MipShading::kFootprint)
            .front();
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::printf("relative RMS error of each mip's shading against the full-resolution mean\n");
    std::printf(
        "mip |  size   |     blit | black ops |     wwii |    clean | clean, footprint | "
        "gloss: black ops |   wwii |  clean\n");
    for (std::size_t k = 0; k < errors[0].size(); ++k) {
        double gloss[4] = {0.0, 0.0, 0.0, 0.0};
        for (std::size_t c = 1; c < 4; ++c) {
            for (float g : chains[c][k].gloss) gloss[c] += double(g);
            gloss[c] /= double(chains[c][k].gloss.size());
        }
        std::printf(
            "%3zu | %3dx%-3d | %8.4f | %9.4f | %8.4f | %8.4f | %16.4f | %16.4f | %6.4f | %6.4f\n",
            k, errors[0][k].width, errors[0][k].height, errors[0][k].relativeError,
            errors[1][k].relativeError, errors[2][k].relativeError, errors[3][k].relativeError,
            footprint[k].relativeError, gloss[1], gloss[2], gloss[3]);
    }
    std::printf("(%zu view-light pairs, %.2f s)\n", sweep.size(), seconds);

    for (std::size_t c = 0; c < chains.size(); ++c) EXPECT_EQ(errors[c][0].relativeError, 0.0);
    for (std::size_t k = 4; k < errors[0].size(); ++k) {
        double blit = errors[0][k].relativeError;
        EXPECT_LE(errors[1][k].relativeError, 0.5 * blit) << "black ops, mip " << k;
        EXPECT_LE(errors[2][k].relativeError, 0.5 * blit) << "wwii, mip " << k;
        EXPECT_LE(errors[3][k].relativeError, 0.5 * blit) << "clean, mip " << k;
    }
}

}  // namespace
}  // namespace onelight::test
