// The brute-force check of a normal-and-gloss mip chain: how far the shading of each mip texel
// is from what the full-resolution texture would give over the same area. For a floor in its
// tangent frame (z up), a view v and a light l, let S(n, g) be the runtime specular lobe
// (shaders/brdf.glsl, specularLobe with NDF_GGX, VIS_SMITH_CORRELATED, FRESNEL_SCHLICK, grey
// f0, of brdfDots(n, v, l)) and, for texel t of mip k with footprint F(t) (mipFootprint) of
// |F(t)| level-0 texels,
//   S_mip(t) = S(n_t, g_t),   S_ref(t) = (1/|F(t)|) sum over i in F(t) of S(n_i, g_i),
// the second being the mean over the footprint of the level-0 shading: a pixel covering F(t)
// with every level-0 texel supersampled (masking between bumps ignored). Then per mip, with
// sums over the mip's texels t and the sweep's (v, l) pairs, each term weighted by |F(t)| (so
// every level-0 texel counts once, for any size):
//   rmsReference  = sqrt(sum |F| S_ref^2 / sum |F|),
//   rmsDifference = sqrt(sum |F| (S_mip - S_ref)^2 / sum |F|),
//   relativeError = rmsDifference / rmsReference,
// a normalised RMS error: 0 for a perfect mip, 1 for a mip that shades black, and large for a
// sharp lobe where the reference is a wide one (a mirror's peak is ~1 / (pi alpha^2) high).
// At mip 0, S_mip = S_ref whenever the chain's level 0 is the level 0 given.
//
// The reference of every mip comes from one pass over level 0 per (v, l): sums of the level-0
// shading over each mip texel's footprint, built level by level from the children's sums, so
// several chains of the same level 0 share it (mipErrors). Pairs are evaluated in parallel and
// accumulated in sweep order: bit-identical at any thread count.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "bake/textures/normal_gloss_mips.hpp"

namespace onelight::bake {

// A view and a light direction, unit, in the floor's tangent frame (z up).
struct ViewLight {
    glm::vec3 view, light;
};

// For each view, given as (elevation, azimuth) in degrees, `lightsPerView` lights in its plane
// of incidence at angles psi_j = (j + 0.5) * 180 / lightsPerView from the horizon opposite the
// view, through the zenith, to the horizon behind the viewer: psi equal to the view's elevation
// is the mirror direction of the floor.
[[nodiscard]] std::vector<ViewLight> incidencePlaneSweep(
    const std::vector<glm::vec2>& viewElevationAzimuthDegrees, int lightsPerView);

struct MipLevelError {
    int level = 0, width = 0, height = 0;
    double rmsReference = 0.0;
    double rmsDifference = 0.0;
    // rmsDifference / rmsReference; 0 when both are 0, +infinity when only the reference is.
    double relativeError = 0.0;
};

// One entry per mip of the chain. Throws std::invalid_argument unless the chain has the level
// count and sizes of buildNormalGlossMips for level 0's size.
[[nodiscard]] std::vector<MipLevelError> mipError(const NormalGlossLevel& level0,
                                                  const NormalGlossChain& chain,
                                                  const std::vector<ViewLight>& sweep,
                                                  float f0 = 0.04f);

// How a mip texel is shaded: the runtime lobe S(n_t, g_t) above, or the runtime's footprint
// (shaders/material.glsl, "A footprint's bumps"): the specular of footprintReflectance, whose
// share of the lobe given by the texel's gloss and base gloss is shaded as unmasked facets.
enum class MipShading { kLobe, kFootprint };

// The same for several chains of one level 0, sharing the reference: result[c] is chain c's.
[[nodiscard]] std::vector<std::vector<MipLevelError>> mipErrors(
    const NormalGlossLevel& level0, std::span<const NormalGlossChain> chains,
    const std::vector<ViewLight>& sweep, float f0 = 0.04f, MipShading shading = MipShading::kLobe);

}  // namespace onelight::bake
