// Cavity maps (bake/textures/cavity_map.hpp) against independent references: analytic height
// fields and their discrete least-squares response for the height solve, cosine-weighted rays
// marched against the analytic height function for the cavity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <tbb/global_control.h>
#include <glm/glm.hpp>

#include "bake/textures/cavity_map.hpp"

namespace {

using onelight::bake::CavityMap;
using onelight::bake::CavitySettings;
using onelight::bake::CavityWrap;
using onelight::bake::CavityWrapModes;
using onelight::bake::HeightField;
using onelight::bake::HorizonScan;
using onelight::bake::TangentNormalMap;

constexpr double kPi = 3.14159265358979323846;
constexpr CavityWrapModes kRepeat{CavityWrap::kRepeat, CavityWrap::kRepeat};
constexpr CavityWrapModes kClamp{CavityWrap::kClamp, CavityWrap::kClamp};

// An analytic height field in texel units over (u, v) = (column, row), v running DOWN the
// image, with its gradient (dh/du, dh/dv).
struct Analytic {
    std::function<double(double, double)> height;
    std::function<glm::dvec2(double, double)> gradient;
};

// The tangent-space normal map of `field` sampled at texel centres, glTF convention written
// out independently of the code under test: the surface z = h(x, y) with x = u (right) and
// y = -v (up) has the normal (-dh/dx, -dh/dy, 1) = (-dh/du, +dh/dv, 1), normalised.
TangentNormalMap normalsOf(const Analytic& field, uint32_t w, uint32_t h) {
    TangentNormalMap map{w, h, {}};
    for (uint32_t v = 0; v < h; ++v)
        for (uint32_t u = 0; u < w; ++u) {
            const glm::dvec2 g = field.gradient(double(u), double(v));
            map.normals.push_back(glm::vec3(glm::normalize(glm::dvec3(-g.x, g.y, 1.0))));
        }
    return map;
}

std::vector<double> sampled(const Analytic& field, uint32_t w, uint32_t h) {
    std::vector<double> out;
    for (uint32_t v = 0; v < h; ++v)
        for (uint32_t u = 0; u < w; ++u) out.push_back(field.height(double(u), double(v)));
    return out;
}

template <typename T>
std::vector<double> minusMean(const std::vector<T>& values) {
    double mean = 0.0;
    for (T x : values) mean += double(x);
    mean /= double(values.size());
    std::vector<double> out;
    for (T x : values) out.push_back(double(x) - mean);
    return out;
}

double rms(const std::vector<double>& a, const std::vector<double>& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(sum / double(a.size()));
}

double maxAbs(const std::vector<double>& a, const std::vector<double>& b) {
    double m = 0.0;
    for (size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(a[i] - b[i]));
    return m;
}

// ---------------------------------------------------------------------------------------------
// Plane waves and their discrete least-squares response

// A sin(kx u + ky v + phase) or, with `cosineProduct`, A cos(kx (u + 1/2)) cos(ky (v + 1/2)) (a
// Neumann eigenfunction on a clamped map of pi p / w radians per texel).
struct Wave {
    double amplitude, kx, ky, phase;
    bool cosineProduct = false;

    double height(double u, double v) const {
        if (cosineProduct) return amplitude * std::cos(kx * (u + 0.5)) * std::cos(ky * (v + 0.5));
        return amplitude * std::sin(kx * u + ky * v + phase);
    }
    glm::dvec2 gradient(double u, double v) const {
        if (cosineProduct)
            return amplitude *
                   glm::dvec2(-kx * std::sin(kx * (u + 0.5)) * std::cos(ky * (v + 0.5)),
                              -ky * std::cos(kx * (u + 0.5)) * std::sin(ky * (v + 0.5)));
        const double c = amplitude * std::cos(kx * u + ky * v + phase);
        return glm::dvec2(kx * c, ky * c);
    }
    // The least-squares fit of edge differences to the mean of two centre slopes, for a plane
    // wave e^(i(kx u + ky v)): the slopes' divergence is -(kx sin kx + ky sin ky) h and the
    // 5-point Laplacian -(4 sin^2(kx/2) + 4 sin^2(ky/2)) h, so the wave comes back scaled by
    //   rho = (kx sin kx + ky sin ky) / (4 sin^2(kx/2) + 4 sin^2(ky/2))   (1 - k^2/12 + ...).
    // A product of cosines is four plane waves of the same |kx|, |ky|: the same rho.
    double response() const {
        const double sx = std::sin(0.5 * kx), sy = std::sin(0.5 * ky);
        return (kx * std::sin(kx) + ky * std::sin(ky)) / (4.0 * sx * sx + 4.0 * sy * sy);
    }
};

Analytic sumOf(const std::vector<Wave>& waves, bool discreteResponse = false) {
    Analytic a;
    a.height = [waves, discreteResponse](double u, double v) {
        double s = 0.0;
        for (const Wave& w : waves) s += (discreteResponse ? w.response() : 1.0) * w.height(u, v);
        return s;
    };
    a.gradient = [waves](double u, double v) {
        glm::dvec2 g(0.0);
        for (const Wave& w : waves) g += w.gradient(u, v);
        return g;
    };
    return a;
}

double radiansPerTexel(int cycles, uint32_t size) {
    return 2.0 * kPi * cycles / double(size);
}

// Float normals carry slopes to 6e-8 relative, and heights are written as floats (ulp 1.9e-6 at
// the largest here, 24 texels): a few ulps. Measured: 2.5e-7 (sinusoids), 9.2e-7 (quadratic).
constexpr double kSolveRounding = 1e-5;

TEST(HeightFromNormals, PeriodicSinusoidsComeBackAsTheirDiscreteLeastSquaresResponse) {
    const uint32_t w = 96, h = 64;  // not square (x and y cannot swap unseen), 96 not 2^k
    const std::vector<Wave> waves = {
        {3.0, radiansPerTexel(2, w), 0.0, 0.3},
        {1.5, 0.0, radiansPerTexel(3, h), -1.1},
        {1.0, radiansPerTexel(3, w), radiansPerTexel(2, h), 0.7},
        {0.5, radiansPerTexel(5, w), radiansPerTexel(-4, h), 2.0},
    };
    const HeightField field =
        onelight::bake::heightFromNormals(normalsOf(sumOf(waves), w, h), kRepeat);
    ASSERT_EQ(field.heights.size(), size_t(w) * h);
    const std::vector<double> got = minusMean(field.heights);
    // Exactly the discrete response: the solver is exact, not iterative.
    EXPECT_LT(maxAbs(got, minusMean(sampled(sumOf(waves, true), w, h))), kSolveRounding);
    // Against the analytic field the only error is discretisation: per wave (1 - rho) A, the
    // waves orthogonal over the map, so RMS = sqrt(sum ((1 - rho) A)^2 / 2) (here 0.0094 texels,
    // 0.4% of the field's RMS 2.5: rho = 0.9986 .. 0.9887 for 48 .. 12.3 texels per period).
    double predicted = 0.0;
    for (const Wave& wave : waves) {
        const double e = (1.0 - wave.response()) * wave.amplitude;
        predicted += 0.5 * e * e;
    }
    predicted = std::sqrt(predicted);
    const double error = rms(got, minusMean(sampled(sumOf(waves), w, h)));
    EXPECT_NEAR(error, predicted, kSolveRounding);
    EXPECT_LT(error, 0.01);
}

TEST(HeightFromNormals, ClampedCosinesComeBackAsTheirDiscreteLeastSquaresResponse) {
    const uint32_t w = 32, h = 16;
    const std::vector<Wave> waves = {
        {2.0, kPi * 1 / w, kPi * 0 / h, 0.0, true},
        {1.0, kPi * 0 / w, kPi * 1 / h, 0.0, true},
        {0.7, kPi * 3 / w, kPi * 2 / h, 0.0, true},
    };
    const HeightField field =
        onelight::bake::heightFromNormals(normalsOf(sumOf(waves), w, h), kClamp);
    EXPECT_LT(maxAbs(minusMean(field.heights), minusMean(sampled(sumOf(waves, true), w, h))),
              kSolveRounding);
}

// The glTF convention pinned by hand: a bump's normals lean away from it (+X to its right, +Y
// above it, i.e. at smaller rows), and it reconstructs as a bump where it is, its long axis
// along u staying along u.
TEST(HeightFromNormals, ABumpComesBackAsABumpWhereItIs) {
    const uint32_t w = 64, h = 48;
    const double u0 = 20.0, v0 = 12.0, su = 6.0, sv = 2.0, amplitude = 3.0;
    Analytic bump;  // exp(-(du/su)^2 / 2 - ...), its tails 1e-6 at the map's opposite side
    bump.height = [=](double u, double v) {
        const double du = u - u0, dv = v - v0;
        return amplitude * std::exp(-0.5 * (du * du / (su * su) + dv * dv / (sv * sv)));
    };
    bump.gradient = [=](double u, double v) {
        const double b = bump.height(u, v);
        return glm::dvec2(-(u - u0) / (su * su) * b, -(v - v0) / (sv * sv) * b);
    };
    const TangentNormalMap normals = normalsOf(bump, w, h);
    const auto normalAt = [&](uint32_t u, uint32_t v) { return normals.normals[v * w + u]; };
    EXPECT_GT(normalAt(26, 12).x, 0.2f);  // right of the bump: leans right
    EXPECT_LT(normalAt(14, 12).x, -0.2f);
    EXPECT_GT(normalAt(20, 10).y, 0.2f);  // above it (smaller row): leans up
    EXPECT_LT(normalAt(20, 14).y, -0.2f);

    const HeightField field = onelight::bake::heightFromNormals(normals, kRepeat);
    const std::vector<double> got = minusMean(field.heights);
    const size_t peak = size_t(std::max_element(got.begin(), got.end()) - got.begin());
    EXPECT_EQ(peak % w, 20u);
    EXPECT_EQ(peak / w, 12u);
    const std::vector<double> want = minusMean(sampled(bump, w, h));
    EXPECT_GT(got[12 * w + 20], 2.5);
    // Long along u: 4 texels right it is still high, 4 texels down it is nearly gone.
    EXPECT_NEAR(got[12 * w + 24], want[12 * w + 24], 0.05);
    EXPECT_NEAR(got[16 * w + 20], want[16 * w + 20], 0.05);
    EXPECT_GT(got[12 * w + 24], 2.0);
    EXPECT_LT(got[16 * w + 20], 0.5);
}

// A quadratic's edge differences equal the mean of its two centre slopes, so a clamped map
// (no wrap edge to contradict) reconstructs any quadratic exactly; a repeating one cannot, as
// its wrap edge asks the ramp to come back down.
TEST(HeightFromNormals, ClampReconstructsAnyQuadraticExactlyAndRepeatDoesNot) {
    const uint32_t w = 37, h = 23;
    Analytic quadratic;
    quadratic.height = [](double u, double v) {
        return 0.3 * u - 0.2 * v + 0.01 * u * u - 0.02 * v * v + 0.005 * u * v;
    };
    quadratic.gradient = [](double u, double v) {
        return glm::dvec2(0.3 + 0.02 * u + 0.005 * v, -0.2 - 0.04 * v + 0.005 * u);
    };
    const TangentNormalMap normals = normalsOf(quadratic, w, h);
    const std::vector<double> want = minusMean(sampled(quadratic, w, h));
    EXPECT_LT(maxAbs(minusMean(onelight::bake::heightFromNormals(normals, kClamp).heights), want),
              kSolveRounding);
    EXPECT_GT(maxAbs(minusMean(onelight::bake::heightFromNormals(normals, kRepeat).heights), want),
              1.0);
    // Mixed: clamped along u only, the v ramp cannot close; along v only, the u ramp.
    EXPECT_GT(maxAbs(minusMean(onelight::bake::heightFromNormals(
                                   normals, {CavityWrap::kClamp, CavityWrap::kRepeat})
                                   .heights),
                     want),
              1.0);
}

TEST(HeightFromNormals, MixedWrapSolvesEachAxisByItsOwnMode) {
    // Periodic along u (a sine of 2 cycles), a quadratic along v: exact with u repeat, v clamp.
    const uint32_t w = 40, h = 25;
    const Wave wave{1.5, radiansPerTexel(2, w), 0.0, 0.4};
    Analytic field;
    field.height = [wave](double u, double v) {
        return wave.height(u, v) + 0.02 * v * v - 0.3 * v;
    };
    field.gradient = [wave](double u, double v) {
        return wave.gradient(u, v) + glm::dvec2(0.0, 0.04 * v - 0.3);
    };
    Analytic response = field;
    response.height = [wave](double u, double v) {
        return wave.response() * wave.height(u, v) + 0.02 * v * v - 0.3 * v;
    };
    const HeightField got = onelight::bake::heightFromNormals(
        normalsOf(field, w, h), {CavityWrap::kRepeat, CavityWrap::kClamp});
    EXPECT_LT(maxAbs(minusMean(got.heights), minusMean(sampled(response, w, h))), kSolveRounding);
}

TEST(HeightFromNormals, OneByNAndNByOneAndOneByOne) {
    Analytic alongV;
    alongV.height = [](double, double v) { return 0.05 * v * v - v; };
    alongV.gradient = [](double, double v) { return glm::dvec2(0.0, 0.1 * v - 1.0); };
    const TangentNormalMap column = normalsOf(alongV, 1, 40);
    EXPECT_LT(maxAbs(minusMean(onelight::bake::heightFromNormals(column, kClamp).heights),
                     minusMean(sampled(alongV, 1, 40))),
              kSolveRounding);

    Analytic alongU;
    alongU.height = [](double u, double) { return 0.5 * u - 0.02 * u * u; };
    alongU.gradient = [](double u, double) { return glm::dvec2(0.5 - 0.04 * u, 0.0); };
    const TangentNormalMap row = normalsOf(alongU, 33, 1);
    EXPECT_LT(maxAbs(minusMean(onelight::bake::heightFromNormals(row, kClamp).heights),
                     minusMean(sampled(alongU, 33, 1))),
              kSolveRounding);

    // A repeating 1 x 27 sine (odd, Bluestein length) comes back as its discrete response.
    const Wave wave{2.0, 0.0, radiansPerTexel(2, 27), 0.5};
    const HeightField periodic =
        onelight::bake::heightFromNormals(normalsOf(sumOf({wave}), 1, 27), kRepeat);
    EXPECT_LT(maxAbs(minusMean(periodic.heights), minusMean(sampled(sumOf({wave}, true), 1, 27))),
              kSolveRounding);

    const TangentNormalMap single{1, 1, {glm::vec3(0.3f, -0.2f, 0.9f)}};
    for (CavityWrapModes wrap : {kRepeat, kClamp}) {
        const HeightField one = onelight::bake::heightFromNormals(single, wrap);
        ASSERT_EQ(one.heights.size(), 1u);
        EXPECT_EQ(one.heights[0], 0.0f);
        const CavityMap cavity = onelight::bake::cavityFromNormals(single, {wrap, 1.0f, {}});
        ASSERT_EQ(cavity.cavity.size(), 1u);
        EXPECT_EQ(cavity.cavity[0], 1.0f);
    }
    const TangentNormalMap empty{0, 5, {}};
    EXPECT_TRUE(onelight::bake::heightFromNormals(empty, kRepeat).heights.empty());
    EXPECT_TRUE(onelight::bake::cavityFromNormals(empty).cavity.empty());
}

TEST(HeightFromNormals, DepthScaleScalesTheHeights) {
    const uint32_t w = 24, h = 24;
    const Wave wave{1.0, radiansPerTexel(1, w), radiansPerTexel(2, h), 0.0};
    const TangentNormalMap normals = normalsOf(sumOf({wave}), w, h);
    const HeightField one = onelight::bake::heightFromNormals(normals, kRepeat);
    const HeightField three = onelight::bake::heightFromNormals(normals, kRepeat, 3.0f);
    for (size_t i = 0; i < one.heights.size(); ++i)
        EXPECT_NEAR(three.heights[i], 3.0f * one.heights[i], 1e-5f);
}

TEST(HeightSlopeFromNormal, FollowsTheConventionAndTreatsDegenerateNormalsAsFlat) {
    using onelight::bake::heightSlopeFromNormal;
    // Leaning right: the surface falls to the right. Leaning up: falls upwards (dh/dy < 0).
    EXPECT_NEAR(heightSlopeFromNormal(glm::vec3(0.6f, 0.0f, 0.8f)).x, -0.75, 1e-6);
    EXPECT_NEAR(heightSlopeFromNormal(glm::vec3(0.0f, 0.6f, 0.8f)).y, -0.75, 1e-6);
    EXPECT_NEAR(heightSlopeFromNormal(glm::vec3(0.0f, 0.6f, 0.8f)).x, 0.0, 1e-12);
    EXPECT_NEAR(heightSlopeFromNormal(glm::vec3(-3.0f, 0.0f, 4.0f)).x, 0.75, 1e-6);  // any length
    // Grazing: nz raised to the floor, the slope bounded by 1 / kMinNormalZ.
    const glm::dvec2 grazing = heightSlopeFromNormal(glm::vec3(1.0f, 0.0f, 1e-6f));
    EXPECT_NEAR(grazing.x, -1.0 / double(onelight::bake::kMinNormalZ), 1e-4);
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (glm::vec3 n :
         {glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, -1.0f),
          glm::vec3(0.5f, 0.5f, -0.1f), glm::vec3(nan, 0.0f, 1.0f), glm::vec3(0.0f, 0.0f, inf),
          glm::vec3(inf, 0.0f, 1.0f), glm::vec3(1e-30f, 0.0f, 1e-30f)}) {
        const glm::dvec2 s = heightSlopeFromNormal(n);
        EXPECT_TRUE(std::isfinite(s.x) && std::isfinite(s.y));
        EXPECT_LE(std::fabs(s.x), 20.0 + 1e-9);
        if (!(n.z > 0.0f) || !std::isfinite(n.x) || !std::isfinite(n.z)) {
            EXPECT_EQ(s.x, 0.0);
            EXPECT_EQ(s.y, 0.0);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Cavity

// Smooth bowls (-depth (1 - (r/radius)^2)^3: C2, compact, so the map is exactly periodic) and
// a gentle ripple, over a 64 x 64 repeating tile.
struct Dent {
    double u, v, radius, depth;
};

Analytic dentField(const std::vector<Dent>& dents, double ripple, uint32_t size) {
    const double k = 2.0 * kPi / double(size);
    Analytic a;
    a.height = [=](double u, double v) {
        double s = ripple * std::sin(k * u + 2.0 * k * v);
        for (const Dent& d : dents) {
            const double du = u - d.u, dv = v - d.v,
                         q = (du * du + dv * dv) / (d.radius * d.radius);
            if (q < 1.0) s -= d.depth * (1.0 - q) * (1.0 - q) * (1.0 - q);
        }
        return s;
    };
    a.gradient = [=](double u, double v) {
        const double c = ripple * std::cos(k * u + 2.0 * k * v);
        glm::dvec2 g(k * c, 2.0 * k * c);
        for (const Dent& d : dents) {
            const double du = u - d.u, dv = v - d.v,
                         q = (du * du + dv * dv) / (d.radius * d.radius);
            if (q < 1.0) {
                const double dq = 3.0 * d.depth * (1.0 - q) * (1.0 - q);  // -d(h)/dq
                g += dq * glm::dvec2(2.0 * du, 2.0 * dv) / (d.radius * d.radius);
            }
        }
        return g;
    };
    return a;
}

const std::vector<Dent> kDents = {
    {16, 16, 12, 6}, {48, 20, 8, 3}, {20, 48, 10, 8}, {46, 46, 14, 4}};

// The reference cavity at texel (u, v): the fraction of cosine-weighted rays from the analytic
// surface point that stay above the analytic field out to a horizontal distance `radius`,
// marched at 1/20 texel, over a periodic (`size`-texel) field. 64 x 64 jittered strata (fixed
// seed): the standard error of such a stratified estimate is ~1e-3 at most.
double referenceCavity(const Analytic& field, double u, double v, double radius, double highest) {
    constexpr int kStrata = 64;
    constexpr double kStep = 0.05;
    std::mt19937 rng(1234567u + uint32_t(u) * 977u + uint32_t(v));
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    const double h0 = field.height(u, v);
    int visible = 0;
    for (int i = 0; i < kStrata; ++i)
        for (int j = 0; j < kStrata; ++j) {
            const double xi1 = (i + jitter(rng)) / kStrata, xi2 = (j + jitter(rng)) / kStrata;
            // Cosine-weighted: sin^2(theta) uniform; rise per horizontal texel cot(theta).
            const double sinTheta = std::sqrt(xi1), rise = std::sqrt(1.0 - xi1) / sinTheta;
            const double phi = 2.0 * kPi * xi2, du = std::cos(phi), dv = std::sin(phi);
            bool blocked = false;
            for (double t = kStep; t <= radius && !blocked; t += kStep) {
                const double z = h0 + rise * t;
                if (z > highest) break;  // above everything: escapes
                blocked = field.height(u + t * du, v + t * dv) > z;
            }
            visible += blocked ? 0 : 1;
        }
    return double(visible) / double(kStrata * kStrata);
}

double highestOf(const Analytic& field, uint32_t size) {
    double m = -1e30;
    for (double v = 0.0; v < size; v += 0.25)
        for (double u = 0.0; u < size; u += 0.25) m = std::max(m, field.height(u, v));
    return m + 1e-3;  // the 1/4-texel scan's miss is far below this for these smooth fields
}

TEST(CavityFromNormals, MatchesCosineWeightedRaysMarchedAgainstTheAnalyticField) {
    const uint32_t size = 64;
    const Analytic field = dentField(kDents, 0.5, size);
    const HorizonScan scan{16, 24.0f};
    const CavityMap cavity =
        onelight::bake::cavityFromNormals(normalsOf(field, size, size), {kRepeat, 1.0f, scan});
    const double highest = highestOf(field, size);
    HeightField exact{size, size, {}};
    for (double x : sampled(field, size, size)) exact.heights.push_back(float(x));
    const CavityMap fromExact = onelight::bake::cavityFromHeight(exact, kRepeat, scan);
    struct Probe {
        int u, v;
        const char* where;
    };
    std::vector<Probe> probes;
    for (const Dent& d : kDents) {
        probes.push_back({int(d.u), int(d.v), "dent centre"});
        for (int a = 0; a < 3; ++a) {  // the bowls' walls at 1/3 and 2/3 of their radius
            const double angle = 0.7 + 2.1 * a;
            for (double f : {1.0 / 3.0, 2.0 / 3.0})
                probes.push_back({int(std::lround(d.u + f * d.radius * std::cos(angle))),
                                  int(std::lround(d.v + f * d.radius * std::sin(angle))), "slope"});
        }
    }
    for (Probe p : {Probe{32, 2, "plateau"}, Probe{2, 30, "plateau"}, Probe{34, 34, "plateau"},
                    Probe{60, 4, "plateau"}})
        probes.push_back(p);

    // Two comparisons against the same reference: the scan alone (cavityFromHeight of the
    // analytic heights at the texel centres) and the whole pipeline (from the normals).
    double sumScan = 0.0, sumPipeline = 0.0, worstScan = 0.0, worstPipeline = 0.0;
    for (const Probe& p : probes) {
        const double want = referenceCavity(field, p.u, p.v, scan.radius, highest);
        const size_t texel = size_t(p.v) * size + size_t(p.u);
        const double scanError = std::fabs(double(fromExact.cavity[texel]) - want);
        const double pipelineError = std::fabs(double(cavity.cavity[texel]) - want);
        sumScan += scanError;
        sumPipeline += pipelineError;
        worstScan = std::max(worstScan, scanError);
        worstPipeline = std::max(worstPipeline, pipelineError);
        // The scan: 16 azimuths (the mean of a horizon that varies between them), unit radial
        // steps on a bilinear field (a rim's rise between samples), the tangent's rise from
        // the harmonic mean of the differences a texel ahead and behind (short by ~c^2 / 4s
        // on a wall curving by c per texel), and the reference's noise (its estimate moves by
        // up to 2e-3 with another seed). Measured: worst 0.008, on the upper walls of the
        // deepest bowl, where the surface curves most and every source adds up.
        EXPECT_LT(scanError, 0.015) << p.where << " (" << p.u << ", " << p.v << ")";
        // The pipeline adds the reconstruction: heights come back shallower by 1 - rho, 0.5
        // .. 1% for bowls of 8 .. 14 texels' radius, and cos^2(e) = 1 / (1 + s^2) moves by
        // 2 s^2 / (1 + s^2)^2 * 1% <= 0.005 with it. Measured: worst 0.0095.
        EXPECT_LT(pipelineError, 0.02) << p.where << " (" << p.u << ", " << p.v << ")";
        EXPECT_GE(cavity.cavity[texel], 0.0f);
        EXPECT_LE(cavity.cavity[texel], 1.0f);
    }
    // Means (measured 0.0021 and 0.0036): the azimuth error averages out, the reconstruction's
    // shallowing and the tangent's short reading do not (both raise cavity in a bowl).
    const double n = double(probes.size());
    EXPECT_LT(sumScan / n, 0.004) << "worst " << worstScan;
    EXPECT_LT(sumPipeline / n, 0.007) << "worst " << worstPipeline;
    // The dents do occlude: the references themselves span a wide range.
    EXPECT_LT(referenceCavity(field, 20, 48, scan.radius, highest), 0.6);
}

// A plane of slope s (texels per texel) hides, in each azimuth facing uphill, the elevations
// below its own rise s cos(phi):
//   V = 1/2 + (1 / 2 pi) int_{-pi/2}^{pi/2} dphi / (1 + s^2 cos^2 phi) = 1/2 + 1 / (2 sqrt(1 +
//   s^2)).
// A clamped map reconstructs a plane exactly; the 16-azimuth mean is within 2.1e-4 of V for
// s <= 2 at any orientation (the integrand is smooth), float rounding adds ~1e-6.
TEST(CavityFromNormals, ATiltedPlaneSeesTheAnalyticHalfHorizon) {
    const uint32_t w = 40, h = 28;
    for (glm::dvec2 g : {glm::dvec2(0.8, -0.5), glm::dvec2(1.5, 1.0), glm::dvec2(0.0, 0.3)}) {
        Analytic plane;
        plane.height = [g](double u, double v) { return g.x * u + g.y * v; };
        plane.gradient = [g](double, double) { return g; };
        const double s2 = glm::dot(g, g);
        const double want = 0.5 + 0.5 / std::sqrt(1.0 + s2);
        for (float radius : {0.0f, 8.0f}) {
            const CavityMap cavity = onelight::bake::cavityFromNormals(
                normalsOf(plane, w, h), {kClamp, 1.0f, {16, radius}});
            // Texels farther than the radius from the border (past it, clamp continues the
            // edge texels, above the plane downhill of them) and than 1 texel (the central
            // difference reads the edge's copy).
            const uint32_t margin = std::max(1u, uint32_t(radius) + 1);
            for (uint32_t v = margin; v + margin < h; ++v)
                for (uint32_t u = margin; u + margin < w; ++u)
                    ASSERT_NEAR(cavity.cavity[v * w + u], want, 5e-4)
                        << "slope (" << g.x << ", " << g.y << ") at (" << u << ", " << v << ")";
        }
    }
}

// A V-groove: walls h = s |u - c| along v, from a generated normal map, against the cavity its
// geometry predicts. From a point x texels up the wall, in azimuth phi (c_phi = cos phi across
// the groove), the horizon is
//   uphill (c_phi > 0): the wall itself, tan e = s c_phi;
//   towards the crease (c_phi < 0): the far wall seen past it, tan e = s |c_phi| - 2 s x / t,
//     largest at the scan's last tap t = R, and 0 when the ray does not cross the crease
//     within R (R |c_phi| <= x) or the far wall stays below (the near wall falls away);
//   along the groove: 0;
// and the cavity is the mean over the scan's azimuths of cos^2 e = 1 / (1 + tan^2 e). At the
// crease (x = 0) this is 1 / sqrt(1 + s^2) in the limit of many azimuths. The triangle wave's
// period (256 texels) keeps the crests out of reach of the scan.
TEST(CavityFromNormals, AVGrooveHasTheCavityItsGeometryPredicts) {
    const uint32_t w = 256, h = 8;
    const double crease = 128.0;
    const HorizonScan scan{16, 24.0f};
    for (double s : {0.5, 1.0}) {
        Analytic groove;
        groove.height = [=](double u, double) { return s * std::fabs(u - crease); };
        groove.gradient = [=](double u, double) {
            return glm::dvec2(u > crease ? s : u < crease ? -s : 0.0, 0.0);
        };
        const CavityMap cavity =
            onelight::bake::cavityFromNormals(normalsOf(groove, w, h), {kRepeat, 1.0f, scan});
        for (double x : {0.0, 3.0, 8.0}) {
            double want = 0.0;
            for (uint32_t j = 0; j < scan.azimuths; ++j) {
                const double c = std::cos(2.0 * kPi * double(j) / double(scan.azimuths));
                double tanE = 0.0;
                if (c > 1e-12) {
                    tanE = s * c;
                } else if (c < -1e-12 && double(scan.radius) * -c > x) {
                    tanE = std::max(0.0, -s * c - 2.0 * s * x / double(scan.radius));
                }
                want += 1.0 / (1.0 + tanE * tanE) / double(scan.azimuths);
            }
            if (x == 0.0) {
                EXPECT_NEAR(want, 1.0 / std::sqrt(1.0 + s * s), 0.01);
            }
            const double got = cavity.cavity[size_t(h / 2) * w + size_t(crease + x)];
            std::printf(
                "  V-groove slope %.1f, %2.0f texels up the wall: cavity %.4f, its "
                "geometry %.4f\n",
                s, x, got, want);
            // The bound. Measured: within 0.04% on the walls; 0.6% and 1.5% at the
            // crease, whose texel sampled a flat normal (the reconstruction rounds the kink).
            EXPECT_NEAR(got / want, 1.0, 0.05) << "slope " << s << ", " << x << " texels up";
            EXPECT_LT(want, 0.95);  // the groove does occlude
        }
    }
}

TEST(CavityFromNormals, AFlatMapHasCavityExactlyOneEverywhere) {
    for (CavityWrapModes wrap :
         {kRepeat, kClamp, CavityWrapModes{CavityWrap::kClamp, CavityWrap::kRepeat}}) {
        for (glm::vec3 n : {glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.0f, 0.0f, 2.5f)}) {
            const TangentNormalMap flat{33, 17, std::vector<glm::vec3>(33 * 17, n)};
            const HeightField field = onelight::bake::heightFromNormals(flat, wrap);
            for (float x : field.heights) ASSERT_EQ(x, 0.0f);
            const CavityMap cavity = onelight::bake::cavityFromNormals(flat, {wrap, 1.0f, {}});
            for (float c : cavity.cavity) ASSERT_EQ(c, 1.0f);
        }
    }
}

TEST(CavityFromNormals, DeeperDentsHaveLowerCavity) {
    const uint32_t size = 64;
    std::vector<float> previous;
    double previousCentre = 2.0, previousMean = 2.0;
    for (double depth : {0.5, 1.0, 2.0, 4.0, 8.0}) {
        const Analytic field = dentField({{30, 34, 12, depth}}, 0.0, size);
        const CavityMap cavity =
            onelight::bake::cavityFromNormals(normalsOf(field, size, size), {kRepeat, 1.0f, {}});
        const double centre = cavity.cavity[34 * size + 30];
        double mean = 0.0;
        for (float c : cavity.cavity) mean += double(c);
        mean /= double(cavity.cavity.size());
        EXPECT_LT(centre, previousCentre - 1e-3) << depth;
        EXPECT_LT(mean, previousMean) << depth;
        // Pointwise: heights scale with depth (the solve is linear), so every horizon rises.
        for (size_t i = 0; i < previous.size(); ++i)
            ASSERT_LE(cavity.cavity[i], previous[i] + 1e-5f) << depth << " texel " << i;
        previous = cavity.cavity;
        previousCentre = centre;
        previousMean = mean;
    }
    EXPECT_LT(previousCentre, 0.65);  // depth 8, radius 12: deep
}

TEST(CavityFromNormals, CrestsAreUnoccluded) {
    // Egg crate A (cos(2 pi u / 32) + cos(2 pi v / 32)): its highest texels, (0, 0), (32, 0),
    // (0, 32), (32, 32), see nothing above them; both waves have the same rho, so the
    // reconstruction keeps them highest.
    const uint32_t size = 64;
    const double k = 2.0 * kPi / 32.0;
    Analytic crate;
    crate.height = [k](double u, double v) { return 3.0 * (std::cos(k * u) + std::cos(k * v)); };
    crate.gradient = [k](double u, double v) {
        return glm::dvec2(-3.0 * k * std::sin(k * u), -3.0 * k * std::sin(k * v));
    };
    const CavityMap cavity =
        onelight::bake::cavityFromNormals(normalsOf(crate, size, size), {kRepeat, 1.0f, {}});
    for (uint32_t v : {0u, 32u})
        for (uint32_t u : {0u, 32u}) EXPECT_GE(cavity.cavity[v * size + u], 1.0f - 1e-6f);
    EXPECT_LT(cavity.cavity[16 * size + 16], 0.8f);  // a trough
}

// Clamp continues the field by its edge texels and repeat tiles it, each axis by its own mode:
// the cavity of a field equals, bit for bit, that of the field continued so by hand past the
// scan radius (whose own border is then never reached).
TEST(CavityFromHeight, ClampExtendsTheEdgesAndRepeatTiles) {
    const uint32_t w = 24, h = 20;
    const int pad = 10;
    const HorizonScan scan{16, 8.0f};
    HeightField field{w, h, {}};
    std::mt19937 rng(42u);
    std::uniform_real_distribution<float> noise(-2.0f, 2.0f);
    for (uint32_t i = 0; i < w * h; ++i) field.heights.push_back(noise(rng));
    const auto source = [](int i, int n, CavityWrap wrap) {
        return wrap == CavityWrap::kClamp ? std::clamp(i, 0, n - 1) : ((i % n) + n) % n;
    };
    for (CavityWrap u : {CavityWrap::kRepeat, CavityWrap::kClamp})
        for (CavityWrap v : {CavityWrap::kRepeat, CavityWrap::kClamp}) {
            HeightField continued{w + 2 * pad, h + 2 * pad, {}};
            for (int y = -pad; y < int(h) + pad; ++y)
                for (int x = -pad; x < int(w) + pad; ++x)
                    continued.heights.push_back(field.heights[size_t(source(y, int(h), v)) * w +
                                                              size_t(source(x, int(w), u))]);
            const CavityMap got = onelight::bake::cavityFromHeight(field, {u, v}, scan);
            const CavityMap want = onelight::bake::cavityFromHeight(continued, kRepeat, scan);
            for (uint32_t y = 0; y < h; ++y)
                for (uint32_t x = 0; x < w; ++x)
                    ASSERT_EQ(got.cavity[y * w + x],
                              want.cavity[(y + pad) * continued.width + x + pad])
                        << "u " << int(u) << " v " << int(v) << " at (" << x << ", " << y << ")";
        }

    // A wall along the left edge: the right edge sees it across the seam only when repeating.
    HeightField wall{32, 8, std::vector<float>(32 * 8, 0.0f)};
    for (uint32_t y = 0; y < 8; ++y) wall.heights[y * 32] = 8.0f;
    const CavityMap wallRepeat = onelight::bake::cavityFromHeight(wall, kRepeat, scan);
    const CavityMap wallClamp = onelight::bake::cavityFromHeight(wall, kClamp, scan);
    EXPECT_LT(wallRepeat.cavity[3 * 32 + 31], 0.8f);
    EXPECT_EQ(wallClamp.cavity[3 * 32 + 31], 1.0f);
    // Next to the wall both see it; the clamped map's wall continues leftward as a plateau.
    EXPECT_LT(wallClamp.cavity[3 * 32 + 1], 0.8f);
}

// The discrete definition written out plainly in double (no early stop, no tables): a low
// rough field with a few tall spikes, so far occluders decide many horizons.
TEST(CavityFromHeight, MatchesThePlainHorizonScan) {
    const uint32_t w = 40, h = 36;
    HeightField field{w, h, {}};
    std::mt19937 rng(7u);
    std::uniform_real_distribution<float> noise(0.0f, 0.3f);
    for (uint32_t i = 0; i < w * h; ++i) field.heights.push_back(noise(rng));
    for (uint32_t spike : {5u * w + 7u, 20u * w + 30u, 33u * w + 2u, 12u * w + 19u})
        field.heights[spike] = 6.0f;
    const HorizonScan scan{12, 16.0f};
    for (CavityWrapModes wrap : {CavityWrapModes{CavityWrap::kRepeat, CavityWrap::kClamp},
                                 CavityWrapModes{CavityWrap::kClamp, CavityWrap::kRepeat}}) {
        const auto read = [&](int x, int y) {
            x = wrap.u == CavityWrap::kClamp ? std::clamp(x, 0, int(w) - 1)
                                             : ((x % int(w)) + int(w)) % int(w);
            y = wrap.v == CavityWrap::kClamp ? std::clamp(y, 0, int(h) - 1)
                                             : ((y % int(h)) + int(h)) % int(h);
            return double(field.heights[size_t(y) * w + size_t(x)]);
        };
        const auto bilinear = [&](double x, double y) {
            const double x0 = std::floor(x), y0 = std::floor(y), fx = x - x0, fy = y - y0;
            const int ix = int(x0), iy = int(y0);
            return (1 - fy) * ((1 - fx) * read(ix, iy) + fx * read(ix + 1, iy)) +
                   fy * ((1 - fx) * read(ix, iy + 1) + fx * read(ix + 1, iy + 1));
        };
        const CavityMap got = onelight::bake::cavityFromHeight(field, wrap, scan);
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                const double h0 = read(int(x), int(y));
                double sum = 0.0;
                for (uint32_t j = 0; j < scan.azimuths; ++j) {
                    const double phi = 2.0 * kPi * j / scan.azimuths;
                    const double dx = std::cos(phi), dy = std::sin(phi);
                    const double r = bilinear(x + dx, y + dy) - h0;
                    const double f = h0 - bilinear(x - dx, y - dy);
                    double steepest = (r > 0.0 && f > 0.0) ? 2.0 * r * f / (r + f) : 0.0;
                    for (int t = 1; t <= int(scan.radius); ++t)
                        steepest = std::max(steepest, (bilinear(x + t * dx, y + t * dy) - h0) / t);
                    sum += 1.0 / (1.0 + steepest * steepest);
                }
                // Float samples of heights up to 6 (ulp 5e-7) against double.
                ASSERT_NEAR(got.cavity[y * w + x], sum / scan.azimuths, 2e-5)
                    << "(" << x << ", " << y << ")";
            }
    }
}

TEST(CavityFromNormals, DegenerateNormalsGiveNoNaN) {
    const uint32_t w = 21, h = 13;
    TangentNormalMap map = normalsOf(dentField({{10, 6, 6, 3}}, 0.0, 32), w, h);
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const glm::vec3 bad[] = {glm::vec3(0.0f),
                             glm::vec3(1.0f, 0.0f, 0.0f),
                             glm::vec3(0.0f, 0.0f, -1.0f),
                             glm::vec3(nan, 0.0f, 1.0f),
                             glm::vec3(inf, inf, inf),
                             glm::vec3(1.0f, 0.0f, 1e-7f),
                             glm::vec3(-1.0f, 1.0f, 1e-30f),
                             glm::vec3(1e-38f, 0.0f, 1e-38f)};
    for (size_t i = 0; i < std::size(bad); ++i) map.normals[i * 31 % map.normals.size()] = bad[i];
    for (CavityWrapModes wrap : {kRepeat, kClamp}) {
        const HeightField field = onelight::bake::heightFromNormals(map, wrap);
        for (float x : field.heights) ASSERT_TRUE(std::isfinite(x));
        const CavityMap cavity = onelight::bake::cavityFromNormals(map, {wrap, 1.0f, {}});
        for (float c : cavity.cavity) ASSERT_TRUE(c >= 0.0f && c <= 1.0f) << c;
    }
    // All zero vectors and z = 0: flat.
    TangentNormalMap degenerate{9, 7, {}};
    for (int i = 0; i < 63; ++i)
        degenerate.normals.push_back(i % 2 ? glm::vec3(0.0f) : glm::vec3(0.7f, -0.7f, 0.0f));
    for (float c : onelight::bake::cavityFromNormals(degenerate).cavity) ASSERT_EQ(c, 1.0f);
}

TEST(CavityFromNormals, OddAndThinSizes) {
    // 1 x N, N x 1 and odd sizes run, stay in [0, 1], and a 1-texel-wide dent profile occludes.
    const Analytic dents = dentField({{3, 9, 5, 3}}, 0.0, 64);
    for (glm::uvec2 size :
         {glm::uvec2(1, 31), glm::uvec2(31, 1), glm::uvec2(17, 9), glm::uvec2(5, 63)})
        for (CavityWrapModes wrap : {kRepeat, kClamp}) {
            const CavityMap cavity = onelight::bake::cavityFromNormals(
                normalsOf(dents, size.x, size.y), {wrap, 1.0f, {8, 16.0f}});
            ASSERT_EQ(cavity.cavity.size(), size_t(size.x) * size.y);
            for (float c : cavity.cavity) ASSERT_TRUE(c >= 0.0f && c <= 1.0f) << c;
        }
    Analytic valley;  // along v only: -3 (1 - ((v - 15) / 8)^2)^3
    valley.height = [](double, double v) {
        const double q = (v - 15.0) * (v - 15.0) / 64.0;
        return q < 1.0 ? -3.0 * (1.0 - q) * (1.0 - q) * (1.0 - q) : 0.0;
    };
    valley.gradient = [](double, double v) {
        const double q = (v - 15.0) * (v - 15.0) / 64.0;
        return glm::dvec2(
            0.0, q < 1.0 ? 3.0 * 3.0 * (1.0 - q) * (1.0 - q) * 2.0 * (v - 15.0) / 64.0 : 0.0);
    };
    const CavityMap column =
        onelight::bake::cavityFromNormals(normalsOf(valley, 1, 31), {kClamp, 1.0f, {16, 16.0f}});
    EXPECT_LT(column.cavity[15], 0.95f);
    EXPECT_GE(column.cavity[0], 0.999f);
}

TEST(CavityFromNormals, BitIdenticalAtAnyThreadCount) {
    const uint32_t w = 96, h = 64;
    const TangentNormalMap normals = normalsOf(dentField(kDents, 0.5, 64), w, h);
    const CavitySettings settings{{CavityWrap::kRepeat, CavityWrap::kClamp}, 1.0f, {16, 24.0f}};
    std::vector<float> one, many;
    {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
        one = onelight::bake::cavityFromNormals(normals, settings).cavity;
    }
    {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, 4);
        many = onelight::bake::cavityFromNormals(normals, settings).cavity;
    }
    EXPECT_EQ(one, many);
}

TEST(CavityFromHeight, RejectsMismatchedSizesAndScans) {
    const HeightField field{4, 4, std::vector<float>(16, 0.0f)};
    EXPECT_THROW((void)onelight::bake::cavityFromHeight({4, 4, std::vector<float>(15)}, kRepeat),
                 std::invalid_argument);
    EXPECT_THROW((void)onelight::bake::cavityFromHeight(field, kRepeat, {0, 8.0f}),
                 std::invalid_argument);
    EXPECT_THROW((void)onelight::bake::cavityFromHeight(field, kRepeat, {16, -1.0f}),
                 std::invalid_argument);
    EXPECT_THROW((void)onelight::bake::cavityFromHeight(
                     field, kRepeat, {16, std::numeric_limits<float>::quiet_NaN()}),
                 std::invalid_argument);
    EXPECT_THROW((void)onelight::bake::heightFromNormals({3, 3, std::vector<glm::vec3>(8)}, kClamp),
                 std::invalid_argument);
    // A radius under one texel scans no samples; only the tangent's rise remains: on the slope
    // (rises 3 ahead, 2 behind) it occludes, on the peak (neighbours 3 and 4) nothing does.
    const HeightField bumpy{5, 1, {0.0f, 1.0f, 3.0f, 6.0f, 4.0f}};
    const CavityMap near = onelight::bake::cavityFromHeight(bumpy, kRepeat, {16, 0.5f});
    EXPECT_LT(near.cavity[2], 0.9f);
    EXPECT_EQ(near.cavity[3], 1.0f);
}

// ---------------------------------------------------------------------------------------------
// Mips and encoding

TEST(CavityMipChain, BoxAveragesDownToOneByOne) {
    CavityMap map{5, 3, {}};
    for (int i = 0; i < 15; ++i) map.cavity.push_back(float(i) / 16.0f);  // exact in float
    const std::vector<CavityMap> chain = onelight::bake::cavityMipChain(map);
    ASSERT_EQ(chain.size(), 3u);
    EXPECT_EQ(chain[0].cavity, map.cavity);
    ASSERT_EQ(chain[1].width, 2u);
    ASSERT_EQ(chain[1].height, 1u);
    ASSERT_EQ(chain[2].width, 1u);
    ASSERT_EQ(chain[2].height, 1u);
    const auto at = [&](int x, int y) { return double(map.cavity[size_t(y * 5 + x)]); };
    // Texel (x, y) of mip 1 covers mip 0's (2x .. 2x+1, 2y .. 2y+1); column 4 and row 2 fall off.
    EXPECT_DOUBLE_EQ(chain[1].cavity[0], (at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1)) / 4.0);
    EXPECT_DOUBLE_EQ(chain[1].cavity[1], (at(2, 0) + at(3, 0) + at(2, 1) + at(3, 1)) / 4.0);
    EXPECT_DOUBLE_EQ(chain[2].cavity[0],
                     (double(chain[1].cavity[0]) + double(chain[1].cavity[1])) / 2.0);

    CavityMap square{64, 64, std::vector<float>(64 * 64, 1.0f)};
    const std::vector<CavityMap> squareChain = onelight::bake::cavityMipChain(square);
    ASSERT_EQ(squareChain.size(), 7u);
    for (size_t k = 0; k < squareChain.size(); ++k) {
        EXPECT_EQ(squareChain[k].width, std::max(64u >> k, 1u));
        for (float c : squareChain[k].cavity) EXPECT_EQ(c, 1.0f);
    }
    const std::vector<CavityMap> thin =
        onelight::bake::cavityMipChain({1, 5, std::vector<float>(5, 0.5f)});
    ASSERT_EQ(thin.size(), 3u);
    EXPECT_EQ(thin[1].width, 1u);
    EXPECT_EQ(thin[1].height, 2u);
    EXPECT_EQ(onelight::bake::cavityMipChain({1, 1, {0.25f}}).size(), 1u);
    EXPECT_TRUE(onelight::bake::cavityMipChain({}).empty());
}

TEST(CavityToUnorm8, RoundsToNearestAndClamps) {
    using onelight::bake::cavityToUnorm8;
    EXPECT_EQ(cavityToUnorm8(0.0f), 0);
    EXPECT_EQ(cavityToUnorm8(1.0f), 255);
    EXPECT_EQ(cavityToUnorm8(0.5f), 128);  // 127.5
    EXPECT_EQ(cavityToUnorm8(0.25f), 64);  // 63.75
    EXPECT_EQ(cavityToUnorm8(0.4f / 255.0f), 0);
    EXPECT_EQ(cavityToUnorm8(0.6f / 255.0f), 1);
    EXPECT_EQ(cavityToUnorm8(100.4f / 255.0f), 100);
    EXPECT_EQ(cavityToUnorm8(-0.5f), 0);
    EXPECT_EQ(cavityToUnorm8(3.0f), 255);
    EXPECT_EQ(cavityToUnorm8(std::numeric_limits<float>::quiet_NaN()), 255);
    const std::vector<uint8_t> bytes = cavityToUnorm8(CavityMap{3, 1, {0.0f, 0.5f, 1.0f}});
    EXPECT_EQ(bytes, (std::vector<uint8_t>{0, 128, 255}));
}

}  // namespace
