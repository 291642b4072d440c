// Prefiltering of environment probes: mip m of the result is the captured radiance convolved
// with the runtime BRDF's lobe (GGX, ggx_smith in docs/brdf-report) for the gloss
// probeGlossOfMip(m) of shaders/probe.glsl, so that the shader's probeMipOfGloss reads the
// lobe of its material.
#pragma once

#include "cubemap.hpp"

namespace onelight::bake {

struct PrefilterOptions {
    // GGX importance samples per output texel (Hammersley): at least this many, and at least
    // 4 per source texel under the lobe (4 * solid angle holding 90% of the lobe / solid angle
    // of a source texel), so that a source smaller than the lobe is never missed.
    int samplesPerTexel = 1024;
    int maxSamplesPerTexel = 65536;
};

// The samples per texel that prefilterGGX uses for a lobe of `alpha` over a source of face
// size `sourceSize`.
[[nodiscard]] int prefilterSampleCount(float alpha, int sourceSize,
                                       const PrefilterOptions& options);

// Karis 2013 ("Real Shading in Unreal Engine 4", split-sum prefilter) with the n = v = r
// assumption: for a texel of direction r and lobe alpha,
//   L(r) = int L(l) D(h) NoL dl / int D(h) NoL dl,   h = normalize(r + l), NoL = r.l > 0,
// estimated with l drawn by sampling h ~ D(h) NoH (pdf(l) = D / 4 since NoH = VoH):
//   L(r) ~= sum L(l_k) NoL_k / sum NoL_k.
// Each sample reads the source at the mip whose texel solid angle matches the sample's
// (Krivanek and Colbert 2008, filtered importance sampling, no bias), which removes the noise
// of undersampling small bright sources without blurring more than the lobe does.
// Where the lobe is wide (the small, rough mips) summing the integral over every texel of a
// source mip fine enough for the lobe (>= 16 texels per alpha: D moves by under 2% across a
// texel there) is exact and cheaper than the
// samples a tiny bright source needs, so each mip takes whichever of the two costs fewer
// evaluations (Lazarov 2011 used CubeMapGen's angular-extent filtering, which sums texels).
// `radiance` needs mip 0 filled; its mips are rebuilt. The result has the same mip count;
// mip 0 (gloss 1, alpha 0.0028) is a copy, its lobe being narrower than a texel.
[[nodiscard]] Cubemap prefilterGGX(Cubemap radiance, const PrefilterOptions& options = {});

// The reference for tests: the same integral by brute-force quadrature over the whole sphere,
// of `radiance`'s mip 0 read bilinearly as the prefilter reads it, at `subdivisions`^2 points
// per source texel (choose them finer than alpha). Slow.
[[nodiscard]] glm::vec3 prefilteredReference(const Cubemap& radiance, glm::vec3 r, float alpha,
                                             int subdivisions);

}  // namespace onelight::bake
