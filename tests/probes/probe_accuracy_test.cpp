// Environment probes: GGX prefiltering of a small bright source against brute-force
// integration of the lobe (bake/probes/prefilter.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "probe_scenes.hpp"
#include "probes/prefilter.hpp"
#include "shading.hpp"

using namespace onelight::bake;
namespace glsl = onelight::glsl;

using namespace onelight::bake::test;

// A small bright source (3 degrees, 1000 cd/m^2, on a black sky): every mip from 2 on matches
// the brute-force integral of the lobe over the sphere (the same bilinear source, sub-texels
// at most alpha / 3 across) within 1% of the mip's peak, at the default options. Mip 1's lobe
// (alpha 0.008) is narrower than its texels, so it is the source seen at that resolution.
TEST(ProbePrefilterAccuracy, BrightSourceMatchesTheIntegratedLobe) {
    Cubemap src = filled(64, brightSource);
    Cubemap c = prefilterGGX(src);
    for (int m = 2; m < c.mipCount(); ++m) {
        float alpha = glsl::ggxAlpha_fromGloss(glsl::probeGlossOfMip(m, c.mipCount()));
        int subdivisions = std::max(2, int(std::ceil(3.0f * (2.0f / 64.0f) / alpha)));
        const CubeMip& mip = c.mips[m];
        float peak = 0.0f, worst = 0.0f;
        // Texels of the +z face (and its neighbours' rims) around the source.
        for (int f : {4, 0, 2})
            for (int y = 0; y < mip.size; ++y)
                for (int x = 0; x < mip.size; ++x) {
                    glm::vec3 r = texelDirection(f, x, y, mip.size);
                    if (glm::dot(r, glm::vec3(0, 0, 1)) < 0.5f) continue;
                    float ref = prefilteredReference(src, r, alpha, subdivisions).x;
                    peak = std::max(peak, ref);
                    worst = std::max(worst, std::abs(mip.at(f, x, y).x - ref));
                }
        EXPECT_LT(worst, 0.01f * peak) << "mip " << m << " (size " << mip.size << ", alpha "
                                       << alpha << "): worst " << worst << " of peak " << peak;
    }
}
