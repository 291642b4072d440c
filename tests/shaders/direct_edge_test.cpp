// A baked direct light's shadow edge as a distance field (shaders/lighting.glsl directEdgeFactor,
// compiled as C++): the four texels around a point hold a straight edge's signed distance and
// their visibility (the edge's low or high level: none and all of one light, or with a second
// light over both sides), their direct light the unshadowed light times it; filtered bilinearly
// as the GPU does, the factor turns the filtered light into the light of the lit side on one
// side of the line and of the dark side on the other, the line itself half way, wherever it
// crosses the cell. Without an edge the factor is 1 (the bilinear visibility), and no input
// the package may hold gives a NaN or an infinity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "shading.hpp"

using namespace onelight::glsl;

namespace {

struct Corner {
    float visibility, distance, light;
};

float bilinear(const Corner c[4], float u, float v, float Corner::*field) {
    return (1.0f - u) * (1.0f - v) * c[0].*field + u * (1.0f - v) * c[1].*field +
           (1.0f - u) * v * c[2].*field + u * v * c[3].*field;
}

void expectStraightEdge(float low, float high) {
    constexpr float kOpen = 800.0f;  // lux, the unshadowed light: the same at the four texels
    constexpr float kWidth = 0.05f;  // texels
    for (const float angle : {0.2f, 0.7f, 1.3f, 2.5f}) {
        for (const float offset : {0.15f, 0.4f, 0.5f, 0.8f}) {
            // The edge: points p of the cell [0,1]^2 with dot(p, n) = offset + dot((0.5,0.5), n)
            // - 0.5; lit where dot(p, n) is larger.
            const vec2 n(std::cos(angle), std::sin(angle));
            const float c = offset - 0.5f + 0.5f * (n.x + n.y);
            const auto signedDistance = [&](float x, float y) { return x * n.x + y * n.y - c; };
            Corner corners[4];
            const vec2 at[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
            for (int k = 0; k < 4; ++k) {
                const float s = signedDistance(at[k].x, at[k].y);
                const float v = s >= 0.0f ? high : low;
                corners[k] = {v, s, kOpen * v};
            }
            for (int i = 0; i <= 20; ++i)
                for (int j = 0; j <= 20; ++j) {
                    const float u = float(i) / 20.0f, v = float(j) / 20.0f;
                    const float visibility = bilinear(corners, u, v, &Corner::visibility);
                    const float s = bilinear(corners, u, v, &Corner::distance);
                    const float light = bilinear(corners, u, v, &Corner::light);
                    const float drawn =
                        directEdgeFactor(visibility, s / kWidth, 0.0f, low, high) * light;
                    ASSERT_TRUE(std::isfinite(drawn));
                    const float exact = signedDistance(u, v);
                    if (visibility <= 0.0f) continue;  // no texel's light to draw from
                    const float ramp = std::clamp(0.5f + exact / kWidth, 0.0f, 1.0f);
                    EXPECT_NEAR(drawn, kOpen * (low + (high - low) * ramp), 1e-3f * kOpen)
                        << u << ", " << v;
                }
        }
    }
}

TEST(DirectEdge, TheFieldDrawsAStraightEdgeAcrossItsCellWhereTheDistanceIsZero) {
    expectStraightEdge(0.0f, 1.0f);
}

TEST(DirectEdge, AnEdgeBetweenTwoLevelsKeepsBoth) {
    expectStraightEdge(0.3f, 0.9f);
}

TEST(DirectEdge, WithoutAnEdgeTheTexelsVisibilityStays) {
    // No edge drawn: both levels the texel's visibility.
    for (const float visibility : {1e-3f, 0.3f, 1.0f})
        for (const float s : {-16.0f, 0.0f, 1.0f})
            EXPECT_FLOAT_EQ(directEdgeFactor(visibility, s, 0.5f, visibility, visibility), 1.0f);
}

TEST(DirectEdge, APixelWiderThanThePenumbraWidensTheRamp) {
    // Half way through a ramp of one penumbra, a quarter through one of two (pixels).
    EXPECT_FLOAT_EQ(directEdgeFactor(1.0f, 0.25f, 0.0f, 0.0f, 1.0f), 0.75f);
    EXPECT_FLOAT_EQ(directEdgeFactor(1.0f, 0.25f, 2.0f, 0.0f, 1.0f), 0.625f);
}

TEST(DirectEdge, NoInputGivesANaNOrAnInfinity) {
    const float visibilities[] = {0.0f, 1e-30f, 1e-5f, 0.5f, 1.0f};
    const float distances[] = {-16.0f, 0.0f, 16.0f};
    const float steps[] = {0.0f, 1e-30f, 1.0f, 1e30f};
    for (const float v : visibilities)
        for (const float s : distances)
            for (const float p : steps) {
                const float g = directEdgeFactor(v, s, p, 0.0f, v);
                EXPECT_TRUE(std::isfinite(g) && g >= 0.0f) << v << " " << s << " " << p;
            }
}

}  // namespace
