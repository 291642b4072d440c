// Alpha-masked shadow casters (runtime/render/shadows.hpp, ShadowDraw): a MASK grate whose
// texture is open on a quarter of its area, under a sun, seen from below the grate on the
// floor its shadow falls on. Near the camera (the runtime map) and beyond the runtime radius (the
// baked shadow mask) the floor gets the same share of the sun, the grate's open fraction; the
// runtime shadow draws the holes themselves; a grate that casts no shadow is left out of it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtx/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "test_scene.hpp"
#include "world/gltf/gltf_builder.hpp"
#include "world/images/image_files.hpp"

namespace {

using namespace onelight;
using nlohmann::json;

constexpr uint32_t kSize = 128;
constexpr float kYfov = 1.0f;
constexpr double kOpenFraction = 0.25;
// The grate's texture repeats every 0.5 m; the camera sees exactly one period of its shadow.
constexpr float kPeriod = 0.5f;
const float kCameraHeight = 0.5f * kPeriod / std::tan(0.5f * kYfov);
const glm::vec3 kSunTravel = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));

// 8 x 8 texels of 4 x 4 cells, each a 2 x 2 hole (alpha 0) framed by two-texel bars (alpha 1).
void writeGrateTexture(const std::string& path) {
    std::vector<uint8_t> rgba;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const bool bar = x % 4 < 2 || y % 4 < 2;
            rgba.insert(rgba.end(), {200, 200, 200, uint8_t(bar ? 255 : 0)});
        }
    world::writePngFile(path, 8, 8, rgba);
}

world::MeshData quad(const char* name, float half, float height, int material, bool uv) {
    world::MeshData m;
    m.name = name;
    m.positions = {
        {-half, height, -half}, {half, height, -half}, {half, height, half}, {-half, height, half}};
    m.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
    if (uv)
        for (const glm::vec3& p : m.positions)
            m.uv0.push_back({(p.x + half) / kPeriod, (p.z + half) / kPeriod});
    m.indices = {0, 2, 1, 0, 3, 2};
    m.material = material;
    return m;
}

// A 6 m floor (albedo 0.5) and a 2 m grate 1 m above it, double-sided, MASK with cutoff 0.5
// (nearest filtering: the holes' edges are the texels'), under a 10 klx sun.
std::string writeGrateLevel(const std::string& folder) {
    writeGrateTexture(folder + "/grate.png");
    world::GltfBuilder g;
    g.document()["images"] = json::array({{{"uri", "grate.png"}}});
    g.document()["samplers"] = json::array({{{"magFilter", 9728}, {"minFilter", 9728}}});
    g.document()["textures"] = json::array({{{"source", 0}, {"sampler", 0}}});
    const int floor = g.addMaterial({{"name", "floor"},
                                     {"pbrMetallicRoughness",
                                      {{"baseColorFactor", {0.5f, 0.5f, 0.5f, 1.0f}},
                                       {"metallicFactor", 0.0f},
                                       {"roughnessFactor", 1.0f}}}});
    const int grate = g.addMaterial({{"name", "grate"},
                                     {"pbrMetallicRoughness",
                                      {{"baseColorTexture", {{"index", 0}}},
                                       {"metallicFactor", 0.0f},
                                       {"roughnessFactor", 1.0f}}},
                                     {"alphaMode", "MASK"},
                                     {"alphaCutoff", 0.5f},
                                     {"doubleSided", true}});
    g.addNode({{"name", "floor"}, {"mesh", g.addMesh(quad("floor", 3.0f, 0.0f, floor, false))}});
    g.addNode({{"name", "grate"}, {"mesh", g.addMesh(quad("grate", 1.0f, 1.0f, grate, true))}});
    const int sun = g.addLight({{"type", "directional"}, {"intensity", 10000.0f}});
    const glm::quat turn = glm::rotation(glm::vec3(0.0f, 0.0f, -1.0f), kSunTravel);
    g.addNode({{"name", "sun"},
               {"rotation", {turn.x, turn.y, turn.z, turn.w}},
               {"extensions", {{"KHR_lights_punctual", {{"light", sun}}}}}});
    return g.write(folder, "masked_grate");
}

// The frame's linear luminance per pixel, looking straight down from kCameraHeight at the floor
// point whose sun ray crosses the grate's centre.
std::vector<double> luminanceOf(const assets::LoadedLevel& level, float shadowRadius,
                                uint32_t featuresOff) {
    render::RendererOptions options;
    options.width = options.height = kSize;
    options.featuresOff = featuresOff;
    if (shadowRadius > 0.0f) {
        options.shadowRadius = shadowRadius;
        options.shadowBand = 0.5f * shadowRadius;
    }
    const glm::vec3 floorPoint = glm::vec3(0.0f, 1.0f, 0.0f) + kSunTravel * (1.0f / -kSunTravel.y);
    render::FrameInputs inputs;
    inputs.camera =
        render::cameraFromYawPitch(floorPoint + glm::vec3(0.0f, kCameraHeight, 0.0f), 0.0f, -90.0f);
    inputs.camera.yfov = kYfov;
    const test::RenderedFrame r = test::renderOnce(level, options, inputs);
    EXPECT_EQ(r.validationErrors, 0u);
    std::vector<double> lum;
    for (size_t i = 0; i + 3 < r.frame.linearRgba.size(); i += 4)
        lum.push_back(0.2126 * double(r.frame.linearRgba[i]) +
                      0.7152 * double(r.frame.linearRgba[i + 1]) +
                      0.0722 * double(r.frame.linearRgba[i + 2]));
    return lum;
}

struct Openness {
    double mean = 0.0;              // the floor's share of the sun over one period of the grate
    double open = 0.0, shut = 0.0;  // pixels over 90% and under 10% of the sun
};

// Per pixel, the primary's part of the frame over the unshadowed primary's.
Openness opennessOf(const std::vector<double>& frame, const std::vector<double>& noPrimary,
                    const std::vector<double>& unshadowed) {
    Openness o;
    double sun = 0.0, lit = 0.0;
    for (size_t i = 0; i < frame.size(); ++i) {
        const double full = unshadowed[i] - noPrimary[i];
        const double share = (frame[i] - noPrimary[i]) / std::max(full, 1e-12);
        sun += frame[i] - noPrimary[i];
        lit += full;
        o.open += share > 0.9 ? 1.0 : 0.0;
        o.shut += share < 0.1 ? 1.0 : 0.0;
    }
    o.mean = sun / std::max(lit, 1e-12);
    o.open /= double(frame.size());
    o.shut /= double(frame.size());
    return o;
}

TEST(MaskedShadowCasters, AGrateLetsTheSunThroughItsHolesAsTheBakedMaskDoes) {
    const std::string folder = test::outputDir();
    const assets::LoadedLevel level =
        test::bakeAndLoad(writeGrateLevel(folder), folder + "/masked_grate.olpak");
    const uint32_t kNoShadow = uint32_t(glsl::FEATURE_RUNTIME_SHADOW | glsl::FEATURE_BAKED_SHADOW);
    const std::vector<double> noPrimary = luminanceOf(level, 0.0f, uint32_t(glsl::FEATURE_PRIMARY));
    const std::vector<double> unshadowed = luminanceOf(level, 0.0f, kNoShadow);
    // The camera is 0.46 m from the floor: within the 40 m radius the runtime map, within a
    // 0.2 m one the baked mask.
    const Openness runtime = opennessOf(luminanceOf(level, 0.0f, 0), noPrimary, unshadowed);
    const Openness baked = opennessOf(luminanceOf(level, 0.2f, 0), noPrimary, unshadowed);
    std::printf(
        "[ masked casters ] open fraction %.3f; runtime shadow %.3f (%.0f%% of pixels "
        "open, %.0f%% shut); baked mask %.3f\n",
        kOpenFraction, runtime.mean, 100.0 * runtime.open, 100.0 * runtime.shut, baked.mean);
    // The runtime map resolves the 12.5 cm holes with 1.1 cm texels: their share of one period
    // is the open fraction but for the filter's and the offsets' blur along the holes' edges.
    EXPECT_NEAR(runtime.mean, kOpenFraction, 0.03);
    EXPECT_GT(runtime.open, 0.5 * kOpenFraction);
    EXPECT_GT(runtime.shut, 0.5 * (1.0 - kOpenFraction));
    // The baked mask, coarser than the holes, keeps their mean.
    EXPECT_NEAR(baked.mean, runtime.mean, 0.06);

    // A grate that casts no shadow (world::Material::castsShadows false, a Quake 3 translucent
    // surface) is left out of the runtime map: with the baked mask off (it was baked with the
    // grate casting) the floor gets the whole sun, where the casting grate's map gives a quarter.
    const uint32_t kNoBakedShadow = uint32_t(glsl::FEATURE_BAKED_SHADOW);
    assets::LoadedLevel passed = level;
    for (world::Material& m : passed.level.materials)
        if (m.name == "grate") m.castsShadows = false;
    const Openness none =
        opennessOf(luminanceOf(passed, 0.0f, kNoBakedShadow), noPrimary, unshadowed);
    const Openness mapOnly =
        opennessOf(luminanceOf(level, 0.0f, kNoBakedShadow), noPrimary, unshadowed);
    std::printf("[ masked casters ] runtime map alone: %.3f; the grate casting no shadow: %.3f\n",
                mapOnly.mean, none.mean);
    EXPECT_NEAR(mapOnly.mean, kOpenFraction, 0.05);
    EXPECT_GT(none.mean, 0.97);
}

}  // namespace
