// normal_withValidReflection (shaders/material.glsl, compiled as C++): a mapped normal whose
// mirror reflection of the view would leave below the surface is bent just enough that it stays
// a little above, the rest are kept, and no input gives a non-finite or non-unit normal.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shading.hpp"

using namespace onelight::glsl;

namespace {

const vec3 kUp(0.0f, 0.0f, 1.0f);

vec3 reflectView(vec3 n, vec3 v) {
    return n * (2.0f * glm::dot(n, v)) - v;
}

vec3 fromAngles(float theta, float phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// The lift the function keeps the reflection above the plane by (Cycles' threshold).
float liftFor(vec3 v) {
    return std::min(0.9f * glm::dot(kUp, v), 0.01f);
}

TEST(ValidReflection, ANormalWhoseReflectionStaysAboveIsKeptBitForBit) {
    const vec3 v = fromAngles(0.6f, 0.3f);
    for (const vec3 n : {kUp, fromAngles(0.3f, 2.0f), fromAngles(0.2f, 0.3f)}) {
        ASSERT_GE(glm::dot(reflectView(n, v), kUp), liftFor(v));
        const vec3 out = normal_withValidReflection(n, kUp, v);
        EXPECT_EQ(out.x, n.x);
        EXPECT_EQ(out.y, n.y);
        EXPECT_EQ(out.z, n.z);
    }
}

// Bumps tilted up to 60 degrees, seen from 0.5 to 89.5 degrees off the surface normal: wherever
// the reflection went below the plane, the bent normal is unit, faces the view, reflects the view
// to exactly the lift above the plane, and keeps the reflection's side (its direction along the
// plane), so a highlight moves towards the horizon rather than elsewhere.
TEST(ValidReflection, TheBentNormalReflectsTheViewJustAboveTheSurfaceOnItsOwnSide) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int bent = 0;
    for (int i = 0; i < 20000; ++i) {
        const vec3 v = fromAngles(glm::radians(0.5f + 89.0f * u(rng)), 6.2831853f * u(rng));
        const vec3 n = fromAngles(glm::radians(60.0f * u(rng)), 6.2831853f * u(rng));
        const vec3 r = reflectView(n, v);
        const float lift = liftFor(v);
        if (glm::dot(r, kUp) >= lift) continue;
        ++bent;
        const vec3 out = normal_withValidReflection(n, kUp, v);
        ASSERT_NEAR(glm::length(out), 1.0f, 1e-5f);
        EXPECT_GT(glm::dot(out, v), 0.0f);
        const vec3 r2 = reflectView(out, v);
        EXPECT_NEAR(glm::dot(r2, kUp), lift, 2e-4f) << "view " << v.z << ", normal " << n.z;
        const glm::vec2 side(r.x, r.y), side2(r2.x, r2.y);
        if (glm::length(side) > 1e-3f) {
            EXPECT_GT(glm::dot(glm::normalize(side), glm::normalize(side2)), 1.0f - 1e-4f);
        }
    }
    EXPECT_GT(bent, 2000);  // the case is common, not an edge
}

// Across the threshold the normal changes continuously: a bump rotated through the angle where
// its reflection reaches the lift gives normals 1e-4 radians apart on either side.
TEST(ValidReflection, ContinuousWhereTheReflectionMeetsTheLift) {
    const vec3 v = fromAngles(glm::radians(70.0f), 0.0f);
    const float lift = liftFor(v);
    // Find the tilt (away from the view, about y) at which the reflection's height is the lift.
    float lo = 0.0f, hi = 1.5f;
    for (int k = 0; k < 60; ++k) {
        const float mid = 0.5f * (lo + hi);
        const vec3 n = fromAngles(mid, 3.14159265f);
        (glm::dot(reflectView(n, v), kUp) > lift ? lo : hi) = mid;
    }
    const vec3 before = normal_withValidReflection(fromAngles(lo - 1e-4f, 3.14159265f), kUp, v);
    const vec3 after = normal_withValidReflection(fromAngles(hi + 1e-4f, 3.14159265f), kUp, v);
    EXPECT_LT(glm::length(before - after), 5e-4f);
}

TEST(ValidReflection, DegenerateViewsAndNormalsGiveAFiniteUnitNormal) {
    const vec3 views[] = {kUp, fromAngles(glm::radians(90.0f), 0.0f),
                          fromAngles(glm::radians(90.0f) - 1e-7f, 1.0f),
                          fromAngles(glm::radians(100.0f), 2.0f), -kUp};
    const vec3 normals[] = {kUp, -kUp, fromAngles(glm::radians(89.9f), 3.0f),
                            fromAngles(glm::radians(45.0f), 0.0f), vec3(1.0f, 0.0f, 0.0f)};
    for (const vec3& v : views)
        for (const vec3& n : normals) {
            const vec3 out = normal_withValidReflection(n, kUp, v);
            ASSERT_TRUE(std::isfinite(out.x) && std::isfinite(out.y) && std::isfinite(out.z));
            EXPECT_NEAR(glm::length(out), 1.0f, 1e-4f)
                << "v (" << v.x << ", " << v.y << ", " << v.z << "), n (" << n.x << ", " << n.y
                << ", " << n.z << ")";
        }
}

}  // namespace
