// The shadowed direct light of many lights at a gathering point (a lightmap texel, a grid
// cell): a fixed budget of shadow rays shared among the lights by importance, so that a texel
// under 64 lights costs a few times one light's rays, not 64 times.
#pragma once

#include <cstdint>
#include <vector>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/lights.hpp"
#include "bake/lighting/sampling.hpp"

namespace onelight::bake {

/// One light as a gathering point weighs it.
struct LightTerm {
    uint32_t light = 0;        // into BakeLights::lights
    LightIncidence incidence;  // seen from the shadow rays' origin
    float importance = 0.0f;   // the caller's estimate of its unshadowed share, > 0
    bool full = false;         // always its own `samplesPerLight` rays (e.g. a primary)
    float visibility = 0.0f;   // out: an unbiased estimate of the visible fraction V_l
};

/// Lights that can reach `position` (those of its light cell, or every light without cells).
[[nodiscard]] std::vector<uint32_t> lightsNear(const BakeLights& lights, const glm::vec3& position);

/*
   With p_l = importance_l / sum importance and a budget of M = 8 S rays (S = samplesPerLight):
   - at most 8 terms: each gets S stratified rays, V_l = visible / S (lightVisibility);
   - else the "large" terms (M p_l >= 1, or `full`) get n_l = min(S, round(M p_l)) stratified
     rays (S when full), V_l = visible / n_l; the "small" ones, of total probability q, share
     m = ceil(M q) rays: ray j draws small term k with probability p_k / q by a stratified
     number u_j = (j + xi) / m, and adds (q / p_k) / m to V_k when its light is visible, so
       E[V_k] = m (p_k / q) vis_k (q / p_k) / m = vis_k       (unbiased for every light)
   A bright light thus keeps as many rays as before, and dim ones cost about one ray each or
   share a few: at most about 2 M rays whatever the light count.
*/
void estimateVisibilities(const BakeScene& scene, const BakeLights& lights,
                          std::vector<LightTerm>& terms, const glm::vec3& origin,
                          uint32_t samplesPerLight, Rng& rng, RayCounts& rays);

}  // namespace onelight::bake
