// Where a path goes after it hits a surface: one direction drawn from a mixture of the diffuse
// lobe (cosine) and the specular lobe (the GGX normal distribution), weighted by the mixture's
// density. Sampling only the cosine left the specular lobe to chance: a floor of gloss 0.8 seen
// through cosine samples is a field of fireflies (its lobe covers ~1e-4 of the hemisphere).
#pragma once

#include <glm/glm.hpp>

#include "bake/lighting/sampling.hpp"
#include "bake/materials/surface_point.hpp"

namespace onelight::bake {

/// The continuation and its throughput factor f(v, l) NoL / pdf(l); weight 0 ends the path.
struct SurfaceSample {
    glm::vec3 direction{0.0f};
    glm::vec3 weight{0.0f};
    float pdf = 0.0f;  // the mixture's density of `direction` (per steradian); 0 with weight 0
};

/// Probability of drawing from the specular lobe at view cosine NoV: the luminance of its
/// Schlick reflectance at normal view, F(NoV) = f0 + (1 - f0)(1 - NoV)^5, over that plus the
/// diffuse albedo's. 0 for a Lambert-only material (no lobe), 1 without albedo.
[[nodiscard]] float specularProbability(const Bsdf& material, float NoV);

/// Density (per steradian) of sampleSurface drawing l at (n, v): the mixture
///   pdf(l) = (1 - p) NoL / pi + p D(h) NoH / (4 VoH),   h = normalize(v + l), p as above
/// (Walter et al. 2007, eq. 14 and 38: a half vector drawn with density D NoH reflects to l
/// with density D NoH / (4 VoH)).
[[nodiscard]] float surfacePdf(const Bsdf& material, const glm::vec3& n, const glm::vec3& v,
                               const glm::vec3& l);

/// Draws the continuation at a hit with unit normal n (facing v) seen from unit v: with
/// probability p a GGX half vector about n (cos^2 theta_h = (1 - u) / (1 + (a^2 - 1) u),
/// Walter et al. 2007 eq. 35) reflected about v, else a cosine direction. The weight is the
/// BRDF times NoL over the mixture density (Veach 1997, sec. 9.2.2: one sample from a mixture
/// is unbiased with weight f cos / sum_i p_i pdf_i, the balance heuristic):
///            +---------------------------------------------------------------------+
///            | weight = (albedo NoL / pi + specularLobe(v, l)) / pdf(l)             |
///            +---------------------------------------------------------------------+
/// A Lambert-only surface draws exactly as before (two random numbers, cosine).
[[nodiscard]] SurfaceSample sampleSurface(const Bsdf& material, const glm::vec3& n,
                                          const glm::vec3& v, Rng& rng);

}  // namespace onelight::bake
