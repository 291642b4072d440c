// The texture stage (bake/textures/texture_stage.hpp) on small levels built in code, their
// images embedded PNGs: plain mips against brute-force footprint means, sRGB averaged in linear
// light, sharing, the normal and metallic-roughness pair (factors and scale folded, gloss mips by
// each method), cavity, sizes, determinism across thread counts and the errors.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "bake/textures/facet_table.hpp"
#include "bake/textures/normal_gloss_mips.hpp"
#include "bake/textures/texture_stage.hpp"
#include "shading.hpp"
#include "world/error.hpp"

// Internal to this file (static), so a program may link another user of stb_image_write.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace onelight::test {
namespace {

using world::GlossMipMethod;
using world::kNoIndex;
using world::ProcessedTexture;
using world::ProcessedTextures;
using world::TexelFormat;

constexpr double kPi = 3.14159265358979323846;
constexpr uint16_t kClampToEdge = 33071;

struct Rgba8 {
    int width = 0, height = 0;
    std::vector<uint8_t> texels;  // RGBA, rows top to bottom
    uint8_t* at(int x, int y) {
        return texels.data() + 4 * (size_t(y) * size_t(width) + size_t(x));
    }
    const uint8_t* at(int x, int y) const {
        return texels.data() + 4 * (size_t(y) * size_t(width) + size_t(x));
    }
};

Rgba8 uniformImage(int width, int height, uint8_t r, uint8_t g, uint8_t b, uint8_t a = 255) {
    Rgba8 image{width, height, {}};
    for (int i = 0; i < width * height; ++i) image.texels.insert(image.texels.end(), {r, g, b, a});
    return image;
}

Rgba8 randomImage(int width, int height, uint32_t seed) {
    std::mt19937 random(seed);
    Rgba8 image{width, height, std::vector<uint8_t>(size_t(width) * size_t(height) * 4)};
    for (uint8_t& t : image.texels) t = uint8_t(random() & 0xff);
    return image;
}

std::vector<uint8_t> encodePng(const Rgba8& image) {
    std::vector<uint8_t> png;
    auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<uint8_t>*>(context);
        const auto* bytes = static_cast<const uint8_t*>(data);
        out->insert(out->end(), bytes, bytes + size);
    };
    EXPECT_TRUE(stbi_write_png_to_func(append, &png, image.width, image.height, 4,
                                       image.texels.data(), image.width * 4));
    return png;
}

// A level of materials, textures and embedded images, no geometry.
struct LevelBuilder {
    world::SourceLevel level;
    LevelBuilder() { level.sourcePath = "stage_test.gltf"; }
    uint32_t image(const Rgba8& pixels, const std::string& name) {
        world::Image image;
        image.name = name;
        image.mimeType = "image/png";
        image.encodedBytes = encodePng(pixels);
        level.images.push_back(std::move(image));
        return uint32_t(level.images.size() - 1);
    }
    uint32_t texture(uint32_t image, world::Sampler sampler = {}) {
        level.textures.push_back({image, sampler});
        return uint32_t(level.textures.size() - 1);
    }
    uint32_t texture(const Rgba8& pixels, const std::string& name, world::Sampler sampler = {}) {
        return texture(image(pixels, name), sampler);
    }
    world::Material& material(const std::string& name) {
        world::Material m;
        m.name = name;
        level.materials.push_back(m);
        return level.materials.back();
    }
};

const uint8_t* texelOf(const ProcessedTexture& t, uint32_t level, int x, int y) {
    size_t offset = 0;
    for (uint32_t k = 0; k < level; ++k)
        offset += size_t(bake::mipSize(int(t.width), int(k))) *
                  size_t(bake::mipSize(int(t.height), int(k))) * world::bytesPerTexel(t.format);
    const size_t w = size_t(bake::mipSize(int(t.width), int(level)));
    return t.texels.data() + offset + (size_t(y) * w + size_t(x)) * world::bytesPerTexel(t.format);
}

void expectWellFormed(const ProcessedTextures& out) {
    for (const ProcessedTexture& t : out.textures) {
        EXPECT_EQ(t.mipCount, world::fullMipCount(t.width, t.height)) << t.name;
        EXPECT_EQ(t.texels.size(), world::mipChainBytes(t.format, t.width, t.height, t.mipCount))
            << t.name;
    }
}

// A tangent-space normal encoded as glTF does (0.5 + 0.5 n, rounded).
void putNormal(uint8_t* t, glm::dvec3 n) {
    n = glm::normalize(n);
    for (int c = 0; c < 3; ++c) t[c] = uint8_t(std::lround(255.0 * (0.5 + 0.5 * n[c])));
    t[3] = 255;
}

// An egg crate of `period` texels with slopes up to `slope`, as a normal map.
Rgba8 eggCrate(int size, int period, double slope) {
    Rgba8 image{size, size, std::vector<uint8_t>(size_t(size) * size_t(size) * 4)};
    const double k = 2.0 * kPi / period, amplitude = slope / k;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double u = k * (x + 0.5), v = k * (y + 0.5);
            const double dhdx = amplitude * k * std::cos(u) * std::sin(v);
            const double dhdy = amplitude * k * std::sin(u) * std::cos(v);
            putNormal(image.at(x, y), {-dhdx, -dhdy, 1.0});
        }
    return image;
}

TEST(TextureStage, PlainMipsAreTheFootprintMeansAndMipZeroIsTheImage) {
    // 3x5 and 7x2: odd sizes fold their leftover texel into the last footprint.
    for (const glm::ivec2 size : {glm::ivec2(3, 5), glm::ivec2(7, 2), glm::ivec2(1, 1)}) {
        LevelBuilder b;
        const Rgba8 pixels = randomImage(size.x, size.y, 7);
        const uint32_t t = b.texture(pixels, "random");
        world::Material& m = b.material("plain");
        m.baseColorTexture = t;
        m.occlusionTexture = t;
        const ProcessedTextures out = bake::processLevelTextures(b.level, GlossMipMethod::kWwii);
        expectWellFormed(out);
        ASSERT_EQ(out.textures.size(), 2u);
        const ProcessedTexture& srgb = out.textures[out.materials[0].baseColor];
        const ProcessedTexture& linear = out.textures[out.materials[0].occlusion];
        EXPECT_EQ(srgb.format, TexelFormat::kRgba8Srgb);
        EXPECT_EQ(linear.format, TexelFormat::kRgba8Unorm);
        for (const ProcessedTexture* p : {&srgb, &linear}) {
            ASSERT_EQ(p->width, uint32_t(size.x));
            ASSERT_EQ(p->height, uint32_t(size.y));
            EXPECT_TRUE(std::equal(pixels.texels.begin(), pixels.texels.end(), p->texels.begin()));
        }
        for (uint32_t level = 1; level < srgb.mipCount; ++level)
            for (int y = 0; y < bake::mipSize(size.y, int(level)); ++y)
                for (int x = 0; x < bake::mipSize(size.x, int(level)); ++x) {
                    const bake::TexelRange fx = bake::mipFootprint(size.x, int(level), x);
                    const bake::TexelRange fy = bake::mipFootprint(size.y, int(level), y);
                    double sums[4] = {}, linearSums[4] = {}, count = 0.0;
                    for (int py = fy.begin; py < fy.end; ++py)
                        for (int px = fx.begin; px < fx.end; ++px) {
                            const uint8_t* p = pixels.at(px, py);
                            for (int c = 0; c < 4; ++c) {
                                sums[c] += p[c];
                                linearSums[c] +=
                                    c < 3 ? double(glsl::srgbDecode(float(p[c]) / 255.0f)) : p[c];
                            }
                            count += 1.0;
                        }
                    const uint8_t* s = texelOf(srgb, level, x, y);
                    const uint8_t* l = texelOf(linear, level, x, y);
                    for (int c = 0; c < 4; ++c) {
                        EXPECT_EQ(l[c], std::lround(sums[c] / count));
                        const double expected =
                            c < 3 ? 255.0 * double(glsl::srgbEncode(float(linearSums[c] / count)))
                                  : linearSums[c] / count;
                        EXPECT_LE(std::abs(double(s[c]) - expected), 0.5 + 1e-3)
                            << "level " << level << " texel " << x << "," << y << " channel " << c;
                    }
                }
    }
}

TEST(TextureStage, SrgbIsAveragedInLinearLight) {
    LevelBuilder b;
    Rgba8 checker = uniformImage(2, 2, 0, 0, 0);
    for (int i : {1, 2}) {
        uint8_t* t = checker.texels.data() + 4 * i;
        t[0] = t[1] = t[2] = 255;
    }
    const uint32_t t = b.texture(checker, "checker");
    b.material("checker").baseColorTexture = t;
    b.level.materials[0].occlusionTexture = t;
    const ProcessedTextures out = bake::processLevelTextures(b.level, GlossMipMethod::kWwii);
    const uint8_t* srgb = texelOf(out.textures[out.materials[0].baseColor], 1, 0, 0);
    const uint8_t* linear = texelOf(out.textures[out.materials[0].occlusion], 1, 0, 0);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(srgb[c], 188);    // srgbEncode(0.5) = 0.7354
        EXPECT_EQ(linear[c], 128);  // 127.5, to nearest
    }
    EXPECT_EQ(srgb[3], 255);
}

// A cut-out grate (bars of one colour, fully opaque; holes transparent black) on a MASK material:
// every mip's colour is the bars', its alpha their coverage. A plain mean darkened the bars towards
// the holes' black wherever a mip reached over both (to 44% of their linear colour at the coarsest
// mips here), and with them the light a grate reflects: the reference's box behind the textured
// room's grate read 14% under Cycles', which reads its texture without mips. Colour under no
// coverage keeps the plain mean (black here). An OPAQUE material's texture, whose alpha glTF
// ignores (and a Quake 3 texture may use for something else), and a linear texture keep plain
// means.
TEST(TextureStage, ACutOutColoursMipsAreTheColourOfWhatCoversThem) {
    LevelBuilder b;
    Rgba8 grate = uniformImage(64, 64, 0, 0, 0, 0);
    int bars = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            if (x % 32 < 8 || y % 32 < 8) {
                uint8_t* t = grate.at(x, y);
                t[0] = 150, t[1] = 150, t[2] = 160, t[3] = 255;
                ++bars;
            }
    const uint32_t t = b.texture(grate, "grate");
    world::Material& cutOut = b.material("grate");
    cutOut.baseColorTexture = t;
    cutOut.occlusionTexture = t;
    cutOut.alphaMode = world::AlphaMode::kMask;
    b.material("opaque").baseColorTexture = t;
    const ProcessedTextures out = bake::processLevelTextures(b.level, GlossMipMethod::kWwii);
    const ProcessedTexture& colour = out.textures[out.materials[0].baseColor];
    const ProcessedTexture& linear = out.textures[out.materials[0].occlusion];
    const ProcessedTexture& opaque = out.textures[out.materials[1].baseColor];
    // Every texel, the holes' too (their colour from what covers nearby, fillClearTexels: a
    // filter across a bar's edge reads the bar's colour on both sides, no dark fringe), and mip
    // 0's holes with them; the alpha stays the coverage.
    for (uint32_t level = 0; level < colour.mipCount; ++level) {
        const int size = bake::mipSize(64, int(level));
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const uint8_t* s = texelOf(colour, level, x, y);
                if (level == 0) {
                    EXPECT_EQ(s[3], grate.at(x, y)[3]);
                }
                EXPECT_EQ(s[0], 150) << "level " << level << " texel " << x << "," << y;
                EXPECT_EQ(s[1], 150);
                EXPECT_EQ(s[2], 160);
            }
    }
    const uint8_t* top = texelOf(colour, colour.mipCount - 1, 0, 0);
    EXPECT_EQ(top[3], std::lround(255.0 * bars / (64.0 * 64.0)));  // 112: 43.75% covered
    // The linear copy of the same image averages its bytes plainly: 150 x 0.4375 = 65.6; the
    // opaque material's colour its linear light: 0.305 x 0.4375 = 0.133, sRGB 102.
    EXPECT_EQ(texelOf(linear, linear.mipCount - 1, 0, 0)[0], 66);
    EXPECT_EQ(texelOf(opaque, opaque.mipCount - 1, 0, 0)[0], 102);
}

TEST(TextureStage, ATextureIsMadeOncePerColourSpace) {
    LevelBuilder b;
    const uint32_t t = b.texture(randomImage(4, 4, 1), "shared");
    b.material("a").baseColorTexture = t;
    b.material("b").baseColorTexture = t;
    b.level.materials[1].emissiveTexture = t;  // also sRGB: the same
    b.material("c").occlusionTexture = t;      // linear: another
    const ProcessedTextures out = bake::processLevelTextures(b.level, GlossMipMethod::kWwii);
    ASSERT_EQ(out.materials.size(), 3u);
    ASSERT_EQ(out.textures.size(), 2u);
    EXPECT_EQ(out.materials[0].baseColor, out.materials[1].baseColor);
    EXPECT_EQ(out.materials[1].emissive, out.materials[1].baseColor);
    EXPECT_NE(out.materials[2].occlusion, out.materials[0].baseColor);
    EXPECT_EQ(out.materials[2].baseColor, kNoIndex);
    EXPECT_FALSE(out.materials[0].factorsFolded);
    const bake::TextureStageReport report = bake::textureStageReport(out);
    ASSERT_EQ(report.textures.size(), 2u);
    EXPECT_EQ(report.textures[0].name, "shared base colour");
    EXPECT_EQ(report.totalBytes, 2u * (64u + 16u + 4u));
}

TEST(TextureStage, ANormalMapWithoutMetallicRoughnessGetsOneFromTheFactors) {
    LevelBuilder b;
    world::Material& m = b.material("flat");
    m.normalTexture = b.texture(uniformImage(8, 8, 128, 128, 255), "flat normal");
    m.roughness = 0.3f;
    m.metallic = 0.7f;
    const ProcessedTextures out = bake::processLevelTextures(b.level, GlossMipMethod::kWwii);
    expectWellFormed(out);
    const world::MaterialTextureSlots& slots = out.materials[0];
    EXPECT_TRUE(slots.factorsFolded);
    ASSERT_NE(slots.metallicRoughness, kNoIndex);
    ASSERT_NE(slots.normal, kNoIndex);
    ASSERT_NE(slots.cavity, kNoIndex);
    const ProcessedTexture& mr = out.textures[slots.metallicRoughness];
    EXPECT_EQ(mr.format, TexelFormat::kRgba8Unorm);
    EXPECT_EQ(mr.width, 8u);
    for (uint32_t level = 0; level < mr.mipCount; ++level) {
        const uint8_t* t = texelOf(mr, level, 0, 0);
        EXPECT_EQ(t[0], 255);                                      // no occlusion packed
        EXPECT_NEAR(t[1], 0.3 * 255.0, 1.0) << "level " << level;  // a flat map keeps it
        EXPECT_NEAR(t[2], 0.7 * 255.0, 1.0);
        EXPECT_EQ(t[3], t[1]);  // the texels' own roughness: a flat map's is all of it
    }
    EXPECT_TRUE(slots.baseRoughnessInAlpha);
    EXPECT_TRUE(slots.slopeKurtosisInNormalAlpha);
    // A flat map's slopes do not spread: the neutral kurtosis 2, stored as (2 - 1) / 2.
    const ProcessedTexture& normal = out.textures[slots.normal];
    for (uint32_t level = 0; level < normal.mipCount; ++level)
        EXPECT_EQ(texelOf(normal, level, 0, 0)[3], 128) << "level " << level;
    const ProcessedTexture& cavity = out.textures[slots.cavity];
    EXPECT_EQ(cavity.format, TexelFormat::kR8Unorm);
    for (uint8_t c : cavity.texels) EXPECT_EQ(c, 255);  // nothing rises above a flat map
}

// Roughness (G) of the metallic-roughness mips of a bumpy map at roughness factor `factor`.
// The metallic-roughness texel (0, 0) of each mip of an egg-crate pair: G, or A with channel 3.
std::vector<double> deepestRoughness(
    GlossMipMethod method, double factor,
    world::MaterialClass materialClass = world::MaterialClass::kDielectric, int channel = 1) {
    LevelBuilder b;
    world::Material& m = b.material("bumps");
    m.normalTexture = b.texture(eggCrate(32, 8, 0.3), "egg crate");
    m.roughness = float(factor);
    m.metallic = 0.0f;
    m.materialClass = materialClass;
    bake::TextureStageOptions options;
    options.cavityScan.radius = 4.0f;
    const ProcessedTextures out = bake::processLevelTextures(b.level, method, options);
    const ProcessedTexture& mr = out.textures[out.materials[0].metallicRoughness];
    std::vector<double> g;
    for (uint32_t level = 0; level < mr.mipCount; ++level)
        g.push_back(double(texelOf(mr, level, 0, 0)[channel]) / 255.0);
    return g;
}

TEST(TextureStage, TheNormalTexturesAlphaIsTheSlopesKurtosis) {
    // An egg crate's slopes over whole bumps: kurtosis 1.25 (normal_gloss_mips.hpp), stored as
    // (1.25 - 1) / 2 in the normal texture's A at the mips that cover whole bumps (8-texel
    // bumps: level 3 down); level 0 spreads nothing (2, stored as 128).
    LevelBuilder b;
    world::Material& m = b.material("bumps");
    m.normalTexture = b.texture(eggCrate(32, 8, 0.3), "egg crate");
    const ProcessedTextures out = bake::processLevelTextures(b.level, GlossMipMethod::kClean);
    ASSERT_TRUE(out.materials[0].slopeKurtosisInNormalAlpha);
    const ProcessedTexture& normal = out.textures[out.materials[0].normal];
    EXPECT_EQ(texelOf(normal, 0, 0, 0)[3], 128);
    for (uint32_t level = 3; level < normal.mipCount; ++level)
        EXPECT_NEAR(texelOf(normal, level, 0, 0)[3], 0.125 * 255.0, 4.0) << "level " << level;
}

TEST(TextureStage, ASpecularNormalMapGetsItsFacetTable) {
    // The whole tile's facets (bake/textures/facet_table.hpp), made with the pair: one R16 float
    // table per pair, shared by the materials that share it; a Lambert material has no lobe to
    // shape and gets none. Its mip 0 is facetTable of the map read through its sampler.
    LevelBuilder b;
    const uint32_t bumps = b.texture(eggCrate(32, 8, 0.3), "egg crate");
    for (const char* name : {"glossy", "glossy too"}) {
        world::Material& m = b.material(name);
        m.normalTexture = bumps;
        m.roughness = 0.2f;
        m.materialClass = world::MaterialClass::kDielectric;
    }
    world::Material& lambert = b.material("matte");
    lambert.normalTexture = bumps;
    lambert.materialClass = world::MaterialClass::kLambert;
    const ProcessedTextures out = bake::processLevelTextures(b.level, GlossMipMethod::kClean);
    expectWellFormed(out);
    const uint32_t facets = out.materials[0].facets;
    ASSERT_NE(facets, kNoIndex);
    EXPECT_EQ(out.materials[1].facets, facets);
    EXPECT_EQ(out.materials[2].facets, kNoIndex);
    const ProcessedTexture& table = out.textures[facets];
    EXPECT_EQ(table.format, TexelFormat::kR16Float);
    EXPECT_EQ(table.width, uint32_t(bake::kFacetTableSize));
    EXPECT_EQ(table.sampler.wrapS, kClampToEdge);
    EXPECT_NE(table.name.find("facets"), std::string::npos) << table.name;
    // The table of the stage's own level 0 (the map's normals, the roughness factor's gloss).
    bake::NormalGlossLevel level0;
    level0.width = level0.height = 32;
    const ProcessedTexture& normal = out.textures[out.materials[0].normal];
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const uint8_t* t = texelOf(normal, 0, x, y);
            level0.normals.push_back(glsl::normal_fromTangentSpace(
                glm::vec3(t[0], t[1], t[2]) / 255.0f, 1.0f, glm::vec3(0.0f, 0.0f, 1.0f),
                glm::vec3(1.0f, 0.0f, 0.0f), 1.0f));
            level0.gloss.push_back(glsl::gloss_fromRoughness(0.2f));
        }
    const bake::FacetTable expected = bake::facetTable(level0, true, true);
    const ProcessedTexture made = bake::facetTableTexture(expected, table.name);
    EXPECT_EQ(made.texels, table.texels);
}

TEST(TextureStage, BumpsBecomeRoughnessInTheDeeperMipsUnlessBlitted) {
    const double factor = 0.2;
    const std::vector<double> blit = deepestRoughness(GlossMipMethod::kBlit, factor);
    ASSERT_EQ(blit.size(), 6u);
    for (double g : blit) EXPECT_NEAR(g, factor, 1.5 / 255.0);
    for (GlossMipMethod method :
         {GlossMipMethod::kWwii, GlossMipMethod::kBlackOps, GlossMipMethod::kClean}) {
        const std::vector<double> g = deepestRoughness(method, factor);
        // A keeps the texels' own roughness, the factor, at every mip: the bumps are G's alone.
        for (double a : deepestRoughness(method, factor, world::MaterialClass::kDielectric, 3))
            EXPECT_NEAR(a, factor, 1.5 / 255.0) << "method " << int(method);
        EXPECT_NEAR(g[0], factor, 1.0 / 255.0);
        // Mips 3 and on average whole periods of the bumps (slopes up to 17 degrees).
        for (size_t level = 3; level < g.size(); ++level)
            EXPECT_GT(g[level], factor + 0.1) << "method " << int(method) << " level " << level;
        // A Lambert-only material has no lobe to widen: its mips are blitted.
        for (double lambert : deepestRoughness(method, factor, world::MaterialClass::kLambert))
            EXPECT_NEAR(lambert, factor, 1.5 / 255.0);
    }
}

TEST(TextureStage, NormalsRoundTripAndTheScaleIsFolded) {
    LevelBuilder b;
    std::mt19937 random(3);
    std::uniform_real_distribution<double> uniform(-0.6, 0.6);
    Rgba8 normals{6, 5, std::vector<uint8_t>(6 * 5 * 4)};
    for (int y = 0; y < normals.height; ++y)
        for (int x = 0; x < normals.width; ++x)
            putNormal(normals.at(x, y), {uniform(random), uniform(random), 1.0});
    const uint32_t t = b.texture(normals, "random normals");
    b.material("scale 1").normalTexture = t;
    b.material("scale 0").normalTexture = t;
    b.level.materials[1].normalScale = 0.0f;
    b.material("scale 1 again").normalTexture = t;  // the same inputs: the same textures
    b.material("scale 1, smoother").normalTexture = t;
    b.level.materials[3].roughness = 0.5f;  // another gloss: its own pair, the same cavity
    const ProcessedTextures out = bake::processLevelTextures(b.level, GlossMipMethod::kWwii);
    expectWellFormed(out);
    const ProcessedTexture& unscaled = out.textures[out.materials[0].normal];
    const ProcessedTexture& flat = out.textures[out.materials[1].normal];
    EXPECT_NE(out.materials[0].normal, out.materials[1].normal);
    EXPECT_EQ(unscaled.format, TexelFormat::kRgba8Unorm);
    for (size_t i = 0; i < normals.texels.size(); ++i) {
        if (i % 4 == 3) {  // A: the slopes' kurtosis, the neutral 2 at level 0 (stored as 128)
            EXPECT_EQ(unscaled.texels[i], 128) << i;
            continue;
        }
        EXPECT_LE(std::abs(int(unscaled.texels[i]) - int(normals.texels[i])), 1) << i;
    }
    for (size_t i = 0; i < flat.texels.size(); i += 4) {
        EXPECT_EQ(flat.texels[i + 0], 128);
        EXPECT_EQ(flat.texels[i + 1], 128);
        EXPECT_EQ(flat.texels[i + 2], 255);
        EXPECT_EQ(flat.texels[i + 3], 128);  // slopes that do not spread: the neutral kurtosis 2
    }
    // The scaled normals' cavity is the flat one's; the unscaled map's is not.
    for (uint8_t c : out.textures[out.materials[1].cavity].texels) EXPECT_EQ(c, 255);
    EXPECT_NE(out.materials[0].cavity, out.materials[1].cavity);
    EXPECT_EQ(out.materials[2].normal, out.materials[0].normal);
    EXPECT_EQ(out.materials[2].metallicRoughness, out.materials[0].metallicRoughness);
    EXPECT_EQ(out.materials[2].cavity, out.materials[0].cavity);
    EXPECT_NE(out.materials[3].metallicRoughness, out.materials[0].metallicRoughness);
    EXPECT_EQ(out.materials[3].cavity, out.materials[0].cavity);
    EXPECT_EQ(out.textures.size(), 2u + 3u * 3u);  // two cavities, three pairs and their facets
}

TEST(TextureStage, AMetallicRoughnessOfAnotherSizeIsResampledBilinearly) {
    // G 0 then 255 across two texels, onto a normal map of four: centres at -0.25, 0.25, 0.75
    // and 1.25 source texels.
    Rgba8 ramp = uniformImage(2, 1, 255, 0, 255);
    ramp.at(1, 0)[1] = 255;
    for (const uint16_t wrap : {uint16_t(kClampToEdge), uint16_t(10497)}) {
        LevelBuilder b;
        world::Material& m = b.material("ramp");
        m.normalTexture = b.texture(uniformImage(4, 1, 128, 128, 255), "flat");
        m.metallicRoughnessTexture = b.texture(ramp, "ramp", {0, 0, wrap, wrap});
        m.roughness = 1.0f;
        const ProcessedTextures out = bake::processLevelTextures(b.level, GlossMipMethod::kWwii);
        const ProcessedTexture& mr = out.textures[out.materials[0].metallicRoughness];
        const int first = wrap == kClampToEdge ? 0 : 64;  // repeat reads texel 1 left of 0
        const int expected[4] = {first, 64, 191, wrap == kClampToEdge ? 255 : 191};
        for (int x = 0; x < 4; ++x) EXPECT_EQ(texelOf(mr, 0, x, 0)[1], expected[x]) << x;
    }
}

TEST(TextureStage, PackedOcclusionAndAResampledMetallicRoughness) {
    LevelBuilder b;
    // ORM at half the normal map's size: R occlusion, G roughness, B metallic.
    Rgba8 orm = uniformImage(2, 3, 100, 200, 50);
    const uint32_t ormTexture = b.texture(orm, "orm", {0, 0, kClampToEdge, kClampToEdge});
    world::Material& m = b.material("orm");
    m.normalTexture = b.texture(uniformImage(4, 6, 128, 128, 255), "flat");
    m.metallicRoughnessTexture = ormTexture;
    m.occlusionTexture = ormTexture;
    m.roughness = 0.5f;
    m.metallic = 1.0f;
    m.materialClass = world::MaterialClass::kFull;
    const ProcessedTextures out = bake::processLevelTextures(b.level, GlossMipMethod::kBlackOps);
    expectWellFormed(out);
    const world::MaterialTextureSlots& slots = out.materials[0];
    EXPECT_EQ(slots.occlusion, slots.metallicRoughness);
    const ProcessedTexture& mr = out.textures[slots.metallicRoughness];
    EXPECT_EQ(mr.width, 4u);
    EXPECT_EQ(mr.height, 6u);
    EXPECT_EQ(mr.sampler.wrapS, out.textures[slots.normal].sampler.wrapS);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 4; ++x) {
            const uint8_t* t = texelOf(mr, 0, x, y);
            EXPECT_EQ(t[0], 100);
            EXPECT_NEAR(t[1], 0.5 * 200.0, 1.0);
            EXPECT_EQ(t[2], 50);
        }
    EXPECT_EQ(out.textures.size(), 4u);  // cavity, normal, metallic-roughness, facets
}

TEST(TextureStage, TinyAndOddSizes) {
    LevelBuilder b;
    world::Material& m = b.material("tiny");
    m.baseColorTexture = b.texture(uniformImage(1, 1, 10, 20, 30, 40), "1x1");
    m.normalTexture = b.texture(eggCrate(5, 5, 0.5), "5x5 bumps");
    m.metallicRoughnessTexture = b.texture(randomImage(3, 5, 9), "3x5 mr");
    world::Material& n = b.material("odd");
    n.normalTexture = b.texture(uniformImage(1, 7, 128, 128, 255), "1x7");
    n.emissiveTexture = b.texture(randomImage(3, 5, 4), "3x5 emissive");
    for (GlossMipMethod method :
         {GlossMipMethod::kBlit, GlossMipMethod::kBlackOps, GlossMipMethod::kWwii}) {
        const ProcessedTextures out = bake::processLevelTextures(b.level, method);
        expectWellFormed(out);
        const ProcessedTexture& base = out.textures[out.materials[0].baseColor];
        EXPECT_EQ(base.mipCount, 1u);
        EXPECT_EQ(base.texels, (std::vector<uint8_t>{10, 20, 30, 40}));
        EXPECT_EQ(out.textures[out.materials[1].normal].mipCount, 3u);
        EXPECT_EQ(out.textures[out.materials[1].cavity].height, 7u);
        EXPECT_EQ(out.textures[out.materials[0].metallicRoughness].width, 5u);
    }
}

world::SourceLevel mixedLevel() {
    LevelBuilder b;
    world::Material& m = b.material("stone");
    m.baseColorTexture = b.texture(randomImage(37, 23, 5), "stone colour");
    m.normalTexture = b.texture(eggCrate(48, 12, 0.4), "stone normal");
    m.metallicRoughnessTexture = b.texture(randomImage(24, 24, 6), "stone mr");
    m.occlusionTexture = m.metallicRoughnessTexture;
    m.normalScale = 1.5f;
    world::Material& n = b.material("tiles");
    n.normalTexture = b.texture(eggCrate(33, 11, 0.2), "tiles normal", {0, 0, kClampToEdge, 33648});
    n.roughness = 0.4f;
    return b.level;
}

TEST(TextureStage, TheSameBytesOnOneThreadAndOnTwo) {
    const world::SourceLevel level = mixedLevel();
    ProcessedTextures one, two;
    {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
        one = bake::processLevelTextures(level, GlossMipMethod::kWwii);
    }
    {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
        two = bake::processLevelTextures(level, GlossMipMethod::kWwii);
    }
    expectWellFormed(one);
    ASSERT_EQ(one.textures.size(), two.textures.size());
    for (size_t i = 0; i < one.textures.size(); ++i)
        EXPECT_EQ(one.textures[i].texels, two.textures[i].texels) << one.textures[i].name;
}

TEST(TextureStage, TheSkyImageIsNoMaterialTexture) {
    LevelBuilder b;
    const uint32_t sky = b.image(uniformImage(2, 2, 1, 2, 3), "sky");
    b.level.skyImage = sky;
    b.material("sky reader").baseColorTexture = b.texture(sky);
    b.level.materials[0].normalTexture = b.level.materials[0].baseColorTexture;
    const ProcessedTextures out = bake::processLevelTextures(b.level, GlossMipMethod::kWwii);
    EXPECT_TRUE(out.textures.empty());
    EXPECT_EQ(out.materials[0].baseColor, kNoIndex);
    EXPECT_EQ(out.materials[0].normal, kNoIndex);
    EXPECT_FALSE(out.materials[0].factorsFolded);
}

void expectErrorNaming(const world::SourceLevel& level, const std::vector<std::string>& parts,
                       const bake::TextureStageOptions& options = {}) {
    try {
        (void)bake::processLevelTextures(level, GlossMipMethod::kWwii, options);
        FAIL() << "no error";
    } catch (const world::Error& e) {
        const std::string message = e.what();
        for (const std::string& part : parts)
            EXPECT_NE(message.find(part), std::string::npos) << message;
    }
}

TEST(TextureStage, ErrorsNameTheLevelAndTheImage) {
    LevelBuilder b;
    b.material("fine").baseColorTexture = b.texture(uniformImage(2, 2, 1, 2, 3), "fine");
    const uint32_t corrupt = b.texture(uniformImage(2, 2, 1, 2, 3), "broken bricks");
    b.level.images[b.level.textures[corrupt].image].encodedBytes.resize(20);
    b.material("broken").normalTexture = corrupt;
    expectErrorNaming(b.level, {"stage_test.gltf", "image 1 'broken bricks'"});

    world::SourceLevel missing = b.level;
    missing.images[1].encodedBytes.clear();
    missing.images[1].uri = "no/such/file.png";
    expectErrorNaming(missing, {"stage_test.gltf", "'broken bricks'", "no/such/file.png"});

    // The budget: a 64x64 normal map's working set is past 100 kB.
    LevelBuilder big;
    big.material("big").normalTexture = big.texture(uniformImage(64, 64, 128, 128, 255), "big");
    bake::TextureStageOptions small;
    small.memoryLimitBytes = 100000;
    expectErrorNaming(big.level, {"stage_test.gltf", "'big'", "64x64"}, small);
}

TEST(TextureStage, TheBudgetHoldsWhatTexturesKeepPlusOneWorkingSet) {
    // Two 64x64 normal maps: each needs 64^2 * kNormalMapBytesPerTexel = 0.92 MB while it is
    // made and keeps 92839 bytes (normal, metallic-roughness, cavity: 49149; its facet table,
    // 128x128 R16 float with its mips: 43690) after.
    LevelBuilder b;
    b.material("a").normalTexture = b.texture(eggCrate(64, 16, 0.2), "a");
    b.material("b").normalTexture = b.texture(eggCrate(64, 8, 0.2), "b");
    bake::TextureStageOptions options;
    options.cavityScan.radius = 4.0f;
    options.memoryLimitBytes = uint64_t(64 * 64 * bake::kNormalMapBytesPerTexel) + 92839 + 100;
    const ProcessedTextures out =
        bake::processLevelTextures(b.level, GlossMipMethod::kWwii, options);
    EXPECT_EQ(bake::textureStageReport(out).totalBytes, 2u * 92839u);
    options.memoryLimitBytes -= 200;
    expectErrorNaming(b.level, {"image 1 'b'"}, options);
}

TEST(TextureStage, APairWithCavityIsTimed) {
    LevelBuilder b;
    world::Material& m = b.material("big");
    const int size = 256;  // the timing below is printed for a 1024^2 pair in the report
    m.normalTexture = b.texture(eggCrate(size, 32, 0.4), "normal");
    m.metallicRoughnessTexture = b.texture(randomImage(size, size, 2), "mr");
    const auto start = std::chrono::steady_clock::now();
    const ProcessedTextures out = bake::processLevelTextures(b.level, GlossMipMethod::kWwii);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    expectWellFormed(out);
    std::printf("%dx%d normal + metallic-roughness with cavity: %.3f s\n", size, size, seconds);
    for (const bake::ProcessedTextureRow& row : bake::textureStageReport(out).textures)
        std::printf("  %-28s %-10s %5ux%-5u %2u mips %9llu bytes\n", row.name.c_str(),
                    bake::texelFormatName(row.format), row.width, row.height, row.mipCount,
                    static_cast<unsigned long long>(row.bytes));
}

}  // namespace
}  // namespace onelight::test
