// A footprint's bumps (shaders/material.glsl, brdf.glsl, lighting.glsl, compiled as C++): the
// bumps' share of a CLEAN lobe, the ring of the footprint's normals, the unmasked facets' lobe
// against its closed-form albedo, and the footprint's reflectance against the texel's.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "shading.hpp"

using namespace onelight::glsl;

namespace {

double alpha2(float gloss) {
    const double a = double(ggxAlpha_fromGloss(gloss));
    return a * a;
}

TEST(Footprint, ShareAndRadiusSplitCleansAlphaSquared) {
    // CLEAN: alpha^2 = alpha_b^2 + s^2. The share is s^2 / alpha^2 and the radius s.
    for (float gloss : {0.0f, 0.2f, 0.5f, 0.8f})
        for (float base : {gloss, gloss + 0.05f, 0.7f, 0.95f, 1.0f}) {
            if (base < gloss) continue;
            const double s = double(bumpSlopeRadius(gloss, base));
            const double share = double(bumpShare(gloss, base));
            EXPECT_NEAR(alpha2(base) + s * s, alpha2(gloss), 1e-6 * alpha2(gloss))
                << gloss << " " << base;
            EXPECT_NEAR(share, s * s / alpha2(gloss), 1e-6) << gloss << " " << base;
            EXPECT_GE(share, 0.0);
            EXPECT_LE(share, 1.0);
        }
    // One texel, or a base rougher than the lobe (a rounding, or a package without the base):
    // no bumps at all.
    EXPECT_EQ(bumpShare(0.6f, 0.6f), 0.0f);
    EXPECT_EQ(bumpShare(0.6f, 0.3f), 0.0f);
    EXPECT_EQ(bumpSlopeRadius(0.6f, 0.3f), 0.0f);
}

TEST(Footprint, TheRingHasTheFootprintsSecondMomentOfSlopes) {
    // Slopes of the ring's normals about n = +z: mean 0, and a second moment of radius^2 over
    // both axes, radius^2 / 2 per axis, whatever the frame's rotation about n.
    const vec3 n(0.0f, 0.0f, 1.0f);
    for (float turn : {0.0f, 0.7f, 2.0f}) {
        const vec3 t(std::cos(turn), std::sin(turn), 0.0f),
            b(-std::sin(turn), std::cos(turn), 0.0f);
        for (float radius : {0.0f, 0.05f, 0.3f, 1.5f}) {
            double sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0;
            for (int k = 0; k < FOOTPRINT_RING_COUNT; ++k) {
                const vec3 m = footprintRingNormal(n, t, b, radius, k);
                ASSERT_NEAR(double(glm::length(m)), 1.0, 1e-6);
                const double x = double(m.x / m.z), y = double(m.y / m.z);
                sx += x, sy += y, sxx += x * x, syy += y * y;
            }
            const double count = FOOTPRINT_RING_COUNT;
            EXPECT_NEAR(sx / count, 0.0, 1e-6);
            EXPECT_NEAR(sy / count, 0.0, 1e-6);
            const double r2 = double(radius) * double(radius);
            EXPECT_NEAR(sxx / count, r2 / 2.0, 1e-5 * (1.0 + r2)) << radius;
            EXPECT_NEAR(syy / count, r2 / 2.0, 1e-5 * (1.0 + r2)) << radius;
        }
    }
}

// The albedo of the facets' lobe at view v, F = 1: its f NoL over the hemisphere of light
// directions, by the midpoint rule in (cos theta, phi).
double facetsAlbedo(vec3 v, float a, int steps) {
    double sum = 0.0;
    const double dMu = 1.0 / steps, dPhi = 2.0 * std::numbers::pi / steps;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            const double mu = (i + 0.5) * dMu, phi = (j + 0.5) * dPhi;
            const double s = std::sqrt(1.0 - mu * mu);
            const vec3 l(float(s * std::cos(phi)), float(s * std::sin(phi)), float(mu));
            const BrdfDots d = brdfDots(vec3(0.0f, 0.0f, 1.0f), v, l);
            sum += double(specularFacets_Beckmann(d.NxH2, d.LoH, a)) * dMu * dPhi;
        }
    return sum;
}

TEST(Footprint, FacetsReflectWhatTheirNormalsCoverAboveTheHorizon) {
    // At normal view a facet of normal h sends the light from l = reflect(v, h) back, which is
    // above the horizon while h is within 45 degrees of n: the albedo is the Beckmann lobe's
    // share of normals there, 1 - exp(-tan^2(45) / a^2). Unmasked facets lose nothing else, so
    // it approaches 1 for a narrow spread (where a masked lobe's does too) and stays far above a
    // Smith-masked lobe's at grazing view for a wide one.
    const vec3 normal(0.0f, 0.0f, 1.0f);
    for (float a : {0.1f, 0.3f, 0.6f, 1.0f}) {
        const double expected = 1.0 - std::exp(-1.0 / (double(a) * double(a)));
        EXPECT_NEAR(facetsAlbedo(normal, a, 800), expected, 2e-3) << "alpha " << a;
    }
    // Oblique and grazing views: never more than the facets hold.
    for (float theta : {0.5f, 1.2f, 1.5f}) {
        const vec3 v(std::sin(theta), 0.0f, std::cos(theta));
        for (float a : {0.1f, 0.4f, 1.0f}) EXPECT_LE(facetsAlbedo(v, a, 600), 1.0 + 2e-3);
    }
}

TEST(Footprint, OneTexelIsTheTexelsReflectanceBitForBit) {
    const vec3 n(0.0f, 0.0f, 1.0f), v = glm::normalize(vec3(0.3f, 0.1f, 0.9f));
    const vec3 albedo(0.5f, 0.4f, 0.3f), f0(0.04f);
    const vec2 env(0.8f, 0.05f);
    for (const vec3 l :
         {glm::normalize(vec3(-0.3f, 0.0f, 0.9f)), glm::normalize(vec3(0.8f, 0.2f, 0.1f))})
        for (float gloss : {0.0f, 0.6f, 1.0f}) {
            const BrdfDots d = brdfDots(n, v, l);
            for (int materialClass : {MATERIAL_LAMBERT, MATERIAL_DIELECTRIC, MATERIAL_METAL}) {
                const vec3 one = surfaceReflectance(materialClass, DIFFUSE_LAMBERT, albedo, f0,
                                                    gloss, env, 1.0f, d);
                const vec3 footprint = footprintReflectance(
                    materialClass, DIFFUSE_LAMBERT, albedo,
                    diffuseEnergyWeight(materialClass, f0, env), f0, gloss, 0.0f, 1.0f, d);
                EXPECT_EQ(one, footprint) << materialClass << " " << gloss;
            }
        }
}

TEST(Footprint, AWholeFootprintOfBumpsIsFacetsPlusItsWeightedDiffuse) {
    const vec3 n(0.0f, 0.0f, 1.0f), v = glm::normalize(vec3(0.0f, 0.9f, 0.05f));
    const vec3 l = glm::normalize(vec3(0.0f, -0.9f, 0.3f));
    const BrdfDots d = brdfDots(n, v, l);
    const vec3 albedo(0.4f), weight(0.3f), f0(0.04f);
    const float gloss = 0.2f;
    const vec3 got = footprintReflectance(MATERIAL_DIELECTRIC, DIFFUSE_LAMBERT, albedo, weight, f0,
                                          gloss, 1.0f, 1.0f, d);
    const vec3 facets =
        F_Schlick(f0, d.LoH) * specularFacets_Beckmann(d.NxH2, d.LoH, ggxAlpha_fromGloss(gloss));
    const vec3 diffuse = albedo * weight * (Fd_Lambert() * d.NoL);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], facets[c] + diffuse[c], 1e-6f * got[c]);
    // Half and half: the mean of the texel's lobe and the facets.
    const vec3 half = footprintReflectance(MATERIAL_DIELECTRIC, DIFFUSE_LAMBERT, albedo, weight, f0,
                                           gloss, 0.5f, 1.0f, d);
    const vec3 lobe = specularLobe(NDF_GGX, VIS_SMITH_CORRELATED, FRESNEL_SCHLICK, f0, gloss, d);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(half[c], 0.5f * (lobe[c] + facets[c]) + diffuse[c], 1e-5f * half[c]);
}

TEST(Footprint, LogGammaIsStirlingsToAMillionth) {
    for (float x : {1.0f, 1.5f, 2.0f, 4.0f, 8.0f, 16.0f, 50.0f})
        EXPECT_NEAR(logGamma(x), std::lgamma(double(x)), 2e-6 * (1.0 + std::lgamma(double(x))))
            << x;
}

// Integral of D(h) cos theta_h over the hemisphere of h, by the midpoint rule in tan^2 theta
// (the slopes' own measure: d(tan^2) pi P(s) / ... is exact for a density of slopes).
double nakagamiNormalisation(float a, float m) {
    // D cos theta dw = P(tan theta) / cos^3 theta sin theta dtheta dphi; with t = tan theta,
    // dt = dtheta / cos^2 theta and sin / cos = t, so it is 2 pi P(t) t dt.
    const int steps = 200000;
    const double top = 12.0 * double(a);  // P is below 1e-20 of its peak beyond
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        const double t = (i + 0.5) * top / steps;
        const double c2 = 1.0 / (1.0 + t * t);
        const double NxH2 = 1.0 - c2;
        sum += double(D_NakagamiSlopes(float(NxH2), a, m)) * c2 * c2 * 2.0 * std::numbers::pi * t *
               (top / steps);
    }
    return sum;
}

TEST(Footprint, NakagamiSlopesAreADensityAndBeckmannsAtShapeOne) {
    for (float a : {0.05f, 0.2f, 0.5f})
        for (float m : {1.0f, 2.0f, 8.0f, 16.0f, 50.0f})
            EXPECT_NEAR(nakagamiNormalisation(a, m), 1.0, 1e-3) << "a " << a << " m " << m;
    for (float a : {0.1f, 0.4f})
        for (float NxH2 : {0.0f, 0.01f, 0.05f, 0.2f, 0.5f}) {
            const float beckmann = D_Beckmann(NxH2, a);
            EXPECT_NEAR(D_NakagamiSlopes(NxH2, a, 1.0f), beckmann, 1e-4f * (1.0f + beckmann));
        }
    // A ring: nothing at the mean normal, its density where the slope is a.
    EXPECT_LT(D_NakagamiSlopes(1e-6f, 0.3f, 16.0f), 1e-12f);
}

TEST(Footprint, FacetShareOfGaussianSlopesFollowsTheKurtosis) {
    const float ring = (FACET_RING_SHAPE + 1.0f) / FACET_RING_SHAPE;
    // Bumps alone (no texel lobe): Gaussian slopes are all Gaussian, a ring none, between
    // linear in the kurtosis; more peaked than a Gaussian, shaded as one.
    EXPECT_FLOAT_EQ(facetGaussianShare_fromKurtosis(2.0f, 0.1f, 0.0f), 1.0f);
    EXPECT_FLOAT_EQ(facetGaussianShare_fromKurtosis(ring, 0.1f, 0.0f), 0.0f);
    EXPECT_FLOAT_EQ(facetGaussianShare_fromKurtosis(1.0f, 0.1f, 0.0f), 0.0f);
    EXPECT_NEAR(facetGaussianShare_fromKurtosis(1.25f, 0.1f, 0.0f), (1.25f - ring) / (2.0f - ring),
                1e-6f);
    EXPECT_FLOAT_EQ(facetGaussianShare_fromKurtosis(3.0f, 0.1f, 0.0f), 1.0f);
    // The texels' own lobes blur the ring: with as much variance as the bumps, a ring's
    // kurtosis (1 s2^2 + 4 s2 b2 + 2 b2^2) / (2 s2)^2 = 7/4.
    EXPECT_NEAR(facetGaussianShare_fromKurtosis(1.0f, 0.1f, 0.1f), (1.75f - ring) / (2.0f - ring),
                1e-6f);
    EXPECT_FLOAT_EQ(facetGaussianShare_fromKurtosis(1.0f, 0.0f, 0.0f), 1.0f);
}

TEST(Footprint, TheCentreAndRingHaveTheSlopesSecondAndFourthMoments) {
    for (float k : {1.0f, 1.25f, 2.0f, 3.0f}) {
        const double s = 0.3;
        const double w = footprintCentreWeight(k), r = footprintRingRadius(float(s), k);
        EXPECT_NEAR((1.0 - w) * r * r, s * s, 1e-6) << k;
        EXPECT_NEAR((1.0 - w) * r * r * r * r, double(k) * s * s * s * s, 1e-6) << k;
    }
    EXPECT_EQ(footprintCentreWeight(1.0f), 0.0f);  // a ring alone: the footprint as before
}

// Whether point p (in the texture's coordinates, about the footprint's centre) lies in part i's
// own parallelogram: its centre plus du, dv each scaled by the part's share of that axis.
bool inPart(const FootprintParts& parts, int i, vec2 p, vec2 du, vec2 dv, float shareU,
            float shareV) {
    const vec2 q = p - parts.offsets[i];
    // Coordinates of q along du, dv (the footprint's axes are independent, det != 0).
    const float det = du.x * dv.y - du.y * dv.x;
    const float a = (q.x * dv.y - q.y * dv.x) / det, b = (du.x * q.y - du.y * q.x) / det;
    return std::abs(a) <= 0.5f * shareU + 1e-5f && std::abs(b) <= 0.5f * shareV + 1e-5f;
}

TEST(Footprint, PartsTileTheFootprintOnceEach) {
    // A square footprint of 8 texels splits two by two; one of 16 by 3 texels (its long axis
    // across the screen or down it) splits into four along the long axis. Every point of the
    // footprint lies in exactly one part, the parts' centres average to the footprint's, and a
    // part's level of detail is log2 of its longer side in texels.
    const vec2 texels(64.0f, 32.0f);
    struct Case {
        vec2 du, dv;
        float shareU, shareV, lod;
    };
    const float turn = 0.6f;
    const vec2 along(std::cos(turn), std::sin(turn)), across(-std::sin(turn), std::cos(turn));
    const Case cases[] = {
        {vec2(8.0f / 64.0f, 0.0f), vec2(0.0f, 8.0f / 32.0f), 0.5f, 0.5f, 2.0f},
        {along * 16.0f / texels, across * 3.0f / texels, 0.25f, 1.0f, 2.0f},
        {across * 3.0f / texels, along * 16.0f / texels, 1.0f, 0.25f, 2.0f},
        {along * 12.0f / texels, across * 5.0f / texels, 0.25f, 1.0f, std::log2(5.0f)},
    };
    for (const Case& c : cases) {
        const vec2 du = c.du * texels, dv = c.dv * texels;  // in texels, to test in
        const FootprintParts parts = footprintParts(c.du, c.dv, texels);
        ASSERT_TRUE(parts.split);
        EXPECT_NEAR(double(parts.lod), double(c.lod), 1e-5);
        FootprintParts inTexels = parts;
        vec2 sum(0.0f);
        for (int i = 0; i < FOOTPRINT_PARTS; ++i) {
            inTexels.offsets[i] = parts.offsets[i] * texels;
            sum += inTexels.offsets[i];
        }
        EXPECT_NEAR(double(glm::length(sum)), 0.0, 1e-4);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                // The centres of a 16 x 16 grid: none on a border between halves or quarters.
                const vec2 p = du * ((float(x) + 0.5f) / 16.0f - 0.5f) +
                               dv * ((float(y) + 0.5f) / 16.0f - 0.5f);
                int in = 0;
                for (int i = 0; i < FOOTPRINT_PARTS; ++i)
                    in += inPart(inTexels, i, p, du, dv, c.shareU, c.shareV) ? 1 : 0;
                EXPECT_EQ(in, 1) << x << " " << y;
            }
    }
}

TEST(Footprint, AFootprintWithinATexelIsNotSplit) {
    const vec2 texels(256.0f, 256.0f);
    EXPECT_FALSE(
        footprintParts(vec2(0.9f, 0.0f) / texels, vec2(0.0f, 0.5f) / texels, texels).split);
    EXPECT_FALSE(footprintParts(vec2(0.0f), vec2(0.0f), texels).split);
    // A NaN or infinite derivative (a degenerate triangle's) does not split either.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(footprintParts(vec2(nan, 0.0f), vec2(0.0f, 0.01f), texels).split);
    EXPECT_FALSE(footprintParts(vec2(inf, 0.0f), vec2(0.0f, 0.01f), texels).split);
    EXPECT_TRUE(footprintParts(vec2(1.5f, 0.0f) / texels, vec2(0.0f), texels).split);
}

}  // namespace
