// Statistics of the runtime specular NDF as functions of gloss, for normal-and-gloss mips: GGX
// (shaders/brdf.glsl, D_GGX) at alpha = ggxAlpha_fromGloss(gloss) (Chan 2018, "Material
// Advances in Call of Duty: WWII", eq. 2). Two statistics, each strictly monotone in gloss, so
// that a mip can measure one on its footprint and read back the gloss of the lobe that has it:
//
//  - the average normal length (Chan 2018, sec. 2.1): the length of the mean microfacet normal
//    when microfacets weigh by their area. Since the projected area is 1 (integral of D cos is
//    1) and D is symmetric about n, the mean normal is n / A with A = integral of D dm, the
//    microsurface area per unit projected area; so length = 1 / A, from 1/2 at gloss 0 (A = 2,
//    D = 1/pi) to 1 - 5.0e-5 at gloss 1.
//  - the normal variance (Lazarov 2011, "Physically Based Lighting in Call of Duty: Black Ops",
//    slide "Normal Variance"), taken through the runtime NDF instead of the slide's Blinn-Phong
//    1/(n+1): var = integral of D (1 - (m.n)^2) (m.n) dm, the mean of sin^2 of the microfacet
//    normal when microfacets weigh by their projected area. Projected area because that is how
//    a mip's texels weigh: each top texel covers the same area of the texture plane, and the
//    slide's v = 1 - (1/K) sum (n_i.nbar)^2 gives each of them weight 1/K. From 1/2 at gloss 0
//    to 8.2e-5 at gloss 1.
//
// Each is tabulated at gloss = i / 255, i = 0..255 (the table size of Chan 2018, sec. 2.1), by
// quadrature (ggxLobeStatistics), as the log2 of its distance from the mirror value:
// log2(1 - length) and log2(var), both close to linear in gloss (distance ~ alpha^2 ~ 2^-18g).
// Lookups in either direction interpolate that one piecewise-linear curve, so they are exact
// inverses of each other (to rounding): a flat footprint gives back its gloss. Also a rational
// fit of gloss against the same variable (Chan 2018, sec. 3 fits rational functions), for a
// caller that wants a closed form (a shader, say), with its error over the table.
#pragma once

#include <array>

namespace onelight::bake {

// Chan 2018, eq. 2, in double: alpha = sqrt(2 / (1 + 2^(18 g))).
[[nodiscard]] double ggxAlpha_fromGloss(double gloss);

// The glTF roughness of a gloss, inverse of gloss_fromRoughness (shaders/material.glsl):
// glTF's GGX alpha is roughness^2, so roughness = (2 / (1 + 2^(18 g)))^(1/4).
[[nodiscard]] double roughness_fromGloss(double gloss);

// The two statistics of the lobe of one gloss, by quadrature, with full relative precision in
// each distance from its mirror value (each is ~1e-4 at gloss 1).
struct GgxLobeStatistics {
    double excessArea;      // A - 1, A = integral over the hemisphere of D(m) dm
    double normalVariance;  // integral of D(m) (1 - (m.n)^2) (m.n) dm
};

// Quadrature in t = ln(tan(theta_m) / alpha), where the lobe's projected measure is
// D cos dm = sech^2(t) / 2 dt for every alpha (so one grid fits every gloss); then
// A - 1 = integral of sech^2(t) / 2 (sqrt(1 + tan^2) - 1) dt and
// var = integral of sech^2(t) / 2 tan^2 / (1 + tan^2) dt, tan^2 = alpha^2 e^(2t), written without
// cancellation. Both integrands are analytic in the strip |Im t| < pi/2 and decay exponentially,
// so the trapezoidal rule converges geometrically, error ~ exp(-pi^2 / h) (Trefethen and
// Weideman 2014, "The Exponentially Convergent Trapezoidal Rule", SIAM Review 56(3), sec. 5);
// step h = 1/16, ~1000 nodes.
[[nodiscard]] GgxLobeStatistics ggxLobeStatistics(double gloss);

// One statistic tabulated at gloss = i / (kEntries - 1) as log2 of its distance from the mirror
// value: strictly decreasing in i.
struct GlossTable {
    static constexpr int kEntries = 256;
    std::array<double, kEntries> log2Distance;
};

// The tables, built on first use (function-local statics, thread-safe).
// distance = 1 - average normal length.
[[nodiscard]] const GlossTable& averageNormalLengthTable();
// distance = normal variance.
[[nodiscard]] const GlossTable& normalVarianceTable();

// The table's curve at any gloss (clamped to [0, 1]): log2(distance) linear between entries.
[[nodiscard]] double distance_fromGloss(const GlossTable& table, double gloss);
// Its inverse: monotone, clamped to gloss 0 above the gloss-0 distance and to gloss 1 below the
// gloss-1 one (a rougher or a sharper footprint than any lobe); distance <= 0 gives 1, NaN 0
// (a broken footprint should not sparkle).
[[nodiscard]] double gloss_fromDistance(const GlossTable& table, double distance);

// The pipeline's lookups, by the tables.
[[nodiscard]] double averageNormalLength_fromGloss(double gloss);
[[nodiscard]] double gloss_fromAverageNormalLength(double length);
[[nodiscard]] double normalVariance_fromGloss(double gloss);
[[nodiscard]] double gloss_fromNormalVariance(double variance);

// A rational fit of gloss against x = (-log2(distance) - xMin) / (xMax - xMin) in [0, 1],
// (xMin, xMax) the table's range: gloss = P(x) / Q(x), P of degree 3, Q of degree 2, Q(0) = 1.
// Fitted by linear least squares on the 256 table entries, iterated on the weights 1 / Q
// (Sanathanan and Koerner 1963, "Transfer function synthesis as a ratio of two complex
// polynomials", IEEE Trans. Automatic Control 8(1)) so that the residual minimized is the error
// in gloss itself; solved by Householder QR (Golub and Van Loan 2013, "Matrix Computations",
// alg. 5.3.2) in double. Max error in gloss 4.6e-4 (length) and 3.0e-4 (variance), under 1/8 of
// an 8-bit gloss step; degrees (3, 1) or (2, 2) err 5x more, (3, 3) or (4, 2) 10x less. Outside
// [0, 1] x clamps, as the table does.
struct GlossFit {
    static constexpr int kNumeratorTerms = 4;
    static constexpr int kDenominatorTerms = 3;
    double xMin = 0.0, xMax = 1.0;
    std::array<double, kNumeratorTerms> p{};    // ascending powers of x
    std::array<double, kDenominatorTerms> q{};  // ascending powers of x, q[0] = 1
    double maxGlossError = 0.0;                 // max over the table entries of |fit - i / 255|
    double rmsGlossError = 0.0;                 // RMS of the same
};

[[nodiscard]] GlossFit fitGloss(const GlossTable& table);
[[nodiscard]] const GlossFit& averageNormalLengthFit();
[[nodiscard]] const GlossFit& normalVarianceFit();

// Gloss of a distance by the fit, clamped to [0, 1]; distance <= 0 gives 1, NaN 0.
[[nodiscard]] double gloss_fromDistance(const GlossFit& fit, double distance);

}  // namespace onelight::bake
