// Tangents for meshes that come without them: per-triangle UV gradients accumulated per vertex,
// orthogonalised against the normal (Lengyel 2001, "Computing Tangent Space Basis Vectors for
// an Arbitrary Mesh"); the sign in w is the bitangent handedness as glTF defines it.
#pragma once

#include <cstdint>
#include <vector>

#include "world/compiled_level.hpp"

namespace onelight::world {

/// Fills vertices[i].tangent for every vertex. Vertices without usable UVs get any unit vector
/// perpendicular to their normal with w = +1. Never produces NaN.
void generateTangents(std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices);

/// A unit vector perpendicular to the unit vector n (Duff et al. 2017, "Building an
/// Orthonormal Basis, Revisited").
[[nodiscard]] glm::vec3 anyPerpendicular(const glm::vec3& n);

}  // namespace onelight::world
