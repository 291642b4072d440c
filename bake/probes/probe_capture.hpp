// Environment probes in the bake: where they go, their HDR radiance cubes path traced through
// the reference's radiance routine (every light at full strength, primaries included), their
// normalization by the secondary irradiance at the capture point, prefiltering and packing
// into section 35's texels (world/package/probe_section.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/lights.hpp"
#include "bake/lighting/radiance.hpp"
#include "bake/report/progress.hpp"
#include "prefilter.hpp"
#include "world/compiled_level.hpp"
#include "world/package/probe_section.hpp"

namespace onelight::bake {

struct ProbePlacement {
    glm::vec3 position{0.0f};              // metres, world: the capture point
    glm::vec3 boxMin{0.0f}, boxMax{0.0f};  // box projection when min < max on every axis
    uint32_t entity = world::kNoIndex;     // the probe entity, kNoIndex when placed
    bool insideSolid = false;  // authored inside solid geometry: its cube sees back faces, dark
};

// The probes of a level: placeProbes in probe_placement.hpp.

struct ProbeCaptureSettings {
    uint32_t faceSize = 64;         // mip 0 edge, a power of two: draft 32, default 64, high 128
    uint32_t samplesPerTexel = 64;  // paths per mip-0 texel: draft 16, default 64, high 256
    TransportSettings transport;
    PrefilterOptions prefilter;
};

// E_avg of an ambient cube (faces +x -x +y -y +z -z): the average over all unit normals n of
// the irradiance the runtime reconstructs, E(n) = sum_i n_i^2 C[i, sign n_i]
// (ambientCubeIrradiance, shaders/lighting.glsl irradianceAmbientCube). Derivation: over the
// sphere, n_i^2 restricted to n_i > 0 averages to half of n_i^2's mean 1/3 (by symmetry
// n_x^2 + n_y^2 + n_z^2 = 1 gives mean(n_i^2) = 1/3, and the two signs of n_i share it equally),
// so mean E = sum_i (1/6) C[i+] + (1/6) C[i-] = (1/3) sum_i (C[i+] + C[i-]) / 2: the mean of the
// six faces. Linear in the cube, so it commutes with the grid's trilinear interpolation.
[[nodiscard]] glm::vec3 ambientCubeAverage(const std::array<glm::vec3, 6>& ambientCube);

// The radiance cube (cd/m^2, mip 0 filled, smaller mips allocated and black) seen from
// `position`: each mip-0 texel is the mean radiance over its solid angle, estimated with
// settings.samplesPerTexel paths through traceRadiance (bake/lighting/radiance.hpp, the
// reference path tracer's routine). Texel (x, y) of `face` seeds its own stream from
// (probeIndex, face, texel), so the cube does not depend on threads. Advances `progress` by one
// per row of a face (6 * faceSize in all).
/*
   L_t = (1 / W_t) int_t L(w) dw; (u, v) uniform over the texel's square of area A = (2 / S)^2
   on the face plane at distance 1, w = normalize(x, y, 1) with r = sqrt(x^2 + y^2 + 1):
   dw = dA / r^3, so pdf(w) = r^3 / A:
                    +------------------------------------------------------+
                    | L_t ~ (A / (W_t N)) sum_i traceRadiance(w_i) / r_i^3 |
                    +------------------------------------------------------+
   with (u, v) on a rotated Hammersley set (stratified within the texel).
*/
[[nodiscard]] Cubemap captureProbe(const BakeScene& scene, const BakeLights& lights,
                                   glm::vec3 position, uint32_t probeIndex,
                                   const ProbeCaptureSettings& settings, Progress* progress,
                                   RayCounts& rays);

// RGB9E5 texels of every mip of `cube`, mips from the largest, faces in order, rows from the
// top (section 35's order), and back.
[[nodiscard]] std::vector<uint32_t> packProbeTexels(const Cubemap& cube);
[[nodiscard]] Cubemap unpackProbeTexels(const world::EnvironmentProbe& probe);

// Irradiance on surfaces facing +x -x +y -y +z -z (an ambient cube), lux per channel.
using IrradianceCube = std::array<glm::vec3, 6>;

// The stored probe: `radiance` (mip 0 as captureProbe leaves it) divided per channel by E_avg,
// the mean of `irradiance` (probeNormalize, shaders/probe.glsl), prefiltered with prefilterGGX,
// packed; `irradiance` kept as the capture's side of the probes' statistic (shaders/probe.glsl,
// "Normalization").
[[nodiscard]] world::EnvironmentProbe finishProbe(Cubemap radiance, const ProbePlacement& placement,
                                                  const IrradianceCube& irradiance,
                                                  const PrefilterOptions& options);

// Probes [begin, end) of `placements`, in order: captured (probe i seeds with i, so a shard
// of the range gives the same probes as the whole) and finished with irradiance[i] (the light
// grid's cube without the punctual lights' direct light, as the runtime samples the grid at the
// capture point: probeIrradianceCubes in bake_level.hpp). One progress bar, "probes", over
// every probe's rows.
[[nodiscard]] std::vector<world::EnvironmentProbe> bakeProbes(
    const BakeScene& scene, const BakeLights& lights, const std::vector<ProbePlacement>& placements,
    const std::vector<IrradianceCube>& irradiance, const ProbeCaptureSettings& settings,
    size_t begin, size_t end, bool showProgress, RayCounts& rays);

}  // namespace onelight::bake
