// The probes' influence volumes and blending order (render/probe_records.hpp) with the shared
// weight of shaders/probe.glsl: what the forward shader's per-pixel blending reads.
#include <gtest/gtest.h>

#include <algorithm>
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

// The shader's blend (forward_shading.glsl probeRadiance): the first two records that reach p, c1 =
// w1, c2 = (1 - w1) w2, normalised. Returns the weight of each record.
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

// The shader's choice (forward_shading.glsl probeRadiance) over candidate lists: the blend weight
// of each record, and the record captured nearest to p (used when no influence reaches p).
struct Choice {
    std::vector<float> weights;
    uint32_t nearest = 0;
};

Choice choose(const std::vector<render::GpuProbe>& records, glm::vec3 p,
              const std::vector<uint32_t>& influence, const std::vector<uint32_t>& nearest) {
    Choice c;
    c.weights.assign(records.size(), 0.0f);
    float total = 0.0f;
    int taken = 0;
    for (size_t k = 0; k < influence.size() && taken < 2; ++k) {
        const float w = weight(records[influence[k]], p) * (1.0f - total);
        if (w <= 0.0f) continue;
        c.weights[influence[k]] = w;
        total += w;
        ++taken;
    }
    for (float& x : c.weights) x = total > 0.0f ? x / total : x;
    float best = 1e30f;
    for (uint32_t i : nearest) {
        const glm::vec3 d = p - glm::vec3(records[i].position);
        if (glm::dot(d, d) < best) {
            best = glm::dot(d, d);
            c.nearest = i;
        }
    }
    return c;
}

// The lists the shader walks at p: its cell's, or every record outside the grid.
void cellLists(const render::ProbeCells& cells, size_t recordCount, glm::vec3 p,
               std::vector<uint32_t>& influence, std::vector<uint32_t>& nearest) {
    influence.clear();
    nearest.clear();
    const uint32_t cell = render::probeCellOf(cells.grid, p);
    if (cell == render::kNoIndex) {
        for (uint32_t i = 0; i < recordCount; ++i) influence.push_back(i), nearest.push_back(i);
        return;
    }
    const uint32_t first = cells.words.at(2 * cell), counts = cells.words.at(2 * cell + 1);
    for (uint32_t k = 0; k < (counts & 0xFFFFu); ++k)
        influence.push_back(cells.words.at(first + k));
    for (uint32_t k = 0; k < (counts >> 16); ++k)
        nearest.push_back(cells.words.at(first + (counts & 0xFFFFu) + k));
}

// 65 probes over a 60 m yard (an automatic placement's 8 x 8 lattice plus one), two boxed
// rooms, and points everywhere, on cell faces and outside the grid: walking a point's cell
// picks exactly the blend and the nearest probe that walking every record picks, while a cell
// lists a handful of the 67 records.
TEST(ProbeCells, ACellsListsPickWhatWalkingEveryRecordPicks) {
    std::vector<world::EnvironmentProbe> probes;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            probes.push_back(probeAt({-26.0f + 7.5f * x + 0.3f * float((x * 7 + y) % 3),
                                      -26.0f + 7.5f * y, 1.5f + 0.2f * float(x % 2)}));
    probes.push_back(probeAt({0.5f, 0.5f, 1.0f}));
    probes.push_back(probeAt({10.0f, 10.0f, 2.0f}, {6.0f, 6.0f, 0.0f}, {14.0f, 16.0f, 4.0f}));
    probes.push_back(probeAt({-12.0f, 3.0f, 2.0f}, {-16.0f, 0.0f, 0.0f}, {-8.0f, 6.0f, 3.0f}));
    const glm::vec3 levelMin(-30.0f, -30.0f, 0.0f), levelMax(30.0f, 30.0f, 6.0f);
    const render::ProbeRecords r = render::makeProbeRecords(probes, levelMin, levelMax);
    const render::ProbeCells cells = render::makeProbeCells(r.records, levelMin, levelMax);
    ASSERT_EQ(cells.grid.dims.w, 1u);

    std::vector<uint32_t> all(r.records.size());
    for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    std::vector<uint32_t> influence, nearest;
    uint32_t seed = 12345u, outside = 0, onFaces = 0, listed = 0;
    auto next = [&seed]() {
        seed = seed * 1664525u + 1013904223u;
        return float(seed >> 8) / float(1u << 24);
    };
    const float cell = cells.grid.cellSize.x;
    for (int n = 0; n < 40000; ++n) {
        glm::vec3 p = glm::mix(levelMin - 8.0f, levelMax + 8.0f, glm::vec3(next(), next(), next()));
        if (n % 4 == 0) {  // on a cell face: rounding may put it in either neighbour
            p.x = cells.grid.origin.x + cell * std::round((p.x - cells.grid.origin.x) / cell);
            ++onFaces;
        }
        cellLists(cells, r.records.size(), p, influence, nearest);
        if (render::probeCellOf(cells.grid, p) == render::kNoIndex) ++outside;
        listed += uint32_t(influence.size() + nearest.size());
        const Choice expected = choose(r.records, p, all, all);
        const Choice got = choose(r.records, p, influence, nearest);
        ASSERT_EQ(got.weights, expected.weights) << "at " << p.x << " " << p.y << " " << p.z;
        if (*std::max_element(expected.weights.begin(), expected.weights.end()) == 0.0f) {
            ASSERT_EQ(got.nearest, expected.nearest) << "at " << p.x << " " << p.y << " " << p.z;
        }
    }
    EXPECT_GT(outside, 1000u);
    EXPECT_GT(onFaces, 1000u);
    // Inside the grid a point walks about 8 list entries instead of 2 x 67.
    EXPECT_LT(double(listed - outside * 2 * r.records.size()) / double(40000 - outside), 16.0);
}

// Few records, an empty level and a level of zero extent get no grid: every record is walked.
TEST(ProbeCells, FewRecordsOrNoExtentGetNoGrid) {
    const render::ProbeRecords few =
        render::makeProbeRecords({probeAt({0.0f, 0.0f, 0.0f}), probeAt({4.0f, 0.0f, 0.0f})},
                                 glm::vec3(-5.0f), glm::vec3(5.0f));
    EXPECT_EQ(render::makeProbeCells(few.records, glm::vec3(-5.0f), glm::vec3(5.0f)).grid.dims.w,
              0u);
    std::vector<world::EnvironmentProbe> many;
    for (int i = 0; i < 8; ++i) many.push_back(probeAt({float(i), 0.0f, 0.0f}));
    const render::ProbeRecords r = render::makeProbeRecords(many, glm::vec3(0.0f), glm::vec3(0.0f));
    const render::ProbeCells none =
        render::makeProbeCells(r.records, glm::vec3(0.0f), glm::vec3(0.0f));
    EXPECT_EQ(none.grid.dims.w, 0u);
    EXPECT_FALSE(none.words.empty());  // a storage buffer is never empty
    EXPECT_EQ(render::probeCellOf(none.grid, glm::vec3(0.0f)), render::kNoIndex);
    const render::ProbeCells flat =
        render::makeProbeCells(r.records, glm::vec3(0.0f), glm::vec3(7.0f, 0.0f, 0.0f));
    EXPECT_EQ(flat.grid.dims.w, 1u);
    EXPECT_EQ(render::probeCellOf(flat.grid, glm::vec3(std::nanf(""))), render::kNoIndex);
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
