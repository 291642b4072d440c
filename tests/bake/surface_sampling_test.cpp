// The path tracer's continuation (bake/lighting/surface_sampling.hpp) against independent
// integrals: the mean weight f cos / pdf over many draws is the surface's directional albedo,
// the diffuse albedo weighted for energy conservation (1 - the split-sum table's albedo, as
// surfaceReflectance weights it) plus the lab's adaptive quadrature of the same specular lobe
// (lab::specularAlbedo, ggx_smith); the density integrates to the probability of landing above
// the horizon; and the mixture's variance on glossy surfaces is far below cosine sampling's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "albedo.hpp"
#include "bake/lighting/radiance.hpp"
#include "bake/lighting/surface_sampling.hpp"
#include "env_brdf_table.hpp"
#include "models.hpp"
#include "shading.hpp"

namespace onelight::bake {
namespace {

Bsdf material(float albedo, float f0, float gloss) {
    return {glm::vec3(albedo), glm::vec3(f0), gloss};
}

glm::vec3 viewAt(float mu) {
    return {std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu};
}

struct Moments {
    double mean = 0.0, variance = 0.0;
};

// Mean and variance of the green weight over `n` draws from one seeded stream.
template <class Draw>
Moments moments(uint32_t n, Draw draw) {
    Rng rng{seedFrom(7, n)};
    double sum = 0.0, sum2 = 0.0;
    for (uint32_t i = 0; i < n; ++i) {
        const double w = double(draw(rng));
        sum += w;
        sum2 += w * w;
    }
    Moments m;
    m.mean = sum / n;
    m.variance = std::max(0.0, sum2 / n - m.mean * m.mean);
    return m;
}

// Tolerance: 5 standard errors of the mean (a false alarm once in ~3.5 million) plus 2e-4 for
// the float BRDF against the lab's double quadrature.
TEST(SurfaceSampling, MeanWeightIsTheDirectionalAlbedo) {
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const lab::SpecularModel& ggx = lab::findModel("ggx_smith");
    constexpr uint32_t kDraws = 400000;
    for (const float albedo : {0.0f, 0.5f})
        for (const float f0 : {0.0f, 0.04f, 0.9f})
            for (const float gloss : {0.0f, 0.5f, 0.9f, 1.0f})
                for (const float mu : {1.0f, 0.5f, 0.1f, 0.02f}) {
                    if (albedo == 0.0f && f0 == 0.0f) continue;
                    const Bsdf m = material(albedo, f0, gloss);
                    const glm::vec3 v = viewAt(mu);
                    const Moments w = moments(
                        kDraws, [&](Rng& rng) { return sampleSurface(m, n, v, rng).weight.y; });
                    const glm::vec2 env =
                        glsl::sampleEnvBrdfTable(glsl::envBrdfTableCoord(mu, gloss));
                    const double weight = std::max(0.0, 1.0 - double(f0 * env.x + env.y));
                    const double expected =
                        double(albedo) * weight + lab::specularAlbedo(ggx, mu, gloss).albedo(f0);
                    const double tolerance = 5.0 * std::sqrt(w.variance / kDraws) + 2e-4;
                    EXPECT_NEAR(w.mean, expected, tolerance) << "albedo " << albedo << " f0 " << f0
                                                             << " gloss " << gloss << " mu " << mu;
                    EXPECT_TRUE(std::isfinite(w.variance));
                }
}

// The density is normalised: its integral over the upper hemisphere (midpoint quadrature in
// (cos theta, phi), at least 8 steps across the lobe up to gloss 0.6, GGX alpha 0.034; narrower
// lobes are checked through the mean weight above) equals the chance that a draw lands above
// the horizon, counted directly.
TEST(SurfaceSampling, DensityIntegratesToTheProbabilityAboveTheHorizon) {
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    for (const float gloss : {0.3f, 0.6f})
        for (const float mu : {0.9f, 0.2f}) {
            const Bsdf m = material(0.3f, 0.04f, gloss);
            const glm::vec3 v = viewAt(mu);
            constexpr int kCos = 4000, kPhi = 720;
            double integral = 0.0;
            for (int i = 0; i < kCos; ++i)
                for (int j = 0; j < kPhi; ++j) {
                    const float c = (float(i) + 0.5f) / kCos;
                    const float s = std::sqrt(1.0f - c * c);
                    const float phi = 2.0f * glsl::PI * (float(j) + 0.5f) / kPhi;
                    integral +=
                        double(surfacePdf(m, n, v, {s * std::cos(phi), s * std::sin(phi), c}));
                }
            integral *= (1.0 / kCos) * (2.0 * M_PI / kPhi);
            Rng rng{seedFrom(3)};
            uint32_t above = 0;
            constexpr uint32_t kDraws = 200000;
            for (uint32_t i = 0; i < kDraws; ++i)
                above += glm::dot(n, sampleSurface(m, n, v, rng).direction) > 1e-6f;
            const double fraction = double(above) / kDraws;
            EXPECT_NEAR(integral, fraction,
                        5.0 * std::sqrt(fraction * (1 - fraction) / kDraws) + 2e-3)
                << "gloss " << gloss << " mu " << mu;
        }
}

// The reason for the mixture: on a glossy dielectric the weight's variance under cosine
// sampling (the old continuation) is orders of magnitude above the mixture's.
TEST(SurfaceSampling, MixtureTamesGlossyVariance) {
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const Bsdf m = material(0.2f, 0.04f, 0.8f);
    const glm::vec3 v = viewAt(0.7f);
    const Moments mixture =
        moments(200000, [&](Rng& rng) { return sampleSurface(m, n, v, rng).weight.y; });
    const Moments cosine = moments(200000, [&](Rng& rng) {
        const glm::vec3 l = sampleCosineHemisphere({rng.next(), rng.next()});
        const glsl::BrdfDots d = glsl::brdfDots(n, v, l);
        return m.albedo.y +
               (l.z > 1e-6f
                    ? glsl::PI / l.z *
                          glsl::specularLobe(glsl::RUNTIME_NDF, glsl::RUNTIME_VIS,
                                             glsl::RUNTIME_FRESNEL, m.specularColor, m.gloss, d)
                              .y
                    : 0.0f);
    });
    std::printf(
        "[ sampling ] gloss 0.8, NoV 0.7: weight mean %.4f / %.4f, variance %.3g (mixture) "
        "vs %.3g (cosine), ratio %.0f\n",
        mixture.mean, cosine.mean, mixture.variance, cosine.variance,
        cosine.variance / mixture.variance);
    EXPECT_LT(mixture.variance * 100.0, cosine.variance);
}

}  // namespace
}  // namespace onelight::bake
