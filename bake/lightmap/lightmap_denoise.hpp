// The lightmap denoiser: a geometry-guided local-linear filter of the indirect part of every
// texel's estimate (docs/lighting.md "Denoising"). It reads neighbours in world space, so the
// texels of another chart across a seam join as if the seam were not there; it never filters
// the shadow mask or the direct light, so hard shadow edges stay where they were traced. A texel
// moved out of a solid takes its indirect part from its neighbours on every side of the solid.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bake/embree/bake_scene.hpp"
#include "bake/lightmap/texel_estimate.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "world/compiled_level.hpp"

namespace onelight::bake {

struct DenoiseSettings {
    bool enabled = true;
    // The relative noise (standard error over value) a texel's window is sized to reach.
    double targetNoise = 0.01;
};

/// The largest window radius, in texels of the filtered texel's footprint.
inline constexpr int kDenoiseMaxRadius = 5;

/// Texel centres hashed in world space for the denoiser's neighbourhood queries.
struct TexelHash {
    float cellSize = 1.0f;  // metres: twice the largest window radius of any texel
    uint32_t bucketMask = 0;
    std::vector<uint32_t> bucketFirst;  // bucketMask + 2 offsets into `texels`
    std::vector<uint32_t> texels;       // sample indices, increasing within a bucket
};

[[nodiscard]] TexelHash makeTexelHash(const std::vector<TexelSample>& samples);

/// Marks in `needed` (one flag per sample) every texel whose estimate the denoised texels
/// `owned` (indices into samples) may read: themselves and every texel within the largest
/// window.
void markDenoiseFootprint(const TexelHash& hash, const std::vector<TexelSample>& samples,
                          const std::vector<uint32_t>& owned, std::vector<uint8_t>& needed);

/// Texel i's indirect part, filtered.
struct DenoisedIndirect {
    glm::dvec3 indirect{0.0}, indirectDirection{0.0};
    double indirectLuminance = 0.0;
    double noise = 0.0;  // its luminance standard error, from the window's weights
    int radius = 0;      // texels; 0: the texel was already quiet (or moved) and is kept
};

/// Filters texel i from the estimates of its neighbours (indexed like `samples`; every texel
/// markDenoiseFootprint marked for i must hold its estimate). Deterministic: the result
/// depends only on the estimates, never on threads or on which other texels are filtered.
[[nodiscard]] DenoisedIndirect denoiseTexel(const BakeScene& scene, const TexelHash& hash,
                                            const std::vector<TexelSample>& samples,
                                            const std::vector<TexelEstimate>& estimates, size_t i,
                                            const DenoiseSettings& settings, RayCounts& rays);

/// A texel moved out of a solid (its centre under a wall standing on its surface) gathered on the
/// one side it was moved to, and bilinear filtering carries its value onto every side of the
/// solid's foot: a floor texel under a wall traced from its sunlit side lit the shadow beside
/// the wall's other face. Its indirect part is instead taken from its unmoved neighbours among
/// its eight in its chart (the texels the bilinear filter blends with it; their denoised
/// values): the value v whose error relative to each neighbour's whole light T_q (direct, its
/// primary's and indirect luminance) is least in the squares' sense, sum_q ((v - I_q) / T_q)^2:
///   v = sum_q (I_q / T_q^2) / sum_q (1 / T_q^2).
/// Of two sides the darker is kept nearly exactly: light does not leak into a shadow or into a
/// dim room from the sunlit side, and the brighter side loses a share of its own whole light,
/// a contact shadow at the foot. Returns the texel's own estimate when it was not moved or has
/// no such neighbour. `denoised` holds the denoised indirect of each texel in `reads`.
[[nodiscard]] DenoisedIndirect movedTexelIndirect(const world::CompiledLevel& level,
                                                  const std::vector<TexelSample>& samples,
                                                  const std::vector<TexelEstimate>& estimates,
                                                  size_t i, const std::vector<uint32_t>& reads,
                                                  const std::vector<DenoisedIndirect>& denoised);

/// The neighbours movedTexelIndirect reads for the moved texels among `owned`: sorted, unique.
[[nodiscard]] std::vector<uint32_t> movedTexelReads(const world::CompiledLevel& level,
                                                    const std::vector<TexelSample>& samples,
                                                    const std::vector<TexelEstimate>& estimates,
                                                    const std::vector<uint32_t>& owned);

}  // namespace onelight::bake
