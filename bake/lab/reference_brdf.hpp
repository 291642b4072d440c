// Double-precision reference microfacet BRDFs, written independently of shaders/brdf.glsl (no
// shared code, std::erfc instead of a fit, G instead of V): what the lab and the tests compare
// the shared float code against.
#pragma once

#include <cmath>
#include <numbers>

namespace onelight::lab::reference {

constexpr double kPi = std::numbers::pi;

inline double specPower(double gloss) { return std::pow(8192.0, gloss); }
inline double beckmannM(double gloss) { return std::sqrt(2.0 / (specPower(gloss) + 2.0)); }
inline double ggxAlpha(double gloss) { return std::sqrt(2.0 / (1.0 + std::pow(2.0, 18.0 * gloss))); }

// NDFs of the half-vector angle, given sin^2 and cos of theta_h.
inline double ndfBlinnPhong(double sin2, double cosH, double n) {
    (void)sin2;
    return (n + 2.0) / (2.0 * kPi) * std::pow(cosH, n);
}
inline double ndfBeckmann(double sin2, double cosH, double m) {
    double cos2 = cosH * cosH;
    return std::exp(-sin2 / (cos2 * m * m)) / (kPi * m * m * cos2 * cos2);
}
inline double ndfGGX(double sin2, double cosH, double alpha) {
    double cos2 = cosH * cosH, a2 = alpha * alpha;
    double t = cos2 * a2 + sin2;
    return a2 / (kPi * t * t);
}

// Smith Lambda for a direction at cosine mu (Walter et al. 2007, eqs. 25 and 35).
inline double lambdaBeckmann(double mu, double m) {
    if (mu >= 1.0) return 0.0;
    double a = mu / (m * std::sqrt(1.0 - mu * mu));
    return 0.5 * (std::exp(-a * a) / (a * std::sqrt(kPi)) - std::erfc(a));
}
inline double lambdaGGX(double mu, double alpha) {
    double tan2 = (1.0 - mu * mu) / (mu * mu);
    return 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

enum class Ndf { BlinnPhong, Beckmann, GGX };

// The exact height-correlated Smith BRDF times the cosine, F = 1:
// f NoL = D G2 / (4 NoV), G2 = 1 / (1 + Lambda(v) + Lambda(l)). Blinn-Phong uses Beckmann's
// Lambda at m = sqrt(2 / (n + 2)) (Walter et al. 2007, sec. 5.2).
inline double smithLobe(Ndf ndf, double gloss, double NoV, double NoL, double sin2H, double cosH) {
    if (NoL <= 0.0 || NoV <= 0.0) return 0.0;
    double D, lv, ll;
    if (ndf == Ndf::GGX) {
        double a = ggxAlpha(gloss);
        D = ndfGGX(sin2H, cosH, a);
        lv = lambdaGGX(NoV, a);
        ll = lambdaGGX(NoL, a);
    } else {
        double m = beckmannM(gloss);
        D = ndf == Ndf::Beckmann ? ndfBeckmann(sin2H, cosH, m)
                                 : ndfBlinnPhong(sin2H, cosH, specPower(gloss));
        lv = lambdaBeckmann(NoV, m);
        ll = lambdaBeckmann(NoL, m);
    }
    return D / (4.0 * NoV * (1.0 + lv + ll));
}

}  // namespace onelight::lab::reference
