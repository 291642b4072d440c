// The facet table of a normal map: the distribution of its facets' normals over the whole tile,
// as the runtime reads it where a pixel's footprint holds the whole tile (shaders/material.glsl,
// "A footprint's bumps"; docs/materials.md, "The whole tile's facets").
//
// Two moments of a footprint's slopes (CLEAN's mips) and their kurtosis fix a lobe's width and
// little of its shape. An egg crate's slopes fill a diamond, |s_x| + |s_y| <= A, densest at its
// edges: rotated by 45 degrees they are two independent arcsine distributions. No isotropic
// lobe of those moments draws a low sun's glint on it far away: the glint looks at slopes near
// the middle of the diamond, where the density is neither a Gaussian's nor a ring's. Where a
// footprint holds the whole tile, its slopes are the tile's, whatever their shape, so the
// texture stage tabulates them once per normal map.
//
// Definition. The map is read as the runtime reads level 0: bilinear between texel centres (wrapped
// as its sampler wraps), the normal normalised. At K points i spread evenly over it (4x4 per
// texel up to 512^2 texels, 2x2 up to 2048^2, then 1), the normal n_i has slope q_i = n_i.xy /
// n_i.z (tangent space, z floored at kMinCos) and its own GGX lobe alpha_i^2, the texels'
// alpha(g)^2 interpolated alike. The tile's facets have the slope density (per unit area of the
// texture plane)
//   P(q) = (1/K) sum_i P_GGX(q - q_i; alpha_i),   P_GGX(q; a) = a^2 / (pi (a^2 + |q|^2)^2)
// (the texels' lobes added in slope space, as LEAN and CLEAN add them), and the normal
// distribution D(m) = P(m.xy / m.z) / m.z^4, so that the integral of D(m) m.z over the
// hemisphere is the integral of P, 1: the share of the texture plane whose facets face m. The
// table holds D at kFacetTableSize^2 points c = m.xy of the unit disc (the projected hemisphere):
// texel (x, y) at c = ((x + 0.5) / N * 2 - 1, (y + 0.5) / N * 2 - 1); a point outside the disc
// holds D at the rim (|c| = kFacetTableRim), so that bilinear filtering near the rim stays finite.
//
// Sampling. A table point holds D averaged over about its cell, not D at its centre: each lobe is
// widened by the size of a cell where it lies in slope space, alpha^2 + cell^2 / 3 (a box of
// width w has variance w^2 / 12 per axis, and GGX's alpha^2 is twice a Beckmann core's per-axis
// variance), so that a lobe narrower than a cell is not lost between two points, and each lobe
// keeps its whole weight (a widening by the cell at the point read instead grows without bound
// towards the rim, where the cells span ever more slope, and gave a table 1.5 times its mass).
// The K points are first gathered into kFacetBins^2 bins of slope where there are more of them
// (each bin its points' mean slope and mean alpha^2; the bins span the texels' slopes but their
// steepest 0.5%, as one texel at the horizon would widen them all; 16 blocks of rows, each with
// bins of its own, summed in order: the same sums at any thread count, a working set of 4.7 MiB),
// and each
// bin's lobe widened to at least 1.5 bins (alpha^2 + (1.5 bin)^2), so that the bins' lobes sum
// to a smooth density: the work is then bins x table points.
//
// Deterministic: each point is a fixed-order sum, rows in parallel. Finite: every value is
// finite and >= 0 (non-finite normals count as (0, 0, 1), non-finite glosses as 0).
#pragma once

#include <cstdint>
#include <vector>

#include "bake/textures/normal_gloss_mips.hpp"
#include "world/processed_textures.hpp"

namespace onelight::bake {

inline constexpr int kFacetTableSize = 128;  // points per axis of the projected disc
inline constexpr int kFacetBins = 96;        // slope bins per axis, for maps of more texels
inline constexpr float kFacetTableRim = 0.995f;

// D at the table's points, row y = 0 first (c.y = -1 + 1/N), kFacetTableSize^2 values.
struct FacetTable {
    std::vector<float> density;
};

// `repeatS`, `repeatT`: the normal texture's sampler repeats along x, y (else it clamps).
[[nodiscard]] FacetTable facetTable(const NormalGlossLevel& level0, bool repeatS, bool repeatT);

// D of the table at a unit tangent-space normal m (m.z > 0), bilinear as the runtime samples it.
[[nodiscard]] float facetTableDensity(const FacetTable& table, glm::vec3 m);

// The table as a processed texture: R16 float, every mip the 2x2 box mean of the one above (the
// runtime reads mip 0), clamped to the edge, linear filters.
[[nodiscard]] world::ProcessedTexture facetTableTexture(const FacetTable& table, std::string name);

}  // namespace onelight::bake
