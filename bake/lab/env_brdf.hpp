// The environment "Fresnel" (split-sum) term: the specular directional albedo f0 * scale + bias
// of the runtime BRDF, as the shader needs it for prefiltered probes. Candidates: the Black Ops
// fit (shaders/brdf.glsl), lookup tables like a GPU samples them, and a rational fit.
#pragma once

#include <string>
#include <vector>

#include "albedo.hpp"

namespace onelight::lab {

struct EnvSample {
    double mu, gloss;
    ScaleBias truth;
};

// The model's albedo at every (mu, gloss) of the grid, computed in parallel, deterministic.
[[nodiscard]] std::vector<EnvSample> envTruth(const SpecularModel& model,
                                              const std::vector<double>& mus,
                                              const std::vector<double>& glosses);

// A resolution x resolution table with texel centres at ((i + 0.5) / res, (j + 0.5) / res),
// sampled bilinearly with clamp-to-edge as a GPU sampler does (float texels).
struct SplitSumTable {
    int resolution = 0;
    std::vector<float> scale, bias;  // row-major, row = gloss, column = mu
    ScaleBias sample(double mu, double gloss) const;
};
[[nodiscard]] SplitSumTable buildSplitSumTable(const SpecularModel& model, int resolution);

// The lab's own fit: scale and bias each a linear combination of 27 basis functions
//   P_i(2x - 1) P_j(2y - 1) * {1, 1 - w, k},  i, j <= 2,  x = sqrt(NoV), y = sqrt(alpha),
//   P_i the Legendre polynomials, w = NoV / sqrt(NoV^2 + alpha^2 (1 - NoV^2)) (the mirror-limit
//   height-correlated Smith G2), k = (1 - NoV)^5 (Schlick's weight at the mirror direction),
// fitted by linear least squares. w carries the grazing feature of width ~alpha that no low
// polynomial in (NoV, gloss) can follow at high gloss; rational fits in (NoV, gloss) grew poles.
// Legendre polynomials and 1 - w (rather than monomials and w, which is ~1 almost everywhere)
// keep the terms from cancelling, so float evaluation stays within ~1e-6 of exact.
struct EnvFit {
    static constexpr int kTerms = 27;
    std::vector<double> scale, bias;  // kTerms coefficients each, in envFitBasis order
    ScaleBias evaluate(double mu, double gloss) const;
};

// The basis functions at (mu, gloss), in coefficient order.
[[nodiscard]] std::vector<double> envFitBasis(double mu, double gloss);

// Least-squares fit to the samples.
[[nodiscard]] EnvFit fitEnv(const std::vector<EnvSample>& samples);

// The fit as shaders/env_brdf_fit.glsl source; `provenance` goes into its header comment.
[[nodiscard]] std::string envFitGlsl(const EnvFit& fit, const std::string& provenance);

}  // namespace onelight::lab
