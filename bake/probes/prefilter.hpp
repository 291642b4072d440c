// Prefiltering of environment probes: mip m of the result is the captured radiance convolved
// with the runtime BRDF's lobe (GGX, ggx_smith in docs/brdf-report) for the gloss
// probeGlossOfMip(m) of shaders/probe.glsl, so that the shader's probeMipOfGloss reads the
// lobe of its material.
#pragma once

#include "cubemap.hpp"

namespace onelight::bake {

struct PrefilterOptions {
    int samplesPerTexel = 512;  // GGX importance samples per output texel (Hammersley)
    float lodBias = 1.0f;       // added to the filtered-importance-sampling mip
    bool filtered = true;       // filtered importance sampling (false: always read mip 0)
};

// Karis 2013 ("Real Shading in Unreal Engine 4", split-sum prefilter) with the n = v = r
// assumption: for a texel of direction r and lobe alpha,
//   L(r) = int L(l) D(h) NoL dl / int D(h) NoL dl,   h = normalize(r + l), NoL = r.l > 0,
// estimated with l drawn by sampling h ~ D(h) NoH (pdf(l) = D / 4 since NoH = VoH):
//   L(r) ~= sum L(l_k) NoL_k / sum NoL_k.
// Each sample reads the source at the mip whose texel solid angle matches the sample's
// (Krivanek and Colbert 2008, filtered importance sampling), which removes the noise of
// undersampling small bright sources without blurring more than the lobe does.
// `radiance` needs mip 0 filled; its mips are rebuilt. The result has the same mip count;
// mip 0 (gloss 1, alpha 0.0028) is a copy, its lobe being narrower than a texel.
Cubemap prefilterGGX(Cubemap radiance, const PrefilterOptions& options = {});

// The reference for tests: the same integral summed over every texel of `radiance`'s mip 0
// (each split into `subdivisions`^2 parts), for direction r and GGX alpha. Exact up to the
// texel quadrature; slow.
glm::vec3 prefilteredReference(const Cubemap& radiance, glm::vec3 r, float alpha,
                               int subdivisions);

}  // namespace onelight::bake
