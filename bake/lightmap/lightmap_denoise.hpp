// The lightmap denoiser: a geometry-guided local-linear filter of the indirect part of every
// texel's estimate (docs/lighting.md "Denoising"). It reads neighbours in world space, so the
// texels of another chart across a seam join as if the seam were not there; it never filters
// the shadow mask or the direct light, so hard shadow edges stay where they were traced.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bake/embree/bake_scene.hpp"
#include "bake/lightmap/texel_estimate.hpp"
#include "bake/lightmap/texel_placement.hpp"

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

}  // namespace onelight::bake
