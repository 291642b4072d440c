// Where each lightmap texel is sampled. Every surface's triangles are rasterised into its
// atlas in lightmap-texel space (uv1 times the atlas size): a texel whose centre lies in a
// triangle samples that point; a texel the triangle only touches (a bilinear lookup somewhere
// on the triangle reads it: its centre within one texel in x and in y) traces its rays from the
// triangle's closest point, nudged inside, so no ray starts off the surface, but keeps its centre's
// own place on the triangle's plane (`centre`): the smooth part of its light (distance and cosine
// to each light) is evaluated there, so bilinear filtering reconstructs a linear field exactly up
// to the chart edge and both charts of a seam read the same value at the border. Texels no triangle
// touches are left for dilation. Sample points always lie on their own surface.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"

namespace onelight::bake {

struct TexelSample {
    uint64_t texel = 0;  // global index (atlases in order, row-major)
    uint32_t atlas = 0, x = 0, y = 0;
    uint32_t surface = 0;       // into CompiledLevel::surfaces
    glm::vec3 position{0.0f};   // metres, world, on the surface
    glm::vec3 centre{0.0f};     // metres, world: the texel centre on the triangle's plane
                                // (== position when centreInside, else past the edge)
    glm::vec3 normal{0.0f};     // unit geometric normal of the triangle (winding)
    float texelSize = 0.0f;     // metres: edge of the texel's footprint on the surface
    bool centreInside = false;  // the texel centre lies inside the triangle
};

/// Samples in increasing texel order, one per touched texel.
[[nodiscard]] std::vector<TexelSample> placeTexels(const world::CompiledLevel& level);

/// Where in `samples` (placeTexels' order) a texel is sampled; -1 when it is not.
[[nodiscard]] int64_t sampleOfTexel(const std::vector<TexelSample>& samples, uint64_t texel);

/// The sample of the texel (dx, dy) from sample i in its atlas, whichever surface's; -1 when
/// that texel lies outside the atlas or is not sampled.
[[nodiscard]] int64_t sampleAtOffset(const world::CompiledLevel& level,
                                     const std::vector<TexelSample>& samples, size_t i, int dx,
                                     int dy);

/// Total texel count over every atlas.
[[nodiscard]] uint64_t totalTexels(const world::CompiledLevel& level);

}  // namespace onelight::bake
