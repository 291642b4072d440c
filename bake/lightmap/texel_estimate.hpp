// One lightmap texel's estimate before it is stored: what the per-texel bake
// (lightmap_bake.cpp) measures and the denoiser (lightmap_denoise.hpp) filters.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace onelight::bake {

struct TexelEstimate {
    glm::vec3 origin{0.0f};  // where the rays started (moved out of geometry if needed)
    glm::dvec3 direct{0.0}, indirect{0.0};                    // lux
    glm::dvec3 directDirection{0.0}, indirectDirection{0.0};  // sum Y(E) w
    double directLuminance = 0.0, indirectLuminance = 0.0;
    double directOpenLuminance = 0.0;  // the same lights' direct luminance unshadowed
    double noise = 0.0;                // luminance standard error of the indirect part
    // Metres: the harmonic mean distance its gathering rays travelled to the first hit (an
    // escaping ray counts as infinitely far; infinity when all escape). Where the irradiance
    // changes by ~ d / harmonicDistance over a step d (Ward's split-sphere bound).
    float harmonicDistance = 0.0f;
    glm::vec3 ownDirect{0.0f};  // lux from the own primary, shadowed (for the bounce cache)
    uint8_t mask = 0;
    bool moved = false;
};

/// The baked direct light's visibility: its shadowed over its unshadowed luminance, 1 where no
/// direct light reaches (world::LightmapTexel::directVisibility).
[[nodiscard]] inline float directVisibility(const TexelEstimate& e) {
    if (!(e.directOpenLuminance > 0.0)) return 1.0f;
    const double v = e.directLuminance / e.directOpenLuminance;
    return static_cast<float>(v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0);
}

/// The estimate's relative noise: the standard error of its indirect part over its whole
/// (direct + indirect) value; 0 for a black texel.
[[nodiscard]] inline double relativeNoise(const TexelEstimate& e) {
    const double value = e.directLuminance + e.indirectLuminance;
    return value > 0.0 ? e.noise / value : 0.0;
}

}  // namespace onelight::bake
