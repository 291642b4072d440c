// The baked direct light's shadow edges as a distance field (docs/lighting.md "Baked shadow
// edges"). A lightmap texel's baked punctual light (world::LightmapTexel::directIrradiance) is
// shadowed or not at its centre; filtered bilinearly, a sharp edge across the texels comes out
// as stair steps a texel wide. Near such an edge the texels also keep the signed distance to
// it, measured on a finer lattice of visibility samples, which the runtime filters instead of
// the visibility (shaders: forward_shading.glsl, directEdgeFactor): the edge is then a straight
// line through the texels, drawn as sharp as its penumbra, the way a distance-field glyph is.
#pragma once

#include <cstdint>
#include <vector>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/lights.hpp"
#include "bake/lightmap/texel_estimate.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "world/compiled_level.hpp"

namespace onelight::bake {

/// Visibility samples per texel edge on the finer lattice (kEdgeLattice^2 per texel).
inline constexpr uint32_t kEdgeLattice = 4;

/// A texel's edge (world::LightmapTexel's directEdge* fields): sharpness 0 and low = high = its
/// visibility where none is drawn.
struct DirectEdge {
    float distance = 0.0f;   // texels, signed (+ lit), within +-world::kDirectEdgeReach
    float width = 0.0f;      // texels: the penumbra across the edge, within kDirectEdgeMaxWidth
    float low = 1.0f;        // the visibility on the edge's dark side...
    float high = 1.0f;       // ...and on its lit side
    float sharpness = 0.0f;  // 1: the runtime draws the edge; 0: the bilinear visibility
};

/// The baked lights' visibility (all but the surface's own primary), luminance-weighted, from
/// `origin` on a surface of normal `n`: what directVisibility(estimate) is at a texel centre.
/// 1 where none reaches.
[[nodiscard]] float directVisibilityAt(const BakeScene& scene, const BakeLights& lights,
                                       uint32_t ownPrimary, const glm::vec3& origin,
                                       const glm::vec3& n, uint32_t shadowSamples, Rng& rng,
                                       RayCounts& rays);

/// The edges of the samples `wanted` (indices into samples; increasing). `estimates` holds the
/// direct part of every sample within kDirectEdgeReach + 2 texels of a wanted one (same
/// surface). A texel's result depends only on its identity: the same at any thread count or
/// sharding.
[[nodiscard]] std::vector<DirectEdge> directEdges(const BakeScene& scene, const BakeLights& lights,
                                                  const world::CompiledLevel& level,
                                                  const std::vector<TexelSample>& samples,
                                                  const std::vector<TexelEstimate>& estimates,
                                                  const std::vector<uint32_t>& wanted,
                                                  uint32_t shadowSamples, RayCounts& rays);

}  // namespace onelight::bake
