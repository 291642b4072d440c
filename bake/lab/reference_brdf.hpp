// Double-precision reference microfacet BRDFs, written independently of shaders/brdf.glsl (no
// shared code, std::erfc instead of a fit, G instead of V): what the lab and the tests compare
// the shared float code against.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "quadrature.hpp"

namespace onelight::lab::reference {

[[nodiscard]] inline double specPower(double gloss) {
    return std::pow(8192.0, gloss);
}
[[nodiscard]] inline double beckmannM(double gloss) {
    return std::sqrt(2.0 / (specPower(gloss) + 2.0));
}
[[nodiscard]] inline double ggxAlpha(double gloss) {
    return std::sqrt(2.0 / (1.0 + std::pow(2.0, 18.0 * gloss)));
}

// NDFs of the half-vector angle, given sin^2 and cos of theta_h.
[[nodiscard]] inline double ndfBlinnPhong(double sin2, double cosH, double n) {
    (void)sin2;
    return (n + 2.0) / (2.0 * std::numbers::pi) * std::pow(cosH, n);
}
[[nodiscard]] inline double ndfBeckmann(double sin2, double cosH, double m) {
    double cos2 = cosH * cosH;
    return std::exp(-sin2 / (cos2 * m * m)) / (std::numbers::pi * m * m * cos2 * cos2);
}
[[nodiscard]] inline double ndfGGX(double sin2, double cosH, double alpha) {
    double cos2 = cosH * cosH, a2 = alpha * alpha;
    double t = cos2 * a2 + sin2;
    return a2 / (std::numbers::pi * t * t);
}

// Smith Lambda for a direction at cosine mu (Walter et al. 2007, eqs. 25 and 35).
[[nodiscard]] inline double lambdaBeckmann(double mu, double m) {
    if (mu >= 1.0) return 0.0;
    double a = mu / (m * std::sqrt(1.0 - mu * mu));
    return 0.5 * (std::exp(-a * a) / (a * std::sqrt(std::numbers::pi)) - std::erfc(a));
}
[[nodiscard]] inline double lambdaGGX(double mu, double alpha) {
    double tan2 = (1.0 - mu * mu) / (mu * mu);
    return 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

// Exact Smith Lambda of the Blinn-Phong NDF, which has no closed form, from the projected-area
// identity (Heitz 2014, eq. 12): mu (1 + Lambda(mu)) = int D(m) <o.m>+ dm. The azimuthal
// integral is analytic: for a = sin(theta_o) sin(theta), b = mu cos(theta),
//   int_0^2pi max(0, a cos phi + b) dphi = 2 pi b               (b >= a)
//                                        = 2 (a sin phi0 + b phi0), cos phi0 = -b / a  (b < a).
// P(mu) = mu (1 + Lambda) is smooth and finite down to mu = 0, so BlinnPhongLambda tabulates it
// once per exponent at 2049 values of mu and interpolates linearly (error < 1e-8).
// ndf(sin2, cos) of any isotropic NDF; w its lobe width (for the theta mapping).
template <class Ndf>
[[nodiscard]] double projectedArea(double mu, double w, const Ndf& ndf) {
    double sinO = std::sqrt(std::max(0.0, 1.0 - mu * mu));
    auto f = [&](double u) {
        double t = std::tan(0.5 * std::numbers::pi * u), theta = std::atan(w * t);
        double dTheta = 0.5 * std::numbers::pi * w * (1.0 + t * t) / (1.0 + w * w * t * t);
        double s = std::sin(theta), c = std::cos(theta);
        double a = sinO * s, b = mu * c, azimuthal;
        if (b >= a) {
            azimuthal = 2.0 * std::numbers::pi * b;
        } else {
            double phi0 = std::acos(-b / a);
            azimuthal = 2.0 * (a * std::sin(phi0) + b * phi0);
        }
        return Vec<1>{ndf(s * s, c) * s * azimuthal * dTheta};
    };
    // The integrand has a kink where facets start to face away (b = a: theta = pi/2 - theta_o);
    // split there so that the adaptive rule sees two smooth pieces.
    double thetaKink = 0.5 * std::numbers::pi - std::acos(std::clamp(mu, 0.0, 1.0));
    double uKink = std::atan(std::tan(thetaKink) / w) * 2.0 / std::numbers::pi;
    QuadratureTolerance tol{1e-14, 1e-11, 2000};
    return integrate<1>(f, 0.0, uKink, tol)[0] + integrate<1>(f, uKink, 1.0, tol)[0];
}

[[nodiscard]] inline double projectedAreaBlinnPhong(double mu, double n) {
    return projectedArea(mu, std::sqrt(2.0 / (n + 2.0)),
                         [n](double s2, double c) { return ndfBlinnPhong(s2, c, n); });
}

// Blinn-Phong's exact Lambda for one exponent: P(mu) tabulated at 2049 values of mu.
class BlinnPhongLambda {
public:
    explicit BlinnPhongLambda(double n) {
        for (int i = 0; i < kSamples; ++i)
            projected_.push_back(projectedAreaBlinnPhong(double(i) / (kSamples - 1), n));
    }
    double operator()(double mu) const {
        double x = std::clamp(mu, 0.0, 1.0) * (kSamples - 1);
        int i = std::min(int(x), kSamples - 2);
        double P = projected_[i] + (projected_[i + 1] - projected_[i]) * (x - i);
        return std::max(0.0, P / mu - 1.0);
    }

private:
    static constexpr int kSamples = 2049;
    std::vector<double> projected_;  // P at mu = i / 2048
};

enum class Ndf { kBlinnPhong, kBeckmann, kGGX };

// The exact height-correlated Smith BRDF times the cosine, F = 1:
// f NoL = D G2 / (4 NoV), G2 = 1 / (1 + Lambda(v) + Lambda(l)), each NDF with its own Lambda
// (Blinn-Phong's from `blinnPhongLambda`, which must be built for specPower(gloss)).
[[nodiscard]] inline double smithLobe(Ndf ndf, double gloss, double NoV, double NoL, double sin2H,
                                      double cosH,
                                      const BlinnPhongLambda* blinnPhongLambda = nullptr) {
    if (NoL <= 0.0 || NoV <= 0.0) return 0.0;
    double D, lv, ll;
    if (ndf == Ndf::kGGX) {
        double a = ggxAlpha(gloss);
        D = ndfGGX(sin2H, cosH, a);
        lv = lambdaGGX(NoV, a);
        ll = lambdaGGX(NoL, a);
    } else if (ndf == Ndf::kBeckmann) {
        double m = beckmannM(gloss);
        D = ndfBeckmann(sin2H, cosH, m);
        lv = lambdaBeckmann(NoV, m);
        ll = lambdaBeckmann(NoL, m);
    } else {
        D = ndfBlinnPhong(sin2H, cosH, specPower(gloss));
        lv = (*blinnPhongLambda)(NoV);
        ll = (*blinnPhongLambda)(NoL);
    }
    return D / (4.0 * NoV * (1.0 + lv + ll));
}

}  // namespace onelight::lab::reference
