// Emissive surfaces as lights: the level's emissive triangles, chosen by their power and
// distance for next-event estimation (light_cells.hpp), and the multiple-importance weights that
// combine it with the paths' own (BSDF or gathering) directions that land on an emitter by chance.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/light_cells.hpp"

namespace onelight::bake {

struct EmissiveTriangle {
    uint32_t triangle = 0;                  // into BakeScene triangles
    glm::vec3 a{0.0f}, ab{0.0f}, ac{0.0f};  // a vertex and the two edges from it (Embree's u, v)
    glm::vec3 normal{0.0f, 0.0f, 1.0f};     // unit, the front face's
    float area = 0.0f;                      // m^2
    bool doubleSided = false;               // emits from both faces
};

/// The emissive triangles of a scene, with the probability of choosing each one from a point.
/*
   Power estimate P_t = A_t Y(L_t) (x 2 when double-sided), L_t the material's emission factor
   times its emissive texture's mean (the chain's last mip), weighted by distance per cell of
   `cells` (light_cells.hpp: P_t / (d^2 + h^2), 0 for cells wholly behind a one-sided emitter):
   the weight only steers the choice, any weight > 0 where the triangle lights keeps the
   estimate unbiased, because the MIS weight of a chance hit uses the same probability
   P(t | x). Triangles of zero estimate are left out (their light is found by chance hits only,
   with weight 1).
*/
struct Emitters {
    std::vector<EmissiveTriangle> triangles;
    LightCells cells;                 // P(t | x), sources indexing `triangles`
    std::vector<uint32_t> emitterOf;  // per scene triangle: its index in `triangles`, or ~0u
    [[nodiscard]] bool empty() const { return triangles.empty(); }
};

[[nodiscard]] Emitters collectEmitters(const BakeScene& scene);

/// A point drawn on an emitter for a shading point.
struct EmitterSample {
    glm::vec3 direction{0.0f, 0.0f, 1.0f};  // unit, from the shading point
    float distance = 0.0f;                  // metres to the point
    float shadowDistance = 0.0f;            // the shadow ray's length (stops short of it)
    glm::vec3 radiance{0.0f};               // cd/m^2 it sends towards the shading point
    float pdf = 0.0f;                       // per steradian; 0: nothing to add
};

/// Draws an emitter by P(t | from) (u.x), a uniform point on it (u.y, u.z), and converts the
/// area density to solid angle at `from`:
///            +-----------------------------------------------------------+
///            | pdf(w) = P(t | x) / A_t  x  d^2 / |cos theta_light|         |
///            +-----------------------------------------------------------+
[[nodiscard]] EmitterSample sampleEmitter(const BakeScene& scene, const Emitters& emitters,
                                          const glm::vec3& from, glm::vec3 u);

/// The density (per steradian) with which sampleEmitter would have drawn, from `from`, the
/// point a ray found on scene triangle `triangle` at `distance` metres, arriving at cosine
/// `cosLight` to it.
[[nodiscard]] float emitterPdf(const Emitters& emitters, const glm::vec3& from, uint32_t triangle,
                               float distance, float cosLight);

/// Veach 1997, sec. 9.2.4, the power heuristic (beta = 2) for a sample drawn from the strategy
/// of density `chosen` against the other's `other` (sample counts folded into both):
///                      +-----------------------------------+
///                      | w = chosen^2 / (chosen^2 + other^2) |
///                      +-----------------------------------+
[[nodiscard]] inline float powerHeuristic(float chosen, float other) {
    const float a = chosen * chosen, b = other * other;
    return a + b > 0.0f ? a / (a + b) : 0.0f;
}

}  // namespace onelight::bake
