// Mip chains of a normal map and its gloss, made together so that the normal variation a mip
// texel averages away reappears as roughness in its gloss (Lazarov 2011, "Physically Based
// Lighting in Call of Duty: Black Ops", slides "Normal Variance"; Chan 2018, "Material Advances
// in Call of Duty: WWII", sec. 2). Without it a bumpy glossy surface in the distance turns into
// a sharp mirror and sparkles: the linear blit of the runtime's textures (Blit below) does that.
//
// Footprints. Mip k is max(1, w >> k) x max(1, h >> k). Along each axis, texel x of a level of
// size n' covers texels [2x, 2x + 2) of the level above (size n), except the last one, which
// also takes the odd texel left over when n is odd (so it covers 3) and covers the whole axis
// when n' = n = 1. So every texel of a level belongs to exactly one texel of the next, and a mip
// texel's footprint on level 0 is a rectangle (mipFootprint). The four methods below compute
// from sums over that rectangle, in double, each level's sums being the sums of its children's:
// nothing is lost to intermediate rounding or normalisation, and every level-0 texel weighs the
// same (each covers the same area of the texture plane). For power-of-two sizes these are the
// 2x2 boxes of a GPU blit.
//
// Methods, for a mip texel whose footprint holds the K level-0 texels i (unit normal n_i,
// cos_i = max(n_i.z, kMinCos), gloss g_i):
//
//  Blit: what the runtime's linear blit of the glTF textures gives: normal = normalize(sum n_i),
//   gloss = gloss_fromRoughness(mean of roughness_fromGloss(g_i)). The blit averages the
//   metallic-roughness texture's G channel, roughness, not gloss.
//
//  BlackOps (Lazarov 2011, slide "Normal Variance"): the variance of the footprint's normals
//   about their normalised mean nbar, v = (1/K) sum (1 - (n_i.nbar)^2) = 1 - nbar^T M nbar with
//   M = (1/K) sum n_i n_i^T, plus the texels' own roughness as the mean of their lobes'
//   variances, v' = v + (1/K) sum var(g_i), gloss = var^-1(v'), normal = nbar. var is the
//   projected normal variance of the runtime GGX lobe (gloss_tables.hpp), so v and var(g_i)
//   are the same statistic: the mean of sin^2 of the microfacet normal about nbar, microfacets
//   weighed by their projected area. The mean of the variances is the second moment of the
//   mixture of the K lobes to first order in their spread: var(g_i) + (1 - (n_i.nbar)^2) per
//   texel, as the slide adds them. Moments come from level 0 at every mip (not mip from mip),
//   so no variance is counted twice.
//
//  Wwii (Chan 2018, sec. 2.1 and Algorithm 1, with the base gloss folded in): the footprint's
//   mean microfacet normal with microfacets weighed by their area, mapped to gloss by the
//   average normal length. Derivation: texel i is a facet of normal n_i whose projection on the
//   texture plane is one texel, so its area is 1 / cos_i. On it, the lobe of g_i has
//   microsurface area A(g_i) per unit facet area (A = 1 / averageNormalLength) and, per unit
//   facet area, sum of microfacet normals times area = integral of D m dm = n_i (projected area
//   1 along n_i, symmetric lobe). So the texel holds microsurface area A(g_i) / cos_i and area-
//   weighted normal sum n_i / cos_i, and the footprint's area-weighted mean microfacet normal is
//     average = sum(n_i / cos_i) / sum(A(g_i) / cos_i),
//   normal = normalize(average), gloss = averageNormalLength^-1(|average|): the GGX lobe whose
//   own mean normal is as long. This is the paper's "base gloss affects the weighting of our
//   normal directions": texel i's shortened normal n_i / A(g_i) weighs by its microsurface area
//   A(g_i) / cos_i. A rough texel weighs more, but its normal is shorter by the same factor, so
//   the direction is the 1/cos-weighted mean of the n_i whatever the glosses; the glosses set
//   the length, rough texels shortening it more. A flat footprint of gloss g gives
//   average = n / A(g), so gloss g again.
//
//  Clean (CLEAN mapping, Olano and Baker 2010, "LEAN Mapping", sec. 5, its isotropic form: the
//   slopes' first and second moments): texel i's normal is the slope s_i = n_i.xy / cos_i, and
//   its own lobe a spread of slopes of variance alpha(g_i)^2 / 2 per axis (a Beckmann lobe of
//   alpha has that slope variance, and GGX's core follows Beckmann's of the same alpha). The
//   footprint's slopes have mean sbar = (1/K) sum s_i and, per axis, the variance of the
//   mixture; averaged over the two axes, the lobe's
//     alpha^2 = (1/K) sum alpha(g_i)^2 + (1/K) sum |s_i|^2 - |sbar|^2,
//   normal = normalize(sbar.x, sbar.y, 1), gloss = the gloss of that alpha (Chan 2018, eq. 2,
//   inverted). Where Black Ops' variance of sin^2 is dominated by GGX's long tail, so that the
//   lobe it picks for a footprint of Gaussian bumps has about half their width, this matches
//   the core's width. A flat footprint of gloss g gives alpha(g), so gloss g again.
//
// Every method also gives each mip texel its base gloss: the gloss of the footprint's texels'
// mean alpha(g_i)^2, their own lobes without the normals' spread (at least as glossy as the
// texel's gloss). With CLEAN, alpha^2 - base alpha^2 is exactly the slopes' variance; the
// runtime shades that share of the lobe as facets (shaders/material.glsl, "A footprint's bumps").
// And the slopes' kurtosis, their fourth central moment over the square of the second, from the
// raw moments E s, E s s^T, E |s|^2 s and E |s|^4 summed as the others are:
//   E|s - m|^4 = E|s|^4 - 4 m.E[|s|^2 s] + 4 m^T E[s s^T] m + 2 |m|^2 E|s|^2 - 3 |m|^4.
//
// Robustness: level 0 of the output is the input, bit for bit (its base gloss its gloss). For the
// sums, a level-0 normal that is not finite or has length < 1e-12 counts as (0, 0, 1), others are
// normalised; a gloss that is not finite counts as 0 and others are clamped to [0, 1]; cos_i is
// floored at kMinCos, so a facet at or below the horizon (not from a height field, but authored
// maps have them) weighs as at most 100 texels. A mean normal shorter than 1e-12 per texel
// (opposite normals cancelling) gives normal (0, 0, 1). Mip texels are always finite, unit normal
// and gloss in [0, 1].
//
// Deterministic: each mip texel is a fixed-order function of the level above, computed in
// parallel rows with TBB; the result is bit-identical at any thread count.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "world/gloss_mip_method.hpp"

namespace onelight::bake {

// One level: width x height texels, row-major, rows top to bottom.
struct NormalGlossLevel {
    int width = 0, height = 0;
    std::vector<glm::vec3> normals;  // unit, tangent space, +z out of the surface
    std::vector<float> gloss;        // [0, 1]
    // [0, 1], >= gloss: the gloss of the footprint's level-0 texels' own lobes, the gloss of
    // their mean alpha^2 (Chan 2018, eq. 2), without the spread of their normals; at level 0
    // the texel's gloss. Output only: buildNormalGlossMips ignores level 0's.
    std::vector<float> baseGloss;
    // >= 1: the kurtosis of the footprint's slopes about their mean, E|s - m|^4 / (E|s - m|^2)^2
    // (2D, radial: 1 for slopes on a ring, 2 for Gaussian ones, more for a few steep slopes
    // among flat ones); 2 where the footprint's slopes do not spread (level 0). The runtime
    // shapes the bumps' facets and picks the normals it averages by it (shaders/material.glsl,
    // "A footprint's bumps"). Output only.
    std::vector<float> slopeKurtosis;
};

// Level 0 first, down to 1x1.
using NormalGlossChain = std::vector<NormalGlossLevel>;

// Which inversion of the gloss statistic the BlackOps and Wwii methods use: the table
// (default; exact on flat footprints) or its rational fit (gloss_tables.hpp, GlossFit).
enum class GlossInversion { Table, Fit };

inline constexpr double kMinCos = 0.01;

// 1 + floor(log2(max(width, height))): levels down to 1x1.
[[nodiscard]] int mipLevelCount(int width, int height);

// max(1, size >> level).
[[nodiscard]] int mipSize(int size, int level);

// A half-open range of level-0 texels along one axis.
struct TexelRange {
    int begin = 0, end = 0;
};

// The texels of a level of size `parentSize` that texel `index` of the next level (of size
// max(1, parentSize >> 1)) covers, along one axis (see Footprints above).
[[nodiscard]] TexelRange mipChildren(int parentSize, int index);

// The level-0 texels that texel `index` of mip `level` covers along an axis of level-0 size
// `size` (see Footprints above).
[[nodiscard]] TexelRange mipFootprint(int size, int level, int index);

// The full chain for `method`. Throws std::invalid_argument unless width, height >= 1 and the
// arrays hold width * height texels.
[[nodiscard]] NormalGlossChain buildNormalGlossMips(
    const NormalGlossLevel& level0, world::GlossMipMethod method,
    GlossInversion inversion = GlossInversion::Table);

}  // namespace onelight::bake
