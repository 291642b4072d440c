// The contract between the level compiler and whoever knows how bright each primary candidate
// is at a point: a function writing the illuminance (lux) of every primary there. The dominant
// primary is its argmax. The baker supplies one with visibility (shadow rays); this folder
// supplies one without visibility, for tests and for `compile`.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"

namespace onelight::world {

/// Writes illuminance[i] (lux, >= 0, finite) of primary i at `position` on a surface facing
/// `normal`. A zero normal means "ignore orientation" (no cosine term).
using PrimaryIlluminanceFn = std::function<void(const glm::dvec3& position, const glm::vec3& normal,
                                                std::span<double> illuminance)>;

/// Index of the largest illuminance (lowest index on ties); kNoIndex when every value is zero.
[[nodiscard]] uint32_t dominantPrimary(std::span<const double> illuminance);

/// Illuminance without visibility: world::unshadowedIlluminance (the light model of
/// shaders/lighting.glsl, the runtime's and the baker's) times the cosine of `normal`, in
/// luminance (Rec. 709). `primaries` are the level's primary-candidate lights.
[[nodiscard]] PrimaryIlluminanceFn makeUnshadowedPrimaryIlluminance(std::vector<Light> primaries);

}  // namespace onelight::world
