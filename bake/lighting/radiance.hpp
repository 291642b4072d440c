// Radiance along a ray through the static world: the one light-transport routine shared by
// the lightmap baker, the light grid and the reference path tracer. Surfaces shade through the
// runtime's own surfaceReflectance (shaders/lighting.glsl, by bsdfCos of surface_point.hpp): the
// level's diffuse model with its energy-conservation weight plus the runtime specular lobe.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/lights.hpp"
#include "bake/lighting/radiance_cache.hpp"
#include "bake/lighting/sampling.hpp"
#include "bake/materials/ray_cone.hpp"
#include "bake/materials/surface_point.hpp"

namespace onelight::bake {

struct TransportSettings {
    uint32_t maxDepth = 64;      // surface hits per path; Russian roulette ends most far earlier
    uint32_t rouletteDepth = 2;  // hits after which Russian roulette starts
    bool sampleLights = true;    // one light per hit by importance (light_cells.hpp), not all
    // Cached bounces: a path ends at a diffuse hit the cache covers (radiance_cache.hpp).
    const RadianceCache* cache = nullptr;
    // A hit nearer than this many of its cache point's reach does not read the cache (its
    // light is traced on): 0 reads it at any distance.
    float cacheNearField = 0.0f;
};

/// Radiance (cd/m^2, RGB) a surface point sends towards `toViewer` by direct light: every
/// directional light, and one point or spot light chosen by resampled importance for the point
/// (or, with sampleLights off or no light cells, every light), each with one shadow ray
/// towards a random point of it. `normal` faces the viewer side.
/*
   Lo_direct(v) = sum_l int_{light l} f(v, w) L_l cos dw
               ~ sum_l f(v, w_l) E_l NoL_l vis(w_l),  w_l uniform on l's apparent disc
   with f NoL = bsdfCos (surfaceReflectance of lighting.glsl) and E_l the irradiance at
   normal incidence (lights.hpp): exact for a small light, unbiased in the visibility.
   The local lights' sum by resampled importance sampling (Talbot, Cline and Egbert 2005,
   "Importance Resampling for Global Illumination"; Bitterli et al. 2020, eq. 6 with M
   candidates): M = 8 candidates l_i drawn from the light cells' P(l | x) (light_cells.hpp),
   each weighted w_i = t(l_i) / P(l_i | x) by the target t(l) = Y(f NoL E_l) towards l's centre
   (plus a 2% floor of its diffuse term), one l_j kept with probability w_j / sum w, then
       Lo_local ~ f(v, w_j) E_j NoL_j vis(w_j) / t(l_j) x (1 / M) sum_i w_i
   unbiased wherever t > 0 where a light gives light, which the floor ensures. One shadow ray;
   the unshadowed part is nearly exact, so what is left is the visibility's noise.
*/
/// A surface point as the transport shades it.
struct ShadingPoint {
    glm::vec3 position{0.0f};
    glm::vec3 geometricNormal{0.0f, 0.0f, 1.0f};  // the triangle's, on the viewer's side
    glm::vec3 shadingNormal{0.0f, 0.0f, 1.0f};    // the material's (smooth, normal-mapped)
    Bsdf bsdf;
};

/// Light reaches the point only from above both its geometric and its shading surface: the
/// BRDF is evaluated about the shading normal, rays leave along the geometric one.
[[nodiscard]] glm::vec3 directRadiance(const BakeScene& scene, const BakeLights& lights,
                                       const TransportSettings& settings, const ShadingPoint& point,
                                       const glm::vec3& toViewer, Rng& rng, RayCounts& rays);

/// Whether `lights` holds light that is found two ways, by next-event estimation and by the
/// paths' own directions: emissive surfaces, or a sky image. (A uniform sky is left to the
/// paths: cosine-weighted directions already sample it perfectly on a diffuse surface.)
[[nodiscard]] bool samplesEmission(const BakeLights& lights);

/// One next-event sample of the emitted light seen from `origin` (already off its surface): a
/// point on an emitter drawn by power (emitters.hpp) or a direction of the sky image drawn by
/// its density (sky.hpp), each with probability 1/2 when the level has both, tested by a shadow
/// ray. `normal`, when not zero, is the hemisphere the point can receive from (directions
/// behind it are skipped without a ray). The caller weights the sample against its own
/// direction strategy of density p_other(l) with powerHeuristic(pdf, p_other(l)).
struct EmissionEstimate {
    glm::vec3 direction{0.0f, 0.0f, 1.0f};
    glm::vec3 radianceOverPdf{0.0f};  // L_e / pdf, 0 when blocked or nothing was drawn
    float pdf = 0.0f;                 // per steradian, the choice between the two included
};
[[nodiscard]] EmissionEstimate sampleEmission(const BakeScene& scene, const BakeLights& lights,
                                              const glm::vec3& origin, const glm::vec3& normal,
                                              Rng& rng, RayCounts& rays);

/// The density (per steradian) with which sampleEmission, from `origin`, draws the point a ray
/// found on scene triangle `triangle` at `distance`, arriving at cosine `cosLight` to it.
[[nodiscard]] float emitterHitPdf(const BakeLights& lights, const glm::vec3& origin,
                                  uint32_t triangle, float distance, float cosLight);

/// The density with which sampleEmission draws `direction`, a ray that escaped to the sky.
[[nodiscard]] float skyEscapePdf(const BakeLights& lights, const glm::vec3& direction);

/// What traceRadiance saw first (for inside-geometry tests).
struct FirstHit {
    bool found = false;
    bool backFace = false;
    float distance = 0.0f;
};

/// Radiance arriving at `origin` from direction `-dir` (i.e. found by looking along `dir`):
/// a path traced with next-event estimation at every hit and a continuation drawn from the
/// diffuse-specular mixture of surface_sampling.hpp.
/*
   L(x, -w) = Lo(y, -w),  y the first hit along w, or the sky's radiance along w when none.
   Lo(y, v) = Lo_direct(y, v) + int f(v, w') L(y, -w') cos' dw'
   Continuation: w' from the mixture density pdf(w') (sampleSurface), so the path throughput
   multiplies by f cos' / pdf (albedo exactly for a Lambert-only surface), and by 1 / q when
   Russian roulette survives with probability q (unbiased).
     +------------------------------------------------------------------------------+
     | L ~ sum_k T_k Lo_direct(y_k),  T_{k+1} = T_k (f cos' / pdf(w')) / q              |
     +------------------------------------------------------------------------------+
   Back faces of single-sided materials absorb (they are only seen from inside solids).
   Every hit is shaded with its material where the ray landed (bake/materials): textures read
   at the level of detail of the path's footprint `cone` (ray_cone.hpp), which each bounce
   widens; the continuation carries the material's ambient occlusion, as the runtime applies it
   to the secondary light.
   With a radiance cache (settings.cache), a hit the cache covers splits its outgoing light:
   the diffuse part is read from the cache and ends there,
       Lo_diffuse(y) ~ albedo w(NoV) / pi (E_direct(y) + occlusion E_indirect(y))
   (w: the diffuse's energy weight at this view, diffuseEnergyWeight of surface_point.hpp, as
   bsdfCos weights a traced bounce's diffuse; without it a wall with a specular lobe sent back
   its whole albedo, and a room of them read 10-17% bright)
   and the specular part is traced on with probability p = specularProbability(NoV) (weight
   1 / p, unbiased): the vertex continues as below with its albedo set to zero, so its direct
   light, emission sample and continuation are the specular lobe's alone. A Lambert surface
   ends the path at once; a metal (albedo 0, p ~ 1) is traced on as before. What the cache
   leaves is its own error: the nearest texel's irradiance, constant over a texel, and the
   bounces its passes and their extrapolated tail approximate. Hits the cache does not cover
   (a back side, a surface without texels) shade in full.
   Emissive surfaces (emitters.hpp) and a sky image (sky.hpp) are found two ways, combined by
   multiple importance sampling (Veach 1997, ch. 9, power heuristic): at every hit one
   sampleEmission (weight w_e = p_e^2 / (p_e^2 + p_f^2), p_f the continuation's density of that
   direction), and the emission a continuation lands on or the sky it escapes to (weight
   p_f^2 / (p_f^2 + p_e^2)). The first segment's has weight 1 unless the caller calls
   sampleEmission at `origin` too, once per direction, and passes the density `originPdf` it
   drew `dir` with.
   With `seenOnly`, a scene the first segment alone meets (the frame's items, which it draws
   without shadows and which occlude no baked light): where that segment hits one of its
   triangles before the scene's, the hit is shaded with its material, and its light, emission
   and continuation come from `scene`, where nothing else sees it.
*/
[[nodiscard]] glm::vec3 traceRadiance(const BakeScene& scene, const BakeLights& lights,
                                      const TransportSettings& settings, glm::vec3 origin,
                                      glm::vec3 dir, RayCone cone, Rng& rng, RayCounts& rays,
                                      FirstHit* firstHit = nullptr, float originPdf = 0.0f,
                                      const BakeScene* seenOnly = nullptr);

}  // namespace onelight::bake
