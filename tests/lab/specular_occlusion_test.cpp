// Specular occlusion from ambient occlusion (shaders/lighting.glsl specularOcclusion: Lagarde and
// de Rousiers 2014, "Moving Frostbite to PBR", listing 26) against the model it approximates: the
// open directions above a point form a cone around the normal whose cosine-weighted solid angle
// is the AO (ao = sin^2 of the cone's half-angle), and the specular occlusion is the share of the
// runtime lobe's reflected energy, f NoL, that leaves through that cone. Integrated by the lab's
// adaptive quadrature over half vectors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "albedo.hpp"
#include "models.hpp"
#include "reflection_dots.hpp"
#include "shading.hpp"

using namespace onelight::lab;

namespace {

// The share of the lobe's f NoL inside the cone of half-angle asin(sqrt(ao)) around n.
double coneShare(double mu, double gloss, double ao) {
    using namespace onelight::glsl;
    const SpecularModel& ggx = findModel("ggx_smith");
    const double cosCone = std::sqrt(std::max(0.0, 1.0 - ao));
    const auto sums = integrateHalfVectors<2>(mu, lobeWidth(ggx, gloss), [&](const Reflection& r) {
        const BrdfDots d = dotsOf(r);
        const double lobe = double(specularLobe(NDF_GGX, VIS_SMITH_CORRELATED, FRESNEL_NONE,
                                                glm::vec3(1.0f), float(gloss), d)
                                       .x) *
                            4.0 * r.VoH;
        return Vec<2>{r.NoL >= cosCone ? lobe : 0.0, lobe};
    });
    return sums[1] > 0.0 ? sums[0] / sums[1] : 1.0;
}

}  // namespace

TEST(SpecularOcclusion, OpenIsOneAndTheTermStaysInRangeAndMonotone) {
    using namespace onelight::glsl;
    for (float gloss : {0.0f, 0.3f, 0.6f, 0.9f, 1.0f})
        for (float NoV : {MIN_NOV, 0.02f, 0.2f, 0.5f, 0.8f, 1.0f}) {
            const float alpha = ggxAlpha_fromGloss(gloss);
            EXPECT_FLOAT_EQ(specularOcclusion(NoV, 1.0f, alpha), 1.0f) << gloss << " " << NoV;
            float previous = 0.0f;
            for (float ao = 0.0f; ao <= 1.0f; ao += 0.05f) {
                const float so = specularOcclusion(NoV, ao, alpha);
                EXPECT_TRUE(std::isfinite(so) && so >= 0.0f && so <= 1.0f);
                EXPECT_GE(so, previous - 1e-6f) << "gloss " << gloss << " NoV " << NoV;
                previous = so;
            }
        }
}

// Lagarde's fit against the cone model: measured mean |error| 0.24, worst 0.88. The two agree
// where the lobe is wide; on glossy surfaces the cone makes visibility a step (the reflection is
// inside the cone or not), which Lagarde's smooth curve rounds off on both sides. Both must
// agree on the trend: glossy reflections are more occluded at grazing view than at normal view.
TEST(SpecularOcclusion, LagardesFitFollowsTheVisibilityCone) {
    using namespace onelight::glsl;
    double sum = 0.0, worst = 0.0;
    int count = 0;
    std::printf("[ spec occ ] gloss  NoV   ao   cone   Lagarde\n");
    for (double gloss : {0.0, 0.4, 0.7, 0.9})
        for (double mu : {0.1, 0.4, 0.7, 1.0})
            for (double ao : {0.2, 0.5, 0.8}) {
                const double reference = coneShare(mu, gloss, ao);
                const double fit = double(
                    specularOcclusion(float(mu), float(ao), ggxAlpha_fromGloss(float(gloss))));
                const double error = std::abs(fit - reference);
                sum += error;
                worst = std::max(worst, error);
                ++count;
                if (ao == 0.5)
                    std::printf("[ spec occ ] %.1f   %.1f   %.1f  %.3f  %.3f\n", gloss, mu, ao,
                                reference, fit);
            }
    std::printf("[ spec occ ] mean |error| %.3f, worst %.3f over %d points\n", sum / count, worst,
                count);
    EXPECT_LT(sum / count, 0.3);
    EXPECT_LT(worst, 0.95);
    for (double gloss : {0.7, 0.9}) {
        const float alpha = ggxAlpha_fromGloss(float(gloss));
        EXPECT_LT(coneShare(0.1, gloss, 0.5), coneShare(1.0, gloss, 0.5));
        EXPECT_LT(specularOcclusion(0.1f, 0.5f, alpha), specularOcclusion(1.0f, 0.5f, alpha));
    }
}
