// The error a uniform environment would cost instead of the probes, predicted from the level's
// views before any probe is captured (docs/level-report.md, "Error budget").
#pragma once

#include <cstdint>
#include <vector>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/lights.hpp"
#include "bake/lighting/radiance.hpp"
#include "world/compiled_level.hpp"

namespace onelight::bake {

struct ProbeDropSettings {
    uint32_t blocksAcross = 16;    // error blocks across a view (down: by its aspect)
    uint32_t samplesPerSide = 4;   // jittered samples per block side
    uint32_t pixelPaths = 2;       // full paths per sample for the pixel's radiance
    uint32_t lobeRays = 16;        // paths in the specular lobe about the reflection
    uint32_t hemisphereRays = 16;  // paths over the hemisphere (E)
};

struct ProbeDropPrediction {
    double error = 0.0;          // the largest view's mean block error
    std::vector<double> views;   // each view's mean block error
    uint64_t samples = 0;        // samples that hit something
    uint64_t glossySamples = 0;  // of them, on a surface with a specular lobe
    RayCounts rays;
};

/// What the runtime's secondary specular changes by, seen from each of `views`, when the probes'
/// normalised radiance P(r) is replaced by the uniform 1 / pi (runtime/render/shaders/
/// forward_shading.glsl without probes), relative to the pixel's whole radiance, per block as
/// level-report measures (bake/lab/block_error.hpp).
/*
   At a sample's first hit x (normal n, view v, reflection r), secondaryRadiance of
   shaders/lighting.glsl with the probe and without:
       dL = secondaryRadiance(.., E(n), P(r), E(n)) - secondaryRadiance(.., E(n), 1 / pi, E(n))
   where the probe is approximated by what x itself sees (no parallax):
       P(r)  = L_lobe(r) / E(n),  L_lobe the GGX-lobe (gloss) average of the radiance about r
             (split-sum: n = v = r, h drawn with density D NoH, Walter et al. 2007 eq. 35,
             weighted by NoL as the prefilter does),
       E(n)  = pi x the cosine-weighted mean radiance about n (the lightmap's irradiance, and
             the probes' statistic at both ends: x sees what the probe does, shaders/probe.glsl
             "Normalization"),
   each radiance a path of traceRadiance (the probes' own routine). Then per block b
       err_b = |sum_b Y(dL)| / max(sum_b Y(L_pixel), 0.05 mean(Y(L_pixel)) n_b)
   (Y luminance, L_pixel the samples' full radiance), and a view's error is the mean over its
   blocks. Deterministic: every sample seeds its own stream.
*/
[[nodiscard]] ProbeDropPrediction predictProbeDropError(const BakeScene& scene,
                                                        const BakeLights& lights,
                                                        const TransportSettings& transport,
                                                        const std::vector<world::Camera>& views,
                                                        const ProbeDropSettings& settings = {});

/// The views the budget predicts from: the level's cameras, else four headings (90 degrees
/// apart, level) from each player spawn at eye height, else none.
[[nodiscard]] std::vector<world::Camera> budgetViews(const world::CompiledLevel& level);

}  // namespace onelight::bake
