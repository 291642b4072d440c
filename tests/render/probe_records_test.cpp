// The probes' influence volumes and blending order (render/probe_records.hpp) with the shared
// weight of shaders/probe.glsl: what the forward shader's per-pixel blending reads.
#include <gtest/gtest.h>

#include <cmath>

#include "render/probe_records.hpp"
#include "shading.hpp"

namespace {

using namespace onelight;

world::EnvironmentProbe probeAt(glm::vec3 p, glm::vec3 boxMin = glm::vec3(0.0f),
                                glm::vec3 boxMax = glm::vec3(0.0f)) {
    world::EnvironmentProbe e;
    e.position = p;
    e.boxMin = boxMin;
    e.boxMax = boxMax;
    return e;
}

float weight(const render::GpuProbe& g, glm::vec3 p) {
    return glsl::probeInfluenceWeight(p, glm::vec3(g.influenceMin), glm::vec3(g.influenceMax),
                                      g.influenceMin.w);
}

// The shader's blend (forward.frag probeRadiance): the first two records that reach p, c1 = w1,
// c2 = (1 - w1) w2, normalised. Returns the weight of each record.
std::vector<float> blend(const render::ProbeRecords& r, glm::vec3 p) {
    std::vector<float> c(r.records.size(), 0.0f);
    float total = 0.0f;
    int taken = 0;
    for (size_t i = 0; i < r.records.size() && taken < 2; ++i) {
        const float w = weight(r.records[i], p) * (1.0f - total);
        if (w <= 0.0f) continue;
        c[i] = w;
        total += w;
        ++taken;
    }
    for (float& x : c) x = total > 0.0f ? x / total : x;
    return c;
}

// A yard probe without a box and a room probe with one: the room (smaller volume) comes first,
// owns its inside fully beyond the band (10% of 4 m = 0.4 m), and fades into the yard probe
// across its walls.
TEST(ProbeRecords, RoomBoxOverridesTheYardAndBlendsAcrossItsWalls) {
    const std::vector<world::EnvironmentProbe> probes = {
        probeAt({0.0f, 2.0f, 0.0f}),
        probeAt({10.0f, 2.0f, 0.0f}, {8.0f, 0.0f, -5.0f}, {18.0f, 4.0f, 5.0f})};
    const render::ProbeRecords r =
        render::makeProbeRecords(probes, glm::vec3(-20.0f), glm::vec3(20.0f));
    ASSERT_EQ(r.order, (std::vector<uint32_t>{1u, 0u}));
    const render::GpuProbe& room = r.records[0];
    EXPECT_EQ(room.boxMin.w, 1.0f);  // box projection on
    EXPECT_NEAR(room.influenceMin.w, 0.4f, 1e-6f);
    EXPECT_EQ(r.records[1].boxMin.w, 0.0f);

    EXPECT_EQ(blend(r, {13.0f, 2.0f, 0.0f}), (std::vector<float>{1.0f, 0.0f}));
    // Half-way into the band the room weighs 0.5; the yard's tent (radius 10 m, to the room's
    // probe) is 1 - 8.2 / 10 there and takes (1 - 0.5) of it.
    const std::vector<float> band = blend(r, {8.2f, 2.0f, 0.0f});
    const float yard = 0.5f * (1.0f - 8.2f / 10.0f);
    EXPECT_NEAR(band[0], 0.5f / (0.5f + yard), 1e-5f);
    EXPECT_NEAR(band[1], yard / (0.5f + yard), 1e-5f);
    const std::vector<float> outside = blend(r, {7.0f, 2.0f, 0.0f});
    EXPECT_EQ(outside[0], 0.0f);
    EXPECT_NEAR(outside[1], 1.0f, 1e-6f);
}

// Two probes without boxes cross-fade: each is a tent reaching 0 at the other's capture point.
TEST(ProbeRecords, NeighboursWithoutBoxesCrossFade) {
    const std::vector<world::EnvironmentProbe> probes = {probeAt({0.0f, 1.0f, 0.0f}),
                                                         probeAt({6.0f, 1.0f, 0.0f})};
    const render::ProbeRecords r =
        render::makeProbeRecords(probes, glm::vec3(-10.0f), glm::vec3(10.0f));
    ASSERT_EQ(r.order, (std::vector<uint32_t>{0u, 1u}));  // equal volumes: index order
    EXPECT_NEAR(weight(r.records[0], {0.0f, 1.0f, 0.0f}), 1.0f, 1e-6f);
    EXPECT_NEAR(weight(r.records[0], {6.0f, 1.0f, 0.0f}), 0.0f, 1e-6f);
    EXPECT_NEAR(weight(r.records[0], {3.0f, 1.0f, 0.0f}), 0.5f, 1e-6f);
    // At a third of the way, the first tent is 2/3 and takes 2/3; the second 1/3 of the rest.
    const std::vector<float> c = blend(r, {2.0f, 1.0f, 0.0f});
    const float w1 = 2.0f / 3.0f, w2 = 1.0f / 3.0f;
    EXPECT_NEAR(c[0], w1 / (w1 + (1.0f - w1) * w2), 1e-5f);
    EXPECT_NEAR(c[0] + c[1], 1.0f, 1e-6f);
}

// A lone probe without a box lights the whole level with weight 1, and the placeholder record
// everything, even at huge coordinates, without Inf or NaN.
TEST(ProbeRecords, LoneProbeAndPlaceholderCoverEverything) {
    const render::ProbeRecords r =
        render::makeProbeRecords({probeAt({1.0f, 1.0f, 1.0f})}, glm::vec3(-50.0f, 0.0f, -30.0f),
                                 glm::vec3(40.0f, 10.0f, 60.0f));
    for (const glm::vec3 p :
         {glm::vec3(-50.0f, 0.0f, -30.0f), glm::vec3(40.0f, 10.0f, 60.0f), glm::vec3(1.0f)})
        EXPECT_EQ(weight(r.records[0], p), 1.0f);
    const render::GpuProbe placeholder = render::placeholderProbeRecord();
    for (const glm::vec3 p : {glm::vec3(0.0f), glm::vec3(1e7f, -1e7f, 3e6f)}) {
        const float w = weight(placeholder, p);
        EXPECT_TRUE(std::isfinite(w));
        EXPECT_EQ(w, 1.0f);
    }
    EXPECT_TRUE(render::makeProbeRecords({}, glm::vec3(0.0f), glm::vec3(1.0f)).records.empty());
}

// Coincident probes without boxes keep a minimum radius instead of a zero-size tent.
TEST(ProbeRecords, CoincidentProbesKeepAMinimumRadius) {
    const render::ProbeRecords r = render::makeProbeRecords(
        {probeAt(glm::vec3(2.0f)), probeAt(glm::vec3(2.0f))}, glm::vec3(0.0f), glm::vec3(4.0f));
    EXPECT_NEAR(r.records[0].influenceMin.w, render::kMinProbeRadius, 1e-6f);
    EXPECT_NEAR(weight(r.records[0], glm::vec3(2.0f)), 1.0f, 1e-6f);
}

}  // namespace
