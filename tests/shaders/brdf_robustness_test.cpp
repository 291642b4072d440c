// Hard cases of the shared BRDF (shaders/brdf.glsl compiled as C++): every piece is finite and
// non-negative for any input the shaders can produce, the dot products are robust to
// degenerate geometry, and the BRDFs are reciprocal.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "shading.hpp"

using namespace onelight::glsl;

namespace {

struct Model {
    const char* name;
    int ndf, vis;
};
const Model kModels[] = {{"bp_none", NDF_BLINN_PHONG, VIS_NONE},
                         {"bp_kelemen", NDF_BLINN_PHONG, VIS_KELEMEN},
                         {"bp_schlick", NDF_BLINN_PHONG, VIS_SCHLICK_SMITH},
                         {"beck_smith", NDF_BECKMANN, VIS_SMITH_CORRELATED},
                         {"ggx_smith", NDF_GGX, VIS_SMITH_CORRELATED}};

const float kDenormal = 1e-40f;
const std::vector<float> kSpecialDots = {0.0f, kDenormal, 1e-7f, 1e-4f, 0.5f, 1.0f - 1e-7f, 1.0f};
const std::vector<float> kSpecialGloss = {0.0f, kDenormal, 1e-4f, 0.5f, 0.9999f, 1.0f};

bool finiteNonNegative(float x) {
    return std::isfinite(x) && x >= 0.0f;
}

// Evaluates every piece at (dots, params); reports the first bad one.
void expectAllPiecesFinite(vec4 dots, vec4 params) {
    for (int p = 0; p < BRDF_PIECE_COUNT; ++p) {
        float v = brdfPiece(p, dots, params);
        ASSERT_TRUE(finiteNonNegative(v))
            << "piece " << p << " = " << v << " at dots (" << dots.x << ", " << dots.y << ", "
            << dots.z << ", " << dots.w << ") gloss " << params.x << " f0 " << params.y;
    }
}

}  // namespace

TEST(BrdfRobustness, SpecialValuesGiveFiniteNonNegativePieces) {
    for (float NoV : kSpecialDots)
        for (float NoL : kSpecialDots)
            for (float LoH : kSpecialDots)
                for (float NxH2 : kSpecialDots)
                    for (float g : kSpecialGloss)
                        for (float f0 : {0.0f, 0.04f, 1.0f})
                            expectAllPiecesFinite(vec4(NoV, NoL, LoH, NxH2), vec4(g, f0, 0, 0));
}

TEST(BrdfRobustness, MillionAdversarialInputsGiveFiniteNonNegativePieces) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uniform_int_distribution<int> pick(0, int(kSpecialDots.size()) - 1);
    // Each coordinate is either special, uniform, or log-uniform down to denormals.
    auto draw = [&]() {
        switch (rng() % 3) {
            case 0:
                return kSpecialDots[pick(rng)];
            case 1:
                return unit(rng);
            default:
                return std::min(1.0f, std::exp2(-140.0f * unit(rng)));
        }
    };
    const int kInputs = 1000000 / BRDF_PIECE_COUNT + 1;  // >= 10^6 piece evaluations
    for (int i = 0; i < kInputs; ++i)
        expectAllPiecesFinite(vec4(draw(), draw(), draw(), draw()), vec4(draw(), draw(), 0, 0));
}

TEST(BrdfRobustness, DotsAreRobustToDegenerateGeometry) {
    const vec3 n(0, 0, 1);
    const float s = std::sqrt(0.5f);
    struct Case {
        const char* what;
        vec3 v, l;
    } cases[] = {
        {"l = v", vec3(s, 0, s), vec3(s, 0, s)},
        {"l = -v", vec3(s, 0, s), vec3(-s, 0, -s)},
        {"l = -v grazing", vec3(1, 0, 0), vec3(-1, 0, 0)},
        {"l below the horizon", vec3(0, 0, 1), vec3(s, 0, -s)},
        {"v below the horizon", vec3(s, 0, -s), vec3(0, 0, 1)},
        {"h exactly n", vec3(s, 0, s), vec3(-s, 0, s)},
        {"both at normal", vec3(0, 0, 1), vec3(0, 0, 1)},
        {"both grazing opposite", vec3(1, 0, 0), vec3(-1, 0, 1e-7f)},
        {"denormal tilt", vec3(kDenormal, 0, 1), vec3(-kDenormal, 0, 1)},
    };
    for (const Case& c : cases) {
        BrdfDots d = brdfDots(n, c.v, c.l);
        for (float x : {d.NoV, d.NoL, d.LoH, d.NxH2}) {
            ASSERT_TRUE(std::isfinite(x)) << c.what;
            ASSERT_GE(x, 0.0f) << c.what;
            ASSERT_LE(x, 1.0f) << c.what;
        }
        ASSERT_GE(d.NoV, MIN_NOV) << c.what;
        for (const Model& m : kModels)
            for (float g : kSpecialGloss) {
                vec3 f = specularLobe(m.ndf, m.vis, FRESNEL_SCHLICK, vec3(0.04f), g, d);
                ASSERT_TRUE(finiteNonNegative(f.x)) << c.what << ' ' << m.name << " gloss " << g;
            }
    }
    // The exact values where they are known.
    BrdfDots hn = brdfDots(n, vec3(s, 0, s), vec3(-s, 0, s));
    EXPECT_EQ(hn.NxH2, 0.0f);
    EXPECT_NEAR(hn.LoH, s, 1e-6f);
    // Exactly opposite (representable) directions: h is undefined, LoH and NoL are 0.
    BrdfDots opposite = brdfDots(n, vec3(1, 0, 0), vec3(-1, 0, 0));
    EXPECT_EQ(opposite.NoL, 0.0f);
    EXPECT_EQ(opposite.LoH, 0.0f);
    // Opposite up to rounding of the unit vectors (1 + VoL ~ 1e-7): LoH = sqrt((1 + VoL) / 2).
    EXPECT_LT(brdfDots(n, vec3(s, 0, s), vec3(-s, 0, -s)).LoH, 1e-3f);
}

TEST(BrdfRobustness, SpecularLobeIsReciprocal) {
    std::mt19937 rng(77);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto direction = [&]() {
        float c = 0.01f + 0.99f * unit(rng), phi = 6.2831853f * unit(rng);
        float s = std::sqrt(1.0f - c * c);
        return vec3(s * std::cos(phi), s * std::sin(phi), c);
    };
    const vec3 n(0, 0, 1);
    for (int i = 0; i < 20000; ++i) {
        vec3 v = direction(), l = direction();
        float g = unit(rng);
        BrdfDots a = brdfDots(n, v, l), b = brdfDots(n, l, v);
        for (const Model& m : kModels) {
            // f = lobe / NoL must not depend on which direction is the light.
            double fa = specularLobe(m.ndf, m.vis, FRESNEL_SCHLICK, vec3(0.04f), g, a).x / a.NoL;
            double fb = specularLobe(m.ndf, m.vis, FRESNEL_SCHLICK, vec3(0.04f), g, b).x / b.NoL;
            ASSERT_NEAR(fa, fb, 2e-5 * std::max(std::abs(fa), 1e-3))
                << m.name << " gloss " << g << " NoV " << a.NoV << " NoL " << a.NoL;
        }
    }
}
