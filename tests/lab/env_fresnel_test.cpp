// The environment "Fresnel" candidates against the integrated albedo of the runtime model.
#include <gtest/gtest.h>

#include "env_brdf.hpp"
#include "grids.hpp"
#include "shading.hpp"

using namespace onelight::lab;

namespace {

const std::vector<EnvSample>& truth() {
    static const std::vector<EnvSample> samples =
        envTruth(findModel(kRuntimeModel), checkGridMu(), checkGridGloss());
    return samples;
}

EnvError shaderFitError() {
    return envError(truth(), [](double mu, double g) {
        onelight::glsl::vec2 e = onelight::glsl::EnvBRDF_Fit(float(mu), float(g));
        return ScaleBias{e.x, e.y};
    });
}

EnvError blackOpsError() {
    return envError(truth(), [](double mu, double g) {
        onelight::glsl::vec2 e = onelight::glsl::EnvBRDF_BlackOps(float(mu), float(g));
        return ScaleBias{e.x, e.y};
    });
}

}  // namespace

// The committed shaders/env_brdf_fit.glsl keeps the accuracy it was generated with (max 2.95e-2,
// RMS 5.2e-3 in its header); 20% of slack absorbs float evaluation, nothing more.
TEST(EnvFresnel, CommittedFitKeepsItsAccuracy) {
    EnvError e = shaderFitError();
    EXPECT_LT(e.max, 3.5e-2);
    EXPECT_LT(e.rms, 6.3e-3);
}

TEST(EnvFresnel, FitIsFarBetterThanTheBlackOpsCurve) {
    EnvError fit = shaderFitError(), blackOps = blackOpsError();
    EXPECT_GT(blackOps.max, 10 * fit.max);
    EXPECT_GT(blackOps.rms, 10 * fit.rms);
}

TEST(EnvFresnel, RefittingReproducesTheCommittedFit) {
    EnvFit fit = fitEnv(envTruth(findModel(kRuntimeModel), fitGridMu(), fitGridGloss()));
    for (const EnvSample& s : truth()) {
        onelight::glsl::vec2 shader = onelight::glsl::EnvBRDF_Fit(float(s.mu), float(s.gloss));
        ScaleBias lab = fit.evaluate(s.mu, s.gloss);
        // The shader saturates to [0, 1] and rounds the coefficients to 10 digits.
        EXPECT_NEAR(shader.x, std::clamp(lab.scale, 0.0, 1.0), 1e-4) << s.mu << ' ' << s.gloss;
        EXPECT_NEAR(shader.y, std::clamp(lab.bias, 0.0, 1.0), 1e-4) << s.mu << ' ' << s.gloss;
    }
}

TEST(EnvFresnel, TablesConvergeWithResolution) {
    double previous = 1e9;
    for (int res : {8, 16, 32}) {
        SplitSumTable t = buildSplitSumTable(findModel(kRuntimeModel), res);
        EnvError e = envError(truth(), [&t](double mu, double g) { return t.sample(mu, g); });
        EXPECT_LT(e.rms, previous) << res;
        previous = e.rms;
    }
}

TEST(EnvFresnel, TableIsExactAtTexelCentres) {
    const SpecularModel& m = findModel(kRuntimeModel);
    SplitSumTable t = buildSplitSumTable(m, 8);
    ScaleBias atCentre = t.sample(2.5 / 8, 5.5 / 8), exact = specularAlbedo(m, 2.5 / 8, 5.5 / 8);
    EXPECT_NEAR(atCentre.scale, exact.scale, 1e-7);
    EXPECT_NEAR(atCentre.bias, exact.bias, 1e-7);
}
