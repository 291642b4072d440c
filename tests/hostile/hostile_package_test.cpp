// Hostile packages: image uris that point anywhere but beside the package, light grids whose
// dimensions overflow or are empty, and error-budget records out of range, all with valid
// checksums, so that only the reader's checks
// stand between them and the runtime.
#include <sys/stat.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>

#include "hostile_level.hpp"
#include "tests/support/error_message.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/baked_lighting.hpp"
#include "world/light_grid_sample.hpp"
#include "world/package/baked_sections.hpp"
#include "world/package/budget_section.hpp"
#include "world/package/format.hpp"
#include "world/package/package_reader.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::test {
namespace {

const world::CompiledLevel& triangleLevel() {
    static const world::CompiledLevel level =
        compileFile(writeTriangleLevel(hostileFolder("package"))).level;
    return level;
}

TEST(HostilePackage, ImageUrisStayBesideThePackage) {
    for (const char* good : {"a.png", "textures/a.png", "t/u/v.hdr", "..a.png", "a..png"})
        EXPECT_TRUE(package::isPathBesideThePackage(good)) << good;
    for (const char* bad : {"", "/etc/hostname", "/proc/self/mem", "../a.png", "t/../../a.png",
                            "t/..", "..", "a//b.png", "C:a.png", "t\\a.png", "t/"})
        EXPECT_FALSE(package::isPathBesideThePackage(bad)) << bad;

    // The reader refuses such a uri with the record and the rule.
    for (const char* bad : {"/etc/hostname", "../../etc/passwd"}) {
        world::CompiledLevel level = triangleLevel();
        world::Image image;
        image.name = "stolen";
        image.uri = bad;
        level.images.push_back(image);
        // The writer refuses to make it (below); the reader must refuse it too.
        EXPECT_NE(errorMessage([&] {
                      (void)package::serializePackage(level);
                  }).find("(the writer runs the reader's checks: nothing was written)"),
                  std::string::npos);
        const std::vector<uint8_t> bytes = package::serializeUncheckedPackage(level);
        const std::string error =
            errorMessage([&] { (void)package::parsePackage(bytes, "hostile.olpak"); });
        EXPECT_NE(error.find("hostile.olpak: section images record 0: uri"), std::string::npos)
            << error;
        EXPECT_NE(error.find("expected a relative path to a file beside the package"),
                  std::string::npos)
            << error;
    }
}

TEST(HostilePackage, TheWriterRunsTheReadersChecksOnEveryRecord) {
    // A light whose intensity overflowed and a spot with cones past pi/2: the writer refuses
    // what the reader would, with the reader's own words.
    world::CompiledLevel level = triangleLevel();
    world::Light hot;
    hot.name = "hot";
    hot.intensity = std::numeric_limits<float>::infinity();
    level.lights.push_back(hot);
    std::string error = errorMessage([&] { (void)package::serializePackage(level); });
    EXPECT_NE(error.find("the package as made: section lights record "), std::string::npos)
        << error;
    EXPECT_NE(error.find("intensity inf; expected finite >= 0 (the writer runs the reader's "
                         "checks: nothing was written)"),
              std::string::npos)
        << error;
    level.lights.back().intensity = 1.0f;
    level.lights.back().type = world::LightType::kSpot;
    level.lights.back().outerCone = -1.0f;
    error = errorMessage([&] { (void)package::serializePackage(level); });
    EXPECT_NE(error.find("cone angles; expected 0 <= inner <= outer <= pi/2"), std::string::npos)
        << error;
    level.lights.back().outerCone = 0.5f;
    EXPECT_EQ(errorMessage([&] { (void)package::serializePackage(level); }), "");
}

TEST(HostilePackage, ImagesOutsideThePackagesFolderAreEmbedded) {
    const std::filesystem::path folder = hostileFolder("embed");
    std::filesystem::create_directories(folder / "assets");
    std::filesystem::create_directories(folder / "out" / "textures");
    std::ofstream(folder / "assets" / "far.png") << "far bytes";
    std::ofstream(folder / "out" / "textures" / "near.png") << "near bytes";
    world::CompiledLevel level = triangleLevel();
    level.images.resize(2);
    level.images[0].uri = (folder / "assets" / "far.png").string();
    level.images[1].uri = (folder / "out" / "textures" / "near.png").string();
    package::placeImagesForPackage(level, (folder / "out" / "level.olpak").string());
    EXPECT_EQ(level.images[0].uri, "");
    EXPECT_EQ(std::string(level.images[0].encodedBytes.begin(), level.images[0].encodedBytes.end()),
              "far bytes");
    EXPECT_EQ(level.images[1].uri, "textures/near.png");
    EXPECT_TRUE(level.images[1].encodedBytes.empty());
    // And the result passes the reader.
    const std::vector<uint8_t> bytes = package::serializePackage(level);
    EXPECT_EQ(errorMessage([&] { (void)package::parsePackage(bytes, "embedded.olpak"); }), "");
    // An image beside the package that is a FIFO (or missing) is refused when the package is
    // made, not written into it for the runtime to meet.
    ASSERT_EQ(::mkfifo((folder / "out" / "textures" / "pipe.png").c_str(), 0600), 0);
    for (const char* name : {"pipe.png", "missing.png"}) {
        world::CompiledLevel piped = triangleLevel();
        piped.images.resize(1);
        piped.images[0].uri = (folder / "out" / "textures" / name).string();
        const std::string error = errorMessage([&] {
            package::placeImagesForPackage(piped, (folder / "out" / "level.olpak").string());
        });
        EXPECT_NE(error.find(name), std::string::npos) << error;
        EXPECT_NE(error.find("expected an image the level uses"), std::string::npos) << error;
    }
}

uint64_t triangleLevelTexels() {
    uint64_t texels = 0;
    for (const world::Atlas& a : triangleLevel().atlases) texels += uint64_t(a.width) * a.height;
    return texels;
}

// A complete bake of the triangle level: every texel, a 1x1x1 grid.
world::BakedLighting triangleBake() {
    const uint64_t texels = triangleLevelTexels();
    world::BakedLighting baked;
    baked.texels.resize(texels);
    for (world::LightmapTexel& t : baked.texels) t.normalWeight = 1.0f;
    baked.shadowMask.assign(texels, 0);
    baked.grid.dims = glm::uvec3(1);
    baked.grid.cells.resize(1);
    return baked;
}

// Its sections.
std::vector<package::RawSection> bakedSections() {
    return package::encodeBakedSections(triangleBake());
}

// The light grid section with its header's dims and cell count replaced.
std::string gridError(uint32_t x, uint32_t y, uint32_t z, uint32_t cellCount) {
    std::vector<package::RawSection> sections = bakedSections();
    for (package::RawSection& s : sections) {
        if (s.id != package::kSectionLightGrid) continue;
        const uint32_t dims[4] = {x, y, z, cellCount};
        std::memcpy(s.bytes.data() + offsetof(package::DiskLightGridHeader, dims), dims,
                    sizeof dims);
    }
    return errorMessage(
        [&] { (void)package::decodeBakedSections(sections, triangleLevel(), "grid.olpak"); });
}

TEST(HostilePackage, LightGridDimsThatOverflowOrAreEmptyAreRejected) {
    EXPECT_EQ(gridError(1, 1, 1, 1), "") << "the unedited grid is valid";
    // 2^21 * 2^21 * 2^22 = 2^64 wraps to 0 in 64 bits; with cellCount 0 it once passed.
    for (auto [x, y, z, n] :
         {std::array<uint32_t, 4>{1u << 21, 1u << 21, 1u << 22, 0},
          std::array<uint32_t, 4>{0xFFFFFFFFu, 0xFFFFFFFFu, 1, 1},
          std::array<uint32_t, 4>{0, 1, 1, 0}, std::array<uint32_t, 4>{1, 0, 7, 0}}) {
        const std::string error = gridError(x, y, z, n);
        EXPECT_NE(error.find("grid.olpak: section light_grid: dims["), std::string::npos) << error;
        EXPECT_NE(error.find("expected 1..4096 cells"), std::string::npos) << error;
    }
    const std::string tooMany = gridError(4096, 4096, 2, 0);
    EXPECT_NE(tooMany.find("33554432 cells; expected at most 16777216"), std::string::npos)
        << tooMany;
}

// The lightmap section with texel 0 changed by `edit`.
template <class Edit>
std::string texelError(Edit edit) {
    world::BakedLighting baked = triangleBake();
    edit(baked.texels[0]);
    const std::vector<package::RawSection> sections = package::encodeBakedSections(baked);
    return errorMessage(
        [&] { (void)package::decodeBakedSections(sections, triangleLevel(), "texel.olpak"); });
}

// A texel's direct part is one light: a unit direction where it has light, none where it has
// none; both parts are finite and not negative.
TEST(HostilePackage, ALightmapTexelsDirectAndIndirectPartsAreChecked) {
    EXPECT_EQ(texelError([](world::LightmapTexel&) {}), "") << "the unedited bake is valid";
    EXPECT_EQ(texelError([](world::LightmapTexel& t) {
                  t.directIrradiance = glm::vec3(3.0f, 2.0f, 1.0f);
                  t.directLight = glm::vec3(0.0f, 0.6f, 0.8f);
                  t.indirectIrradiance = glm::vec3(1.0f);
              }),
              "");
    const std::string prefix = "texel.olpak: section lightmap_texels, record 0: ";
    EXPECT_EQ(texelError([](world::LightmapTexel& t) {
                  t.directIrradiance = glm::vec3(1.0f);
                  t.directLight = glm::vec3(0.0f, 0.5f, 0.0f);
              }),
              prefix + "directLight length 0.500000: expected 1 (a direct light)");
    EXPECT_EQ(texelError([](world::LightmapTexel& t) { t.directLight = glm::vec3(1.0f, 0, 0); }),
              prefix + "directLight length 1.000000: expected 0 (no direct light)");
    EXPECT_EQ(texelError([](world::LightmapTexel& t) {
                  t.directIrradiance = glm::vec3(1.0f);
                  t.directLight = glm::vec3(std::nanf(""), 0.0f, 1.0f);
              }),
              prefix + "directLight length nan: expected 1 (a direct light)");
    EXPECT_EQ(texelError([](world::LightmapTexel& t) { t.directIrradiance.y = -1.0f; }),
              prefix + "directIrradiance[1] = -1.000000: not finite or negative");
    EXPECT_EQ(texelError([](world::LightmapTexel& t) {
                  t.indirectIrradiance.z = std::numeric_limits<float>::infinity();
              }),
              prefix + "indirectIrradiance[2] = inf: not finite or negative");
}

TEST(HostilePackage, ALightmapTexelsShadowEdgeIsChecked) {
    EXPECT_EQ(texelError([](world::LightmapTexel& t) {
                  t.directVisibility = 0.25f;
                  t.directEdgeDistance = -1.5f;
                  t.directEdgeWidth = 0.2f;
                  t.directEdgeLow = 0.1f;
                  t.directEdgeHigh = 0.9f;
                  t.directEdgeSharpness = 1.0f;
              }),
              "");
    const std::string prefix = "texel.olpak: section lightmap_texels, record 0: ";
    EXPECT_EQ(texelError([](world::LightmapTexel& t) { t.directVisibility = 1.5f; }),
              prefix + "directVisibility 1.500000 outside [0.000000, 1.000000]");
    EXPECT_EQ(texelError([](world::LightmapTexel& t) { t.directVisibility = std::nanf(""); }),
              prefix + "directVisibility nan outside [0.000000, 1.000000]");
    EXPECT_EQ(texelError([](world::LightmapTexel& t) { t.directEdgeDistance = -3.0f; }),
              prefix + "directEdgeDistance -3.000000 outside [-2.000000, 2.000000]");
    EXPECT_EQ(texelError([](world::LightmapTexel& t) {
                  t.directEdgeWidth = std::numeric_limits<float>::infinity();
              }),
              prefix + "directEdgeWidth inf outside [0.000000, 1.000000]");
    EXPECT_EQ(texelError([](world::LightmapTexel& t) { t.directEdgeLow = -0.25f; }),
              prefix + "directEdgeLow -0.250000 outside [0.000000, 1.000000]");
    EXPECT_EQ(texelError([](world::LightmapTexel& t) {
                  t.directEdgeLow = 0.8f;
                  t.directEdgeHigh = 0.5f;
              }),
              prefix + "directEdgeHigh 0.500000 outside [0.800000, 1.000000]");
    EXPECT_EQ(texelError([](world::LightmapTexel& t) { t.directEdgeSharpness = -0.5f; }),
              prefix + "directEdgeSharpness -0.500000 outside [0.000000, 1.000000]");
}

TEST(HostilePackage, SamplingAGridWhoseCellsDoNotMatchItsDimsReadsNothing) {
    world::LightGrid grid;
    grid.dims = glm::uvec3(1u << 21, 1u << 21, 1u << 22);  // wraps to 0 cells in 64 bits
    grid.cells.resize(8);
    grid.cells[0].ambientCube[0] = glm::vec3(1.0f);
    const world::LightGridSample s = world::sampleLightGrid(grid, glm::vec3(1e6f, 2e6f, 3e6f));
    for (const glm::vec3& face : s.ambientCube) EXPECT_EQ(face, glm::vec3(0.0f));
}

// The triangle level's bake with an error budget's choices.
world::ErrorBudgetChoices budgetChoices() {
    world::ErrorBudgetChoices c;
    c.budget = 0.05f;
    c.flags = world::kBudgetProbesDropped | world::kBudgetGridReduced;
    c.probeError = 0.004f;
    c.probesPlaced = 12;
    c.densityTolerance = 0.1f;
    c.lightmapError = 0.0125f;
    c.texelsRequested = 900;
    c.texelsSampled = 30;
    c.gridCellsFull = 64;
    c.gridCells = 1;
    c.viewsPredicted = 4;
    c.predictedError = 0.0165f;
    return c;
}

// decodeBakedSections' message for the budget section made from `choices`.
std::string budgetError(const world::ErrorBudgetChoices& choices) {
    std::vector<package::RawSection> sections = bakedSections();
    sections.push_back(package::encodeBudgetSection(choices));
    return errorMessage(
        [&] { (void)package::decodeBakedSections(sections, triangleLevel(), "budget.olpak"); });
}

TEST(HostilePackage, ErrorBudgetChoicesRoundTripAndBadOnesAreRejected) {
    std::vector<package::RawSection> sections = bakedSections();
    sections.push_back(package::encodeBudgetSection(budgetChoices()));
    const world::ErrorBudgetChoices back =
        package::decodeBakedSections(sections, triangleLevel(), "budget.olpak").baked.budget;
    const world::ErrorBudgetChoices want = budgetChoices();
    EXPECT_EQ(std::memcmp(&back, &want, sizeof back), 0) << "the choices changed on the way";

    struct Case {
        void (*edit)(world::ErrorBudgetChoices&);
        const char* mustSay;
    } cases[] = {
        {[](world::ErrorBudgetChoices& c) { c.budget = 1.5f; }, "budget = 1.5"},
        {[](world::ErrorBudgetChoices& c) { c.budget = std::nanf(""); }, "budget = nan"},
        {[](world::ErrorBudgetChoices& c) { c.flags = 8; }, "flags = 8; expected no bits but"},
        {[](world::ErrorBudgetChoices& c) {
             c.probeError = std::numeric_limits<float>::infinity();
         },
         "probeError = inf; expected a finite error >= 0"},
        {[](world::ErrorBudgetChoices& c) { c.lightmapError = -0.1f; }, "lightmapError = -0.1"},
        {[](world::ErrorBudgetChoices& c) { c.densityTolerance = 0.0f; }, "densityTolerance = 0"},
        {[](world::ErrorBudgetChoices& c) { c.texelsSampled = 901; },
         "texelsSampled = 901; expected at most texelsRequested (900)"},
        {[](world::ErrorBudgetChoices& c) { c.gridCells = 2; },
         "gridCells = 2; expected the light grid's 1 cells"},
        {[](world::ErrorBudgetChoices& c) { c.gridCellsFull = 0; }, "gridCellsFull = 0"},
    };
    for (const Case& k : cases) {
        world::ErrorBudgetChoices c = budgetChoices();
        k.edit(c);
        const std::string error = budgetError(c);
        EXPECT_NE(error.find("budget.olpak: section error_budget: "), std::string::npos) << error;
        EXPECT_NE(error.find(k.mustSay), std::string::npos) << error;
    }
    // A truncated record, and the section without baked lighting.
    package::RawSection cut = package::encodeBudgetSection(budgetChoices());
    cut.bytes.resize(20);
    std::vector<package::RawSection> truncated = bakedSections();
    truncated.push_back(cut);
    EXPECT_NE(errorMessage([&] {
                  (void)package::decodeBakedSections(truncated, triangleLevel(), "cut.olpak");
              }).find("cut.olpak: section error_budget: element size 48, count 1, 20 bytes"),
              std::string::npos);
    const std::vector<package::RawSection> alone = {package::encodeBudgetSection(budgetChoices())};
    EXPECT_NE(errorMessage([&] {
                  (void)package::decodeBakedSections(alone, triangleLevel(), "alone.olpak");
              }).find("section error_budget present without baked lighting"),
              std::string::npos);
}

// A part of a sharded bake of the triangle level with `range`: shard 1 of 2; with !part, a
// whole package given a part's range section anyway.
std::string shardRangeError(const world::ShardRange& range, bool part = true) {
    world::BakedLighting baked = triangleBake();
    baked.shardIndex = part ? 1 : 0;
    baked.shardCount = part ? 2 : 1;
    baked.shardRange = range;
    std::vector<package::RawSection> sections = package::encodeBakedSections(baked);
    if (!part) {
        baked.shardCount = 2;
        for (const package::RawSection& s : package::encodeBakedSections(baked))
            if (s.id == package::kSectionShardRange) sections.push_back(s);
    }
    return errorMessage(
        [&] { (void)package::decodeBakedSections(sections, triangleLevel(), "part.olpak"); });
}

TEST(HostilePackage, AShardsRangeThatLiesIsRejected) {
    const uint64_t charts = triangleLevel().charts.size();
    ASSERT_GE(charts, 1u);
    const world::ShardRange good{0, charts, 0, 1, 0, 0, 0};
    EXPECT_EQ(shardRangeError(good), "") << "the unedited range is valid";
    struct Case {
        world::ShardRange range;
        const char* mustSay;
    } cases[] = {
        {{0, charts + 1, 0, 1, 0, 0, 0}, "section shard_range: charts [0, "},
        {{5, 4, 0, 1, 0, 0, 0}, "charts [5, 4); expected begin <= end"},
        {{0, charts, 0, 2, 0, 0, 0}, "cells [0, 2); expected begin <= end <= 1"},
        {{0, charts, 0, 1, 0, 1, 1}, "probes [0, 1) but the probe section holds 0"},
        {{0, charts, 0, 1, 0, 3, 2}, "probes [0, 3); expected begin <= end <= 2 (probeTotal)"},
    };
    for (const Case& k : cases) {
        const std::string error = shardRangeError(k.range);
        EXPECT_NE(error.find("part.olpak: section shard_range: "), std::string::npos) << error;
        EXPECT_NE(error.find(k.mustSay), std::string::npos) << error;
    }
    // A part without the section, and a whole package with one.
    world::BakedLighting part = triangleBake();
    part.shardIndex = 1;
    part.shardCount = 2;
    std::vector<package::RawSection> missing;
    for (const package::RawSection& s : package::encodeBakedSections(part))
        if (s.id != package::kSectionShardRange) missing.push_back(s);
    EXPECT_NE(errorMessage([&] {
                  (void)package::decodeBakedSections(missing, triangleLevel(), "part.olpak");
              }).find("section shard_range missing with light_grid's shard 1/2"),
              std::string::npos);
    EXPECT_NE(shardRangeError(good, false)
                  .find("section shard_range present with light_grid's "
                        "shard 0/1; expected it in an unmerged part"),
              std::string::npos);
}

}  // namespace
}  // namespace onelight::test
