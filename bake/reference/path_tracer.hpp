// The reference path tracer: ground truth for the lab and the tests. Every light at full
// strength (no primary/secondary split, no shadow masks), shading through the shared BRDF
// (bake/lighting/radiance.hpp), radiance in cd/m^2 with no exposure and no tonemap.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/lights.hpp"
#include "bake/lighting/radiance.hpp"
#include "bake/report/progress.hpp"
#include "world/compiled_level.hpp"

namespace onelight::bake {

struct ReferenceImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgb;  // cd/m^2, row-major from the top, 3 floats per pixel
};

/// The ray through film point (sx, sy) of `camera` (each in [-1, 1], y up) for a frame of
/// width / height `aspect`: from the eye for a perspective camera, from the film plane along the
/// view for an orthographic one. `dir` is unit.
struct CameraRay {
    glm::vec3 origin{0.0f}, dir{0.0f, 0.0f, -1.0f};
};
[[nodiscard]] CameraRay cameraRay(const world::Camera& camera, float aspect, float sx, float sy);

/// Renders `camera`'s view with `spp` jittered paths per pixel; pixel (x, y) seeds its own
/// stream from (x, y, seed), so the image does not depend on threads, and two seeds give two
/// independent estimates (their difference measures the reference's own noise). `seenOnly`:
/// triangles the camera rays see and nothing else does (traceRadiance).
/*
   L(pixel) = (1 / A) int_pixel L(camera, w(s)) ds,  s uniform in the pixel (pdf 1 / A):
                      +---------------------------------------------+
                      | L(pixel) ~ (1 / N) sum_i traceRadiance(w_i) |
                      +---------------------------------------------+
*/
[[nodiscard]] ReferenceImage renderReference(const BakeScene& scene, const BakeLights& lights,
                                             const world::Camera& camera, uint32_t width,
                                             uint32_t height, uint32_t spp,
                                             const TransportSettings& transport, Progress* progress,
                                             RayCounts& rays, uint32_t seed = 0,
                                             const BakeScene* seenOnly = nullptr);

/// Irradiance (lux, RGB) at a surface point with every light at full strength: the reference
/// the lightmaps are checked against. An estimator independent of the lightmap's: uniform
/// hemisphere directions (not cosine-distributed), each light's visibility by its own rays.
/*
   E = sum_l E_l (n.w_l)+ V_l + int_H L(w) (n.w) dw,   w uniform on H (pdf 1 / (2 pi)):
              +------------------------------------------------------------------+
              | E ~ sum_l E_l (n.w_l)+ V_l + (2 pi / N) sum_i L(w_i) (n.w_i)       |
              +------------------------------------------------------------------+
*/
[[nodiscard]] glm::vec3 referenceIrradiance(const BakeScene& scene, const BakeLights& lights,
                                            const glm::vec3& position, const glm::vec3& normal,
                                            uint32_t samples, uint32_t seed,
                                            const TransportSettings& transport, RayCounts& rays);

}  // namespace onelight::bake
