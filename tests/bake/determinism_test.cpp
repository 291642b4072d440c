// Determinism and sharding: the same bytes at any thread count, and shards merged equal a
// whole bake byte for byte.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <string>

#include "bake/lightmap/lightmap_denoise.hpp"
#include "bake/shard_plan.hpp"
#include "bake_scenes.hpp"
#include "shading.hpp"
#include "tests/support/error_message.hpp"
#include "world/package/baked_sections.hpp"
#include "world/package/package_reader.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::bake {
namespace {

std::string outputFolder() {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "onelight_determinism";
    std::filesystem::create_directories(dir);
    return dir.string();
}

// A plain room, and the same room with textures, a normal map, an emissive panel and a MASK
// grate (every material feature the transport reads at a hit).
class BakeDeterminism : public ::testing::TestWithParam<bool> {
protected:
    world::SourceLevel level() const {
        return GetParam() ? test::texturedRoomWithProbes(outputFolder())
                          : test::smallRoomWithProbes();
    }
};

TEST_P(BakeDeterminism, OneAndTwoThreadsGiveIdenticalBytes) {
    const world::SourceLevel level = this->level();
    std::vector<uint8_t> one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        BakeResult r = bakeLevel(level, test::fastBakeOptions());
        package::placeImagesForPackage(r.level, outputFolder() + "/determinism.olpak");
        one = packageBytes(r.level, r.baked, r.textures);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        BakeResult r = bakeLevel(level, test::fastBakeOptions());
        package::placeImagesForPackage(r.level, outputFolder() + "/determinism.olpak");
        two = packageBytes(r.level, r.baked, r.textures);
    }
    ASSERT_EQ(one.size(), two.size());
    EXPECT_TRUE(one == two);
}

TEST_P(BakeDeterminism, ShardsMergedEqualAWholeBake) {
    const world::SourceLevel level = this->level();
    const BakeResult whole = bakeLevel(level, test::fastBakeOptions());
    ASSERT_EQ(whole.baked.probes.size(), 3u);
    // Each probe's E_avg is the mean of its irradiance cube (the grid's there, without the
    // punctual lights' direct light), which a part bakes alone.
    for (const world::EnvironmentProbe& p : whole.baked.probes) {
        const glm::vec3 mean = glm::max(ambientCubeAverage(p.irradianceCube),
                                        glm::vec3(onelight::glsl::PROBE_MIN_IRRADIANCE));
        EXPECT_EQ(p.irradianceAverage, mean);
        EXPECT_GT(p.irradianceAverage.x, 0.1f);  // lit room: far above the floor
    }
    std::vector<world::BakedLighting> parts;
    world::CompiledLevel compiled;
    const std::string packagePath = "/tmp/onelight_determinism_parts/level.olpak";
    for (uint32_t i : {1u, 0u}) {  // any order
        BakeOptions o = test::fastBakeOptions();
        o.shardIndex = i;
        o.shardCount = 2;
        BakeResult part = bakeLevel(level, o);
        package::placeImagesForPackage(part.level, packagePath);
        // Through the package, as `merge` reads it.
        const std::vector<uint8_t> bytes = packageBytes(part.level, part.baked, part.textures);
        const package::PackageContents read = package::parsePackage(bytes, "part");
        const package::BakedContents baked =
            package::decodeBakedSections(read.bakedSections, read.level, "part");
        EXPECT_EQ(baked.baked.shardCount, 2u);
        parts.push_back(baked.baked);
        compiled = read.level;
    }
    const world::BakedLighting merged = mergeBakedLighting(compiled, parts);
    world::CompiledLevel wholeLevel = whole.level;
    package::placeImagesForPackage(wholeLevel, packagePath);
    EXPECT_TRUE(packageBytes(compiled, merged, whole.textures) ==
                packageBytes(wholeLevel, whole.baked, whole.textures));
    EXPECT_TRUE(test::allFiniteNonNegative(merged));

    // A shard whose grid has another origin, with the same counts: named, not merged.
    std::vector<world::BakedLighting> moved = parts;
    moved[1].grid.origin.x += 0.25f;
    const std::string originError = onelight::test::errorMessage([&] {
        (void)mergeBakedLighting(compiled, moved, {"first.olpak", "second.olpak"});
    });
    EXPECT_NE(originError.find("second.olpak (shard "), std::string::npos) << originError;
    EXPECT_NE(originError.find("light grid's origin"), std::string::npos) << originError;

    // Parts whose ranges do not meet (a cell baked by neither): named, not merged.
    std::vector<world::BakedLighting> overlapping = parts;
    for (world::BakedLighting& p : overlapping)
        if (p.shardIndex == 1) p.shardRange.cellBegin += 1;
    const std::string overlapError = onelight::test::errorMessage([&] {
        (void)mergeBakedLighting(compiled, overlapping, {"first.olpak", "second.olpak"});
    });
    EXPECT_NE(overlapError.find("expected to start where shard 0 ends"), std::string::npos)
        << overlapError;

    // Probes of another face size in one part (a bake with another --probe-face-size): named.
    std::vector<world::BakedLighting> faces = parts;
    ASSERT_FALSE(whole.baked.probes.empty());
    world::EnvironmentProbe bigger = whole.baked.probes[0];
    bigger.faceSize *= 2;
    faces[1].probes.insert(faces[1].probes.begin(), bigger);
    faces[0].probes.insert(faces[0].probes.begin(), whole.baked.probes[0]);
    const std::string faceError = onelight::test::errorMessage([&] {
        (void)mergeBakedLighting(compiled, faces, {"first.olpak", "second.olpak"});
    });
    EXPECT_NE(faceError.find("second.olpak (shard "), std::string::npos) << faceError;
    EXPECT_NE(faceError.find("like first.olpak's (baked with another --probe-face-size?)"),
              std::string::npos)
        << faceError;

    // Two complete bakes are not the parts of one.
    std::vector<world::BakedLighting> completes(2, whole.baked);
    const std::string completeError = onelight::test::errorMessage([&] {
        (void)mergeBakedLighting(compiled, completes, {"a.olpak", "b.olpak"});
    });
    EXPECT_EQ(completeError,
              "merge: a.olpak is a complete package (a bake of one shard); expected the parts of "
              "one sharded bake (onelight-bake --shard i/N)");

    parts.pop_back();
    const std::string error =
        onelight::test::errorMessage([&] { (void)mergeBakedLighting(compiled, parts); });
    EXPECT_NE(error.find("1 parts given"), std::string::npos) << error;
}

INSTANTIATE_TEST_SUITE_P(Levels, BakeDeterminism, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& level) {
                             return level.param ? "Textured" : "Plain";
                         });

// Every chart, cell and probe belongs to exactly one shard, in order, and each shard's estimated
// cost is its equal share to within one item.
void expectTiling(const ShardCosts& costs, uint32_t count) {
    world::ShardRange next;
    double total = 0.0, largest = 0.0;
    for (const auto* list : {&costs.charts, &costs.cells, &costs.probes})
        for (const double c : *list) {
            total += c;
            largest = std::max(largest, c);
        }
    for (uint32_t i = 0; i < count; ++i) {
        const world::ShardRange r = shardRange(costs, i, count);
        EXPECT_EQ(r.chartBegin, next.chartEnd) << i << "/" << count;
        EXPECT_EQ(r.cellBegin, next.cellEnd) << i << "/" << count;
        EXPECT_EQ(r.probeBegin, next.probeEnd) << i << "/" << count;
        EXPECT_LE(r.chartBegin, r.chartEnd);
        EXPECT_LE(r.cellBegin, r.cellEnd);
        EXPECT_LE(r.probeBegin, r.probeEnd);
        EXPECT_EQ(r.probeTotal, costs.probes.size());
        EXPECT_NEAR(shardCost(costs, r), total / count, largest + 1e-9) << i << "/" << count;
        next = r;
    }
    EXPECT_EQ(next.chartEnd, costs.charts.size()) << count;
    EXPECT_EQ(next.cellEnd, costs.cells.size()) << count;
    EXPECT_EQ(next.probeEnd, costs.probes.size()) << count;
}

// Charts, cells and probes are laid end to end and cut by cost: a chart of many texels takes a
// larger share than one of few, and a probe worth many cells takes a shard's share alone.
TEST(BakeShards, ChartsCellsAndProbesAreCutIntoEqualShares) {
    ShardCosts costs;
    for (int c = 0; c < 40; ++c) costs.charts.push_back(c < 10 ? 7000.0 : 1000.0);
    costs.cells.assign(300, 200.0);
    costs.probes.assign(2, 24576.0);
    // Total 70000 + 30000 + 60000 + 49152 = 209152.
    for (const uint32_t count : {1u, 2u, 3u, 5u, 8u, 64u, 500u}) expectTiling(costs, count);
    // Four shards: the first quarter (52288) is 8 of the costly charts (56000 reaches it).
    const world::ShardRange first = shardRange(costs, 0, 4);
    EXPECT_EQ(first.chartEnd, 8u);
    EXPECT_EQ(first.cellEnd, 0u);
    const world::ShardRange last = shardRange(costs, 3, 4);
    EXPECT_EQ(last.probeEnd - last.probeBegin, 2u);
    // No cost at all (an empty level's zero paths): cut by count.
    ShardCosts none;
    none.cells.assign(10, 0.0);
    expectTiling(none, 3);
    EXPECT_EQ(shardRange(none, 1, 3).cellBegin, 3u);
}

// A shard owns the placed texels of its charts, whatever their place in the atlas; its range is
// of positions in the charts' space order.
TEST(BakeShards, AShardOwnsTheTexelsOfItsCharts) {
    world::CompiledLevel level;
    level.charts.resize(3);
    level.surfaces.resize(3);
    // Surface s is on chart 2 - s; the charts lie along x at 10 m (chart 0), 0 m (chart 1) and
    // 5 m (chart 2): in space order 1, 2, 0.
    const float chartX[3] = {10.0f, 0.0f, 5.0f};
    for (uint32_t s = 0; s < 3; ++s) {
        level.surfaces[s].chart = 2 - s;
        level.surfaces[s].boundsMin = glm::vec3(chartX[2 - s], 0.0f, 0.0f);
        level.surfaces[s].boundsMax = glm::vec3(chartX[2 - s] + 1.0f, 0.0f, 1.0f);
    }
    EXPECT_EQ(chartSpaceOrder(level), (std::vector<uint32_t>{1, 2, 0}));
    std::vector<TexelSample> samples;
    for (uint32_t t = 0; t < 9; ++t) {
        samples.push_back({t});
        samples.back().surface = t % 3;  // charts 2, 1, 0, 2, 1, 0, ... interleaved in rows
    }
    const std::vector<uint32_t> order = chartSpaceOrder(level);
    EXPECT_EQ(samplesOfRange(level, order, samples, {0, 1, 0, 0, 0, 0, 0}),
              (std::vector<uint32_t>{1, 4, 7}));
    EXPECT_EQ(samplesOfRange(level, order, samples, {1, 3, 0, 0, 0, 0, 0}),
              (std::vector<uint32_t>{0, 2, 3, 5, 6, 8}));
}

// The space order is a permutation of the charts that follows a Morton curve: a chart without a
// surface or without finite bounds first, equal centres by index, huge coordinates no trouble.
TEST(BakeShards, TheChartsSpaceOrderIsAPermutationAlongAMortonCurve) {
    EXPECT_TRUE(chartSpaceOrder(world::CompiledLevel{}).empty());
    world::CompiledLevel level;
    level.charts.resize(7);
    // Charts 0..3 at the corners of a square 1e7 m from the origin, in the order (1,1), (0,0),
    // (1,0), (0,1); chart 4 has no surface; charts 5 and 6 share chart 1's centre; chart 0's
    // second surface widens it without moving its centre.
    const glm::vec2 corner[4] = {{1, 1}, {0, 0}, {1, 0}, {0, 1}};
    const glm::vec3 far(1.0e7f, -1.0e7f, 3.0e6f);
    const auto add = [&](uint32_t chart, glm::vec3 low, glm::vec3 high) {
        world::Surface s;
        s.chart = chart;
        s.boundsMin = low;
        s.boundsMax = high;
        level.surfaces.push_back(s);
    };
    for (uint32_t c = 0; c < 4; ++c) {
        const glm::vec3 at = far + 100.0f * glm::vec3(corner[c], 0.0f);
        add(c, at - glm::vec3(1.0f), at + glm::vec3(1.0f));
    }
    add(0, far + glm::vec3(99.0f, 99.0f, -1.0f), far + glm::vec3(101.0f, 101.0f, 1.0f));
    add(5, far - glm::vec3(1.0f), far + glm::vec3(1.0f));
    add(6, far - glm::vec3(0.5f), far + glm::vec3(0.5f));
    add(world::kNoIndex, glm::vec3(-1e30f), glm::vec3(1e30f));  // on no chart: not counted
    // Morton order interleaves x in the lowest bit: (0,0), (1,0), (0,1), (1,1).
    EXPECT_EQ(chartSpaceOrder(level), (std::vector<uint32_t>{4, 1, 5, 6, 2, 3, 0}));
}

// What the space order is for: a part gathers its own texels and those its denoiser windows read
// in other parts' charts. On a floor of 32 x 32 small charts numbered at random, cutting the index
// order in four makes every part gather most of the floor; the space order's quarters gather
// their own quarter and a band of window reach along two edges.
TEST(BakeShards, PartsInSpaceOrderGatherLittleBeyondTheirOwnTexels) {
    constexpr uint32_t kCharts = 32, kTexels = 8;  // per side; a chart is 8 x 8 texels
    constexpr float kTexelSize = 0.25f;
    world::CompiledLevel level;
    level.charts.resize(kCharts * kCharts);
    std::vector<uint32_t> shuffled(kCharts * kCharts);
    for (uint32_t c = 0; c < shuffled.size(); ++c) shuffled[c] = c;
    std::mt19937 random(7);
    std::shuffle(shuffled.begin(), shuffled.end(), random);
    std::vector<TexelSample> samples;
    for (uint32_t cy = 0; cy < kCharts; ++cy)
        for (uint32_t cx = 0; cx < kCharts; ++cx) {
            const uint32_t surface = uint32_t(level.surfaces.size());
            world::Surface s;
            s.chart = shuffled[cy * kCharts + cx];
            s.boundsMin = glm::vec3(cx, cy, 0.0f) * (kTexels * kTexelSize);
            s.boundsMax = s.boundsMin + glm::vec3(kTexels * kTexelSize, kTexels * kTexelSize, 0.0f);
            level.surfaces.push_back(s);
            for (uint32_t y = 0; y < kTexels; ++y)
                for (uint32_t x = 0; x < kTexels; ++x) {
                    TexelSample t;
                    t.texel = samples.size();
                    t.surface = surface;
                    t.centre = t.position =
                        s.boundsMin + kTexelSize * glm::vec3(x + 0.5f, y + 0.5f, 0.0f);
                    t.normal = glm::vec3(0.0f, 0.0f, 1.0f);
                    t.texelSize = kTexelSize;
                    t.centreInside = true;
                    samples.push_back(t);
                }
        }
    const TexelHash hash = makeTexelHash(samples);
    const auto gathered = [&](const std::vector<uint32_t>& owned) {
        std::vector<uint8_t> needed;
        markDenoiseFootprint(hash, samples, owned, needed);
        return double(std::count(needed.begin(), needed.end(), uint8_t(1)));
    };
    ShardCosts costs;
    costs.charts.assign(level.charts.size(), 1.0);
    const std::vector<uint32_t> order = chartSpaceOrder(level);
    double inSpaceOrder = 0.0, inIndexOrder = 0.0;
    for (uint32_t part = 0; part < 4; ++part) {
        const world::ShardRange range = shardRange(costs, part, 4);
        ASSERT_EQ(range.chartEnd - range.chartBegin, 256u);
        inSpaceOrder += gathered(samplesOfRange(level, order, samples, range));
        std::vector<uint32_t> byIndex;
        for (uint32_t i = 0; i < samples.size(); ++i) {
            const uint32_t chart = level.surfaces[samples[i].surface].chart;
            if (chart >= range.chartBegin && chart < range.chartEnd) byIndex.push_back(i);
        }
        inIndexOrder += gathered(byIndex);
    }
    inSpaceOrder /= double(samples.size());
    inIndexOrder /= double(samples.size());
    std::printf(
        "[ shards   ] 4 parts gather %.3f x the texels in space order, %.3f x in index "
        "order\n",
        inSpaceOrder, inIndexOrder);
    // Each quarter is 128 x 128 texels: a band of 5.5 texels (the largest window) along two of
    // its edges adds 2 x 5.5 / 128 = 8.6%, a little more at the corner.
    EXPECT_LT(inSpaceOrder, 1.1);
    EXPECT_GT(inSpaceOrder, 1.0);
    EXPECT_GT(inIndexOrder, 2.5);
}

// A cell that more lights reach costs more shadow rays; a texel's lights do not count (its
// direct light is computed whole in every part). Without cached bounces (--paths-only) every
// gathering path costs twice as much.
TEST(BakeShards, CostsFollowPathsAndTheLightsThatReachEachCell) {
    world::Light near;
    near.type = world::LightType::kPoint;
    near.role = world::LightRole::kBaked;
    near.position = glm::vec3(0.5f, 0.5f, 0.5f);
    near.range = 2.0f;
    world::Light sun;
    sun.type = world::LightType::kDirectional;
    sun.role = world::LightRole::kBaked;
    BakeLights lights = makePunctualLights({near, sun}, LightSizes{}, glm::vec3(0.0f));
    // The point light in light cells over the 16 m row, the sun everywhere, as makeBakeLights
    // lays them over a scene.
    lights.localLights = {0};
    lights.directionalLights = {1};
    lights.lightCells = layoutLightCells(1, glm::vec3(0.0f), glm::vec3(16.0f, 1.0f, 1.0f));
    fillLightCells(lights.lightCells, {lightBoundOf(lights.lights[0])});
    world::LightGrid grid;
    grid.origin = glm::vec3(0.0f);
    grid.cellSize = glm::vec3(1.0f);
    grid.dims = glm::uvec3(16, 1, 1);
    grid.cells.resize(16);
    std::vector<TexelSample> samples(2);
    samples[0].position = glm::vec3(0.5f);
    samples[1] = {1};
    samples[1].position = glm::vec3(15.5f, 0.5f, 0.5f);
    samples[1].surface = 1;
    world::CompiledLevel level;  // the two texels on charts 0 and 1
    level.charts.resize(2);
    level.surfaces.resize(2);
    level.surfaces[0].chart = 0;
    level.surfaces[1].chart = 1;
    LightmapSettings lm;
    lm.indirectSamples = 128;
    lm.bouncePasses = 3;
    GridSettings gs;
    gs.samples = 128;
    gs.shadowSamples = 8;
    ProbeCaptureSettings ps;
    ps.faceSize = 16;
    ps.samplesPerTexel = 4;
    const std::vector<uint32_t> order = chartSpaceOrder(level);
    const ShardCosts cached =
        estimateShardCosts(lights, level, order, samples, grid, 1, lm, gs, ps);
    EXPECT_EQ(lightsReaching(lights, glm::vec3(0.5f)), 2u);
    EXPECT_EQ(lightsReaching(lights, glm::vec3(15.5f, 0.5f, 0.5f)), 1u);
    // 128 paths at 0.45 us, 8 shadow rays per light at 0.1 us.
    EXPECT_NEAR(cached.cells[15], 128 * 0.45e-6 + 8 * 1 * 0.1e-6, 1e-12);
    EXPECT_NEAR(cached.cells[0], 128 * 0.45e-6 + 8 * 2 * 0.1e-6, 1e-12);
    EXPECT_NEAR(cached.charts[0], 128 * 1.5e-6, 1e-12);
    EXPECT_EQ(cached.charts[0], cached.charts[1]);
    EXPECT_NEAR(cached.probes[0], 6.0 * 16 * 16 * 4 * 1.9e-6, 1e-12);
    lm.bouncePasses = 0;
    const ShardCosts paths = estimateShardCosts(lights, level, order, samples, grid, 0, lm, gs, ps);
    EXPECT_NEAR(paths.charts[1], 2 * cached.charts[1], 1e-12);
    EXPECT_NEAR(paths.cells[15], 128 * 0.9e-6 + 8 * 1 * 0.1e-6, 1e-12);
    EXPECT_TRUE(paths.probes.empty());
}

}  // namespace
}  // namespace onelight::bake
