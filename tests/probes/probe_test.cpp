// Environment probes: cube addressing, GGX prefiltering against brute-force integration,
// seams, box projection (shaders/probe.glsl, bake/probes).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "probe_scenes.hpp"
#include "probes/prefilter.hpp"
#include "shading.hpp"

using namespace onelight::bake;
namespace glsl = onelight::glsl;

using namespace onelight::bake::test;

TEST(ProbeCube, AddressingRoundTripsAndSolidAnglesSumToTheSphere) {
    std::mt19937 rng(5);
    std::normal_distribution<float> g;
    for (int i = 0; i < 100000; ++i) {
        glm::vec3 d = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
        int face = glsl::cubeFace(d);
        glm::vec2 uv = glsl::cubeFaceUV(d, face);
        ASSERT_GE(uv.x, 0.0f);
        ASSERT_LE(uv.x, 1.0f);
        glm::vec3 back = glsl::cubeDirection(face, uv);
        ASSERT_LT(glm::length(back - d), 1e-5f) << i;
    }
    for (int size : {1, 4, 32}) {
        double total = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) total += 6.0 * double(texelSolidAngle(x, y, size));
        EXPECT_NEAR(total, 4.0 * M_PI, 1e-4) << size;
    }
}

TEST(ProbeCube, GlossAndMipMapOneToOne) {
    for (int count : {1, 5, 8})
        for (int m = 0; m < count; ++m)
            EXPECT_FLOAT_EQ(glsl::probeMipOfGloss(glsl::probeGlossOfMip(m, count), count),
                            float(m));
    EXPECT_FLOAT_EQ(glsl::probeGlossOfMip(0, 8), 1.0f);
    EXPECT_FLOAT_EQ(glsl::probeGlossOfMip(7, 8), 0.0f);
}

// White furnace: a uniform environment stays uniform at every mip.
TEST(ProbePrefilter, UniformEnvironmentIsPreservedAtEveryMip) {
    Cubemap c = prefilterGGX(filled(32, [](glm::vec3) { return glm::vec3(3.0f); }), {64, 64});
    for (const CubeMip& m : c.mips)
        for (const glm::vec3& t : m.texels) ASSERT_NEAR(t.y, 3.0f, 3.0f * 0.005f) << m.size;
}

// More samples converge on the integral: the error shrinks as the count grows.
TEST(ProbePrefilter, ImportanceSamplingConverges) {
    Cubemap src = filled(32, brightSource);
    int m = 2;
    double previous = 1e30;
    for (int samples : {8, 64, 512}) {
        Cubemap c = prefilterGGX(src, {samples, samples});  // exactly `samples` per texel
        float alpha = glsl::ggxAlpha_fromGloss(glsl::probeGlossOfMip(m, c.mipCount()));
        double error = 0;
        const CubeMip& mip = c.mips[m];
        for (int y = 0; y < mip.size; ++y)
            for (int x = 0; x < mip.size; ++x) {
                glm::vec3 r = texelDirection(4, x, y, mip.size);
                error +=
                    double(std::abs(mip.at(4, x, y).x - prefilteredReference(src, r, alpha, 1).x));
            }
        EXPECT_LT(error, previous) << samples;
        previous = error;
    }
}

// No seams: across face edges neighbouring texels differ no more than inside a face (5% slack:
// texel centres across an edge are a little farther apart than inside a face).
TEST(ProbePrefilter, FaceEdgesShowNoSeams) {
    Cubemap c = prefilterGGX(filled(32, smoothSky), {128, 128});
    for (int m = 0; m < c.mipCount() - 1; ++m) {
        const CubeMip& mip = c.mips[m];
        float inside = 0.0f, across = 0.0f;
        for (int f = 0; f < 6; ++f)
            for (int y = 0; y < mip.size; ++y)
                for (int x = 0; x < mip.size; ++x) {
                    glm::vec3 v = mip.at(f, x, y);
                    for (TexelRef n : {neighbourTexel(f, x + 1, y, mip.size),
                                       neighbourTexel(f, x, y + 1, mip.size)}) {
                        float d = maxComponent(glm::abs(v - mip.at(n.face, n.x, n.y)));
                        (n.face == f ? inside : across) =
                            std::max(n.face == f ? inside : across, d);
                    }
                }
        EXPECT_LE(across, inside * 1.05f + 1e-6f) << "mip " << m << " size " << mip.size;
    }
}

// A marked point on the wall of a probe's box: the reflection that hits it reads the cube in
// the direction of that point from the capture position.
TEST(ProbeBoxProjection, ReflectionLandsOnTheMarkedWallPoint) {
    glm::vec3 boxMin(-4, 0, -3), boxMax(6, 3, 5), probe(1, 1.5f, 0);
    glm::vec3 marked(6.0f, 2.0f, 1.0f);  // on the +x wall
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 1000; ++i) {
        glm::vec3 P = boxMin + (boxMax - boxMin) * glm::vec3(u(rng), u(rng), u(rng)) * 0.9f +
                      (boxMax - boxMin) * 0.05f;
        glm::vec3 R = glm::normalize(marked - P);
        glm::vec3 d = glsl::boxProjectedDirection(P, R, boxMin, boxMax, probe);
        ASSERT_LT(glm::length(d - (marked - probe)), 1e-4f) << i;
    }
    // Axis-aligned rays never produce Inf or NaN.
    glm::vec3 d = glsl::boxProjectedDirection(probe, glm::vec3(0, 0, 1), boxMin, boxMax, probe);
    EXPECT_TRUE(std::isfinite(d.x) && std::isfinite(d.y));
    EXPECT_NEAR(d.z, 5.0f, 1e-5f);
}
