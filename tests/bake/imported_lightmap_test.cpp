// A source format's own bake (world::ImportedLightmap, a Quake 3 map's q3map2 lightmaps) read at
// the engine's lightmap texels: every sampled texel holds the page's bilinear value (or the
// corners' vertex light) where the texel lies, in closed form; shards merge to the whole bake's
// bytes; package section 36 round-trips and is refused when wrong; and bytes stored under
// q3map2's -gamma, -exposure, -compensate, -brightness, -contrast and sRGB options decode to the
// values q3map2 computed.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "bake/lightmap/imported_lightmap.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "bake_scenes.hpp"
#include "tests/support/error_message.hpp"
#include "world/package/baked_sections.hpp"
#include "world/package/format.hpp"
#include "world/package/package_reader.hpp"

namespace onelight::bake {
namespace {

constexpr uint32_t kPage = 4;  // texels per side

// Page texel (i, j): a plane in i and j, so that bilinear reads are exact.
glm::vec3 pageValue(float i, float j) {
    return {10.0f * i + 3.0f * j + 5.0f, 2.0f * i, 40.0f};
}

// A 4 x 4 m floor (y = 0) whose q3map2 light is the page above (uv = (x, z) / 4), and a 4 x 2 m
// wall (z = -2) without a page, lit by vertex light rising with height: 0 at the floor, 100 lux
// at the top.
world::SourceLevel importedLevel() {
    world::SourceLevel level;
    const uint32_t m = test::addLambertMaterial(level, 0.5f);
    test::addQuad(level, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2}, m, "floor");
    test::addQuad(level, {-2, 0, -2}, {2, 0, -2}, {2, 2, -2}, {-2, 2, -2}, m, "wall");
    level.lights.push_back(test::pointLight({0, 1.5f, 0}, 100.0f, world::LightRole::kBaked));
    level.texelsPerMetre = 4.0f;
    world::ImportedLightmap& imported = level.importedLightmap;
    imported.producer = "q3map2";
    imported.pageSize = kPage;
    for (uint32_t j = 0; j < kPage; ++j)
        for (uint32_t i = 0; i < kPage; ++i) {
            const glm::vec3 v = pageValue(float(i), float(j));
            imported.pages.insert(imported.pages.end(), {uint8_t(v.x), uint8_t(v.y), uint8_t(v.z)});
        }
    const auto floorUv = [](glm::vec3 p) { return glm::vec2(p.x + 2.0f, p.z + 2.0f) / 4.0f; };
    const glm::vec3 f[4] = {{-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2}};
    const glm::vec3 w[4] = {{-2, 0, -2}, {2, 0, -2}, {2, 2, -2}, {-2, 2, -2}};
    for (const auto& corners : {std::array<int, 3>{0, 1, 2}, {0, 2, 3}}) {
        world::ImportedLightmap::Triangle floor, wall;
        for (int k = 0; k < 3; ++k) {
            floor.corners[k] = f[corners[size_t(k)]];
            floor.uv[k] = floorUv(floor.corners[k]);
            wall.corners[k] = w[corners[size_t(k)]];
            wall.vertexLight[k] = glm::vec3(50.0f * wall.corners[k].y);
        }
        floor.page = 0;
        imported.triangles.push_back(floor);
        imported.triangles.push_back(wall);
    }
    return level;
}

// What a texel at `p` must read: the page bilinearly (centres at (i + 1/2) / size, clamped at
// the edge) on the floor, the vertex light interpolated on the wall.
glm::vec3 expectedAt(glm::vec3 p) {
    if (p.z < -1.999f) return glm::vec3(50.0f * p.y);
    const float s = float(kPage);
    const float i = std::clamp((p.x + 2.0f) / 4.0f * s - 0.5f, 0.0f, s - 1.0f);
    const float j = std::clamp((p.z + 2.0f) / 4.0f * s - 0.5f, 0.0f, s - 1.0f);
    return pageValue(i, j);
}

TEST(ImportedLightmap, EveryTexelReadsTheSourcesLightWhereItLies) {
    const world::SourceLevel source = importedLevel();
    const BakeResult r = bakeLevel(source, test::fastBakeOptions());
    ASSERT_EQ(r.baked.importedTexels.size(), r.baked.texels.size());
    size_t checked = 0, floor = 0, wall = 0;
    for (const TexelSample& s : placeTexels(r.level)) {
        const world::LightmapTexel& t = r.baked.importedTexels[s.texel];
        ASSERT_EQ(t.flags, world::kLightmapTexelSampled) << s.texel;
        const glm::vec3 want = expectedAt(s.position);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(t.irradiance[c], want[c], 1e-3f * (1.0f + want[c]))
                << "texel " << s.texel << " at " << s.position.x << " " << s.position.y << " "
                << s.position.z;
        EXPECT_EQ(t.direction, glm::vec3(0.0f));
        EXPECT_EQ(t.normalWeight, 0.5f);
        ++checked;
        (s.position.z < -1.999f ? wall : floor) += 1;
    }
    EXPECT_GT(floor, 100u);
    EXPECT_GT(wall, 50u);
    // Padding around the charts is dilated like the engine's own texels: nothing is left unset
    // where the engine's bake has a value.
    for (size_t i = 0; i < r.baked.texels.size(); ++i)
        EXPECT_EQ(r.baked.importedTexels[i].flags != 0, r.baked.texels[i].flags != 0) << i;
    EXPECT_GT(checked, 0u);
}

TEST(ImportedLightmap, ShardsMergeToTheWholeBake) {
    const world::SourceLevel source = importedLevel();
    BakeOptions options = test::fastBakeOptions();
    const BakeResult whole = bakeLevel(source, options);
    std::vector<world::BakedLighting> parts;
    for (uint32_t i = 0; i < 2; ++i) {
        options.shardIndex = i;
        options.shardCount = 2;
        parts.push_back(bakeLevel(source, options).baked);
    }
    const world::BakedLighting merged = mergeBakedLighting(whole.level, parts);
    EXPECT_EQ(packageBytes(whole.level, merged, whole.textures),
              packageBytes(whole.level, whole.baked, whole.textures));
}

// As `merge` reads them: each part through its package, whose section 36 keeps only the light
// (the texels' flags come from the part's own texels, so from its range alone).
TEST(ImportedLightmap, ShardsReadFromTheirPackagesMergeToTheWholeBake) {
    const world::SourceLevel source = importedLevel();
    BakeOptions options = test::fastBakeOptions();
    const BakeResult whole = bakeLevel(source, options);
    std::vector<world::BakedLighting> parts;
    world::CompiledLevel compiled;
    for (uint32_t i = 0; i < 2; ++i) {
        options.shardIndex = i;
        options.shardCount = 2;
        const BakeResult part = bakeLevel(source, options);
        const package::PackageContents read =
            package::parsePackage(packageBytes(part.level, part.baked, part.textures), "part");
        parts.push_back(package::decodeBakedSections(read.bakedSections, read.level, "part").baked);
        compiled = read.level;
    }
    const world::BakedLighting merged = mergeBakedLighting(compiled, parts);
    EXPECT_TRUE(packageBytes(compiled, merged, whole.textures) ==
                packageBytes(whole.level, whole.baked, whole.textures));
}

TEST(ImportedLightmap, Section36RoundTripsAndIsCheckedAgainstTheAtlases) {
    BakeOptions options = test::fastBakeOptions();
    options.visibility = false;  // section 36 is then the last
    const BakeResult r = bakeLevel(importedLevel(), options);
    std::vector<package::RawSection> sections = package::encodeBakedSections(r.baked);
    ASSERT_EQ(sections.back().id, package::kSectionImportedLightmap);
    const package::BakedContents back = package::decodeBakedSections(sections, r.level, "x.olpak");
    ASSERT_EQ(back.baked.importedTexels.size(), r.baked.importedTexels.size());
    for (size_t i = 0; i < r.baked.importedTexels.size(); ++i)
        ASSERT_EQ(back.baked.importedTexels[i].irradiance, r.baked.importedTexels[i].irradiance);

    const auto errorOf = [&](const std::vector<package::RawSection>& broken) {
        return onelight::test::errorMessage(
            [&] { (void)package::decodeBakedSections(broken, r.level, "x.olpak"); });
    };
    std::vector<package::RawSection> short_ = sections;
    short_.back().bytes.resize(short_.back().bytes.size() - sizeof(package::DiskImportedTexel));
    short_.back().count -= 1;
    EXPECT_NE(errorOf(short_).find("x.olpak: section imported_lightmap: element size 12, count"),
              std::string::npos)
        << errorOf(short_);
    std::vector<package::RawSection> negative = sections;
    const float minus = -1.0f;
    std::memcpy(negative.back().bytes.data(), &minus, 4);
    EXPECT_NE(errorOf(negative).find("section imported_lightmap, record 0: irradiance[0]"),
              std::string::npos)
        << errorOf(negative);
    const std::vector<package::RawSection> alone(sections.end() - 1, sections.end());
    EXPECT_NE(errorOf(alone).find("section imported_lightmap present without baked lighting"),
              std::string::npos)
        << errorOf(alone);
}

// q3map2's ColorToBytes, step by step as q3map2 stores a light value (light_ydnar.c), unrounded:
// the reference the decoder must invert.
glm::vec3 q3map2Stored(glm::vec3 v, const world::ImportedLightEncoding& e) {
    glm::vec3 s = v * e.brightness;
    for (int c = 0; c < 3; ++c) s[c] = 255.0f * std::pow(s[c] / 255.0f, 1.0f / e.gamma);
    const float peak = std::max({s.x, s.y, s.z});
    if (e.exposure == 0.0f) {
        if (peak > 255.0f) s *= 255.0f / peak;
    } else if (peak > 0.0f) {
        s *= (1.0f - std::exp(-peak / e.exposure)) * 255.0f / peak;
    }
    s /= e.compensate;
    if (e.contrast != 1.0f) s = glm::max(e.contrast * (s - 128.0f) + 128.0f, glm::vec3(0.0f));
    if (e.srgb)
        for (int c = 0; c < 3; ++c) {
            const float x = s[c] / 255.0f;
            s[c] =
                255.0f * (x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1 / 2.4f) - 0.055f);
        }
    return s;
}

TEST(ImportedLightmap, Q3map2EncodingsDecodeToTheLightQ3map2Computed) {
    struct Case {
        const char* name;
        world::ImportedLightEncoding e;
    };
    world::ImportedLightEncoding gamma, exposure, compensate, all;
    gamma.gamma = 1.5f;
    exposure.exposure = 175.0f;
    compensate.compensate = 4.0f;
    all.brightness = 2.0f;
    all.gamma = 2.0f;
    all.exposure = 200.0f;
    all.compensate = 2.0f;
    all.contrast = 1.1f;
    all.srgb = true;
    for (const Case& k :
         {Case{"linear", {}}, Case{"gamma 1.5", gamma}, Case{"exposure 175", exposure},
          Case{"compensate 4", compensate}, Case{"all", all}}) {
        SCOPED_TRACE(k.name);
        // Values q3map2 stores without clipping (the exposure keeps every value under 255).
        for (const glm::vec3 v : {glm::vec3(1.0f, 2.0f, 3.0f), glm::vec3(20.0f, 10.0f, 5.0f),
                                  glm::vec3(60.0f, 50.0f, 40.0f), glm::vec3(0.0f)}) {
            const glm::vec3 stored = q3map2Stored(v, k.e);
            ASSERT_TRUE(glm::all(glm::lessThan(stored, glm::vec3(255.0f))));
            if (k.e.contrast > 1.0f && v == glm::vec3(0.0f)) continue;  // contrast clips to 0
            const glm::vec3 back = decodeImportedValue(stored, k.e);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], v[c], 1e-3f * (1.0f + v[c])) << c;
        }
    }
    // A channel at 255 under an exposure decodes finite, and nothing decodes negative.
    const glm::vec3 top = decodeImportedValue(glm::vec3(255.0f, 0.0f, 300.0f), exposure);
    EXPECT_TRUE(std::isfinite(top.x) && std::isfinite(top.z));
    EXPECT_GT(top.x, 175.0f * 5.0f);  // -E ln(1 - 254.5 / 255) = 6.2 E
    EXPECT_GE(decodeImportedValue(glm::vec3(0.0f), all).x, 0.0f);
}

TEST(ImportedLightmap, PagesAndVertexLightAreDecodedBeforeTheyAreRead) {
    world::SourceLevel level = importedLevel();
    level.importedLightmap.encoding.compensate = 4.0f;  // every value stored at a quarter
    const BakeResult r = bakeLevel(level, test::fastBakeOptions());
    size_t floor = 0, wall = 0;
    for (const TexelSample& s : placeTexels(r.level)) {
        const world::LightmapTexel& t = r.baked.importedTexels[s.texel];
        const glm::vec3 want = 4.0f * expectedAt(s.position);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(t.irradiance[c], want[c], 1e-3f * (1.0f + want[c])) << s.texel;
        (s.position.z < -1.999f ? wall : floor) += 1;
    }
    EXPECT_GT(floor, 100u);
    EXPECT_GT(wall, 50u);
}

}  // namespace
}  // namespace onelight::bake
