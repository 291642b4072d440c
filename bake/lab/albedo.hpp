// Directional albedo of the specular BRDFs by numerical integration over half vectors.
//
// For a view at cosine mu, reflecting v about a half vector h gives l with NoL = 2 VoH NoH - mu
// and dl = 4 VoH dh, so for any lobe f:
//   A(mu) = int f(l, v) NoL dl = int f NoL 4 VoH dh,  over the half vectors with NoL > 0.
// With h = (theta, phi) about n and v in the xz-plane, NoL > 0 <=> cos phi > C(theta) with
//   C = -mu cos(2 theta) / (sin(theta_v) sin(2 theta)),
// so phi runs over [0, acos C] (doubled by symmetry) and the inner integral is smooth. theta is
// mapped from u in [0, 1) by tan theta = w tan(u pi / 2), w the lobe width, which spreads the
// lobe over u even at gloss 1 (GGX alpha = 0.0028). Both integrals are adaptive Gauss-Kronrod.
#pragma once

#include <cmath>
#include <numbers>

#include "models.hpp"
#include "quadrature.hpp"

namespace onelight::lab {

// One reflection configuration, in double.
struct Reflection {
    double NoV, NoL, VoH;
    double sin2H, cosH;  // of the half vector's polar angle
};

// The shared BRDF is float: its values carry ~1e-7 relative noise, so tolerances below that
// can never be met. These give albedos accurate to ~1e-6 (tests/lab checks 1e-4 against
// independent integrations).
struct HalfVectorTolerance {
    QuadratureTolerance outer{1e-8, 1e-6, 400};
    QuadratureTolerance inner{1e-9, 1e-6, 100};
};

// int g(reflection) dh over the half vectors with NoL > 0 (g returns Vec<N>).
template <int N, class G>
[[nodiscard]] Vec<N> integrateHalfVectors(double mu, double width, const G& g,
                                          HalfVectorTolerance tol = {}) {
    double sinV = std::sqrt(std::max(0.0, 1.0 - mu * mu));
    auto outer = [&](double u) -> Vec<N> {
        double t = std::tan(0.5 * std::numbers::pi * u);
        double theta = std::atan(width * t);
        double dThetaDu =
            0.5 * std::numbers::pi * width * (1.0 + t * t) / (1.0 + width * width * t * t);
        double sinH = std::sin(theta), cosH = std::cos(theta);
        double cos2 = (cosH - sinH) * (cosH + sinH), sin2 = 2.0 * sinH * cosH;
        double phiMax;
        if (sinV * sin2 <= 1e-300) {
            phiMax = (mu * cos2 > 0.0) ? std::numbers::pi : 0.0;
        } else {
            double C = -mu * cos2 / (sinV * sin2);
            phiMax = C <= -1.0 ? std::numbers::pi : (C >= 1.0 ? 0.0 : std::acos(C));
        }
        Vec<N> r{};
        if (phiMax <= 0.0) return r;
        auto inner = [&](double phi) -> Vec<N> {
            double VoH = sinV * sinH * std::cos(phi) + mu * cosH;
            double NoL = 2.0 * VoH * cosH - mu;
            if (NoL <= 0.0) return Vec<N>{};
            return g(Reflection{mu, NoL, VoH, sinH * sinH, cosH});
        };
        r = integrate<N>(inner, 0.0, phiMax, tol.inner);
        for (double& x : r) x *= 2.0 * sinH * dThetaDu;
        return r;
    };
    return integrate<N>(outer, 0.0, 1.0, tol.outer);
}

// Albedo with Schlick Fresnel of reflectance f0 is f0 * scale + bias.
struct ScaleBias {
    double scale, bias;
    double albedo(double f0) const { return f0 * scale + bias; }
};

// Through the shared float BRDF of shaders/brdf.glsl. mu in (0, 1], gloss in [0, 1].
[[nodiscard]] ScaleBias specularAlbedo(const SpecularModel& model, double mu, double gloss);

// The double-precision exact-Smith reference of the model's NDF (reference_brdf.hpp).
[[nodiscard]] ScaleBias referenceAlbedo(const SpecularModel& model, double mu, double gloss);

// Relative L1 error of the model's lobe f NoL (F = 1) against its exact-Smith reference:
// int |f - f_ref| NoL dl / int f_ref NoL dl.
[[nodiscard]] double lobeError(const SpecularModel& model, double mu, double gloss);

}  // namespace onelight::lab
