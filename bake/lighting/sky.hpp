// The sky as a light: an equirectangular HDR image (shaders/sky.glsl's mapping) times the
// level's scale, looked up bilinearly along a direction and importance-sampled by a
// piecewise-constant density over its texels (Pharr, Jakob and Humphreys, "Physically Based
// Rendering", 4th ed., sec. 12.5.2: a marginal density over rows, a conditional one over the
// columns of each row).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "world/images/image_decode.hpp"

namespace onelight::bake {

/*
   Texel weight w_ij = (Ybar_ij + Y_mean / 64) sin(theta_i), theta_i at the row's centre: the
   mean luminance of the bilinear lookup over the texel (Ybar, the image filtered by
   [1/8, 3/4, 1/8] each way: a hot texel's light spreads half a texel into its neighbours)
   times the solid angle of its row, with a floor so that every direction has a density.
   Uniform (u, v) within a texel, so over the sphere (dw = 2 pi^2 sin(theta) du dv):
                  +----------------------------------------------------------+
                  | p(w) = w_ij W H / (sum w) / (2 pi^2 sin(theta(w)))        |
                  +----------------------------------------------------------+
*/
struct SkyImage {
    uint32_t width = 0, height = 0;
    std::vector<glm::vec3> radiance;  // cd/m^2, row-major, the top row the zenith
    std::vector<float> rowCdf;        // height + 1 entries, 0 .. 1: the marginal over rows
    std::vector<float> columnCdf;     // height rows of width + 1 entries, 0 .. 1 each
    std::vector<float> texelDensity;  // p(u, v) of each texel, W H w_ij / sum w
    [[nodiscard]] bool empty() const { return radiance.empty(); }
};

/// The sky of `image` (linear RGB, e.g. world::readHdrFile) times `scale` (cd/m^2 per unit).
/// An image of zero light is kept (it shows black) and sampled uniformly.
[[nodiscard]] SkyImage makeSkyImage(const world::HdrImage& image, glm::vec3 scale);

/// Radiance (cd/m^2) arriving from direction `direction` (unit, towards the sky): bilinear
/// between texel centres, wrapping around in u and clamped at the poles.
[[nodiscard]] glm::vec3 skyRadiance(const SkyImage& sky, const glm::vec3& direction);

struct SkySample {
    glm::vec3 direction{0.0f, 1.0f, 0.0f};  // unit, towards the sky
    glm::vec3 radiance{0.0f};               // cd/m^2 along it
    float pdf = 0.0f;                       // per steradian; 0: nothing drawn (a pole)
};

/// A direction drawn with density skyPdf from two uniform numbers.
[[nodiscard]] SkySample sampleSky(const SkyImage& sky, glm::vec2 u);

/// The density (per steradian) with which sampleSky draws `direction`.
[[nodiscard]] float skyPdf(const SkyImage& sky, const glm::vec3& direction);

}  // namespace onelight::bake
