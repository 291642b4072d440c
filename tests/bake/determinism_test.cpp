// Determinism and sharding: the same bytes at any thread count, and shards merged equal a
// whole bake byte for byte.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <filesystem>
#include <string>

#include "bake_scenes.hpp"
#include "shading.hpp"
#include "tests/support/error_message.hpp"
#include "world/light_grid_sample.hpp"
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
        const BakeResult r = bakeLevel(level, test::fastBakeOptions());
        one = packageBytes(r.level, r.baked, r.textures);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        const BakeResult r = bakeLevel(level, test::fastBakeOptions());
        two = packageBytes(r.level, r.baked, r.textures);
    }
    ASSERT_EQ(one.size(), two.size());
    EXPECT_TRUE(one == two);
}

TEST_P(BakeDeterminism, ShardsMergedEqualAWholeBake) {
    const world::SourceLevel level = this->level();
    const BakeResult whole = bakeLevel(level, test::fastBakeOptions());
    ASSERT_EQ(whole.baked.probes.size(), 3u);
    // Each probe's E_avg is exactly what the runtime reads from the finished grid there.
    for (const world::EnvironmentProbe& p : whole.baked.probes) {
        const glm::vec3 runtime = glm::max(
            ambientCubeAverage(world::sampleLightGrid(whole.baked.grid, p.position).ambientCube),
            glm::vec3(onelight::glsl::PROBE_MIN_IRRADIANCE));
        EXPECT_EQ(p.irradianceAverage, runtime);
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

    parts.pop_back();
    const std::string error =
        onelight::test::errorMessage([&] { (void)mergeBakedLighting(compiled, parts); });
    EXPECT_NE(error.find("1 parts given"), std::string::npos) << error;
}

INSTANTIATE_TEST_SUITE_P(Levels, BakeDeterminism, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& level) {
                             return level.param ? "Textured" : "Plain";
                         });

// Shards own equal shares of the placed texels, not of the atlases: placed texels crowd the
// first tenth of a 1000-texel atlas, and the cut follows them, while every texel, placed or not,
// still belongs to exactly one shard.
TEST(BakeShards, TexelsAreCutIntoEqualSharesOfThePlacedTexels) {
    std::vector<TexelSample> samples;
    for (uint64_t t = 0; t < 100; ++t) samples.push_back({t});
    for (uint64_t t = 100; t < 1000; t += 10) samples.push_back({t});  // 190 placed in all
    for (const uint32_t count : {1u, 2u, 4u, 7u, 300u}) {
        uint64_t next = 0;
        for (uint32_t i = 0; i < count; ++i) {
            const ShardRange r = shardRange(samples, 1000, 10, 0, i, count);
            EXPECT_EQ(r.texelBegin, next) << i << "/" << count;
            EXPECT_LE(r.texelBegin, r.texelEnd) << i << "/" << count;
            next = r.texelEnd;
            size_t owned = 0;
            for (const TexelSample& s : samples)
                owned += s.texel >= r.texelBegin && s.texel < r.texelEnd;
            EXPECT_LE(owned, samples.size() / count + 1) << i << "/" << count;
            EXPECT_GE(owned, samples.size() / count) << i << "/" << count;
        }
        EXPECT_EQ(next, 1000u) << count;
    }
    // Two shards: the first owns 95 of the crowded first 100 texels, not half the atlas.
    EXPECT_EQ(shardRange(samples, 1000, 10, 0, 0, 2).texelEnd, 95u);
}

}  // namespace
}  // namespace onelight::bake
