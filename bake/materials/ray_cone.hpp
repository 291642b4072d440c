// A ray's footprint, for the level of detail of the textures it reads where it lands: a cone
// (Akenine-Moller et al. 2019, "Texture Level of Detail Strategies for Real-Time Ray Tracing",
// Ray Tracing Gems ch. 20, sec. 20.3.4) of width w at its origin that widens by a spread angle
// per metre. A path's cone starts at the camera pixel (the reference) or at the sampling density
// of the rays leaving a lightmap texel, a grid cell or a probe texel, and after each bounce takes
// the solid angle its direction stands for (one over the density it was drawn with), so bounce
// rays read the mip their footprint covers instead of aliasing.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "shading.hpp"

namespace onelight::bake {

struct RayCone {
    float width = 0.0f;   // metres at the origin
    float spread = 0.0f;  // radians: the width grows by this per metre travelled

    /// The width after `distance` metres.
    [[nodiscard]] float widthAt(float distance) const { return width + spread * distance; }
};

/// The spread of each of `count` rays that cover a solid angle of `steradians` evenly: the side
/// of the square of solid angle each one stands for.
[[nodiscard]] inline float sampleSpread(float steradians, uint32_t count) {
    return std::sqrt(steradians / float(std::max(count, 1u)));
}

/// The cone of the ray leaving a hit `distance` metres along `incoming`, in a direction drawn
/// with density `pdf` (per steradian): the footprint where it left, widening by the larger of
/// the incoming spread and the solid angle 1 / pdf the new direction stands for (a mirror keeps
/// the incoming spread, a diffuse bounce widens to about a radian).
[[nodiscard]] inline RayCone bounceCone(const RayCone& incoming, float distance, float pdf) {
    const float sampled = pdf > 0.0f ? std::sqrt(1.0f / pdf) : glsl::PI;
    return {incoming.widthAt(distance), std::max(incoming.spread, std::min(sampled, glsl::PI))};
}

}  // namespace onelight::bake
