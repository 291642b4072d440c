// glTF BLEND materials (runtime/render/frame_view.cpp batchDraws, frame_passes.cpp): drawn after
// the opaque draws and the sky, back to front, each over what is behind it by its alpha. Two
// half-transparent emissive sheets, the nearer listed first, overlap in front of the sky; every
// region's radiance is the "over" composite in the right order, against the closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "test_scene.hpp"
#include "world/gltf/gltf_builder.hpp"
#include "world/images/image_files.hpp"

namespace {

using namespace onelight;
using nlohmann::json;

constexpr uint32_t kWidth = 256, kHeight = 128;
constexpr float kYfov = 0.8f;
const glm::vec3 kRed(40.0f, 0.0f, 0.0f), kBlue(0.0f, 0.0f, 40.0f);  // cd/m^2
const glm::vec3 kSky(0.0f, 20.0f, 0.0f);
constexpr float kAlpha = 0.5f;

// A sheet facing +z at depth z over x in [x0, x1], y in [-0.5, 0.5].
world::MeshData sheet(const char* name, float x0, float x1, float z, int material) {
    world::MeshData m;
    m.name = name;
    m.positions = {{x0, -0.5f, z}, {x1, -0.5f, z}, {x1, 0.5f, z}, {x0, 0.5f, z}};
    m.normals.assign(4, glm::vec3(0.0f, 0.0f, 1.0f));
    m.indices = {0, 1, 2, 0, 2, 3};
    m.material = material;
    return m;
}

int blendedEmitter(world::GltfBuilder& g, const char* name, glm::vec3 radiance) {
    const float scale = std::max({radiance.r, radiance.g, radiance.b});
    return g.addMaterial(
        {{"name", name},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {0.0f, 0.0f, 0.0f, kAlpha}},
           {"metallicFactor", 0.0f},
           {"roughnessFactor", 1.0f}}},
         {"emissiveFactor", {radiance.r / scale, radiance.g / scale, radiance.b / scale}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", scale}}}}},
         {"alphaMode", "BLEND"}});
}

// The red sheet 2 m ahead (x -1..0.3), listed first; the blue one 3 m ahead (x -0.3..1.5); the
// sky behind: uniform, or a constant sky image when `skyImage` (then the sky pass draws it).
assets::LoadedLevel sheetsLevel(bool skyImage) {
    const std::string folder = test::outputDir();
    const std::string name = skyImage ? "blend_sheets_sky_image" : "blend_sheets";
    world::GltfBuilder g;
    const int red = blendedEmitter(g, "red", kRed);
    const int blue = blendedEmitter(g, "blue", kBlue);
    g.addNode({{"name", "red"}, {"mesh", g.addMesh(sheet("red", -1.0f, 0.3f, -2.0f, red))}});
    g.addNode({{"name", "blue"}, {"mesh", g.addMesh(sheet("blue", -0.3f, 1.5f, -3.0f, blue))}});
    json sky = {kSky.r, kSky.g, kSky.b};
    if (skyImage) {
        std::vector<float> green;
        for (int i = 0; i < 8 * 4; ++i) green.insert(green.end(), {0.0f, 1.0f, 0.0f});
        world::writeHdrFile(folder + "/" + name + ".hdr", 8, 4, green);
        sky = {{"image", name + ".hdr"}, {"scale", {kSky.g, kSky.g, kSky.g}}};
    }
    g.addNode({{"name", "settings"}, {"extras", {{"onelight", {{"sky", sky}}}}}});
    const std::string gltf = g.write(folder, name);
    return test::compileAndLoad(gltf, folder + "/" + name + ".olpak");
}

// The frame's linear radiance where the camera's ray through world point p (in front of it)
// lands.
glm::vec3 radianceAt(const render::CapturedFrame& frame, glm::vec3 p) {
    const float t = std::tan(0.5f * kYfov);
    const float aspect = float(kWidth) / float(kHeight);
    const float ndcX = p.x / (-p.z * t * aspect), ndcY = p.y / (-p.z * t);
    const uint32_t col = uint32_t((ndcX * 0.5f + 0.5f) * float(kWidth));
    const uint32_t row = uint32_t((0.5f - ndcY * 0.5f) * float(kHeight));
    const float* px = &frame.linearRgba[(size_t(row) * kWidth + col) * 4];
    return {px[0], px[1], px[2]};
}

void expectNear(glm::vec3 got, glm::vec3 want, const char* where) {
    for (int c = 0; c < 3; ++c)  // RGBA16F: 11 bits of mantissa, one rounding per blend
        EXPECT_NEAR(got[c], want[c], 0.01f * std::max(want[c], 1.0f)) << where << ", channel " << c;
}

void checkSheets(bool skyImage) {
    const assets::LoadedLevel level = sheetsLevel(skyImage);
    render::RendererOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.placeholderAmbientLux = 0.0f;  // the sheets' radiance is their emission alone
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({0.0f, 0.0f, 0.0f}, 0.0f, 0.0f);
    inputs.camera.yfov = kYfov;
    const test::RenderedFrame r = test::renderOnce(level, options, inputs);
    EXPECT_EQ(r.validationErrors, 0u);
    const float a = kAlpha;
    const glm::vec3 sky = radianceAt(r.frame, {0.0f, 0.45f, -1.0f});  // above both sheets
    const glm::vec3 redOnly = radianceAt(r.frame, {-0.7f, 0.0f, -2.0f});
    const glm::vec3 blueOnly = radianceAt(r.frame, {1.2f, 0.0f, -3.0f});
    const glm::vec3 both = radianceAt(r.frame, {0.0f, 0.0f, -2.0f});
    std::printf(
        "[ blend ] %s: sky %.2f %.2f %.2f; red over sky %.2f %.2f %.2f; blue over sky "
        "%.2f %.2f %.2f; red over blue over sky %.2f %.2f %.2f\n",
        skyImage ? "sky image" : "uniform sky", double(sky.r), double(sky.g), double(sky.b),
        double(redOnly.r), double(redOnly.g), double(redOnly.b), double(blueOnly.r),
        double(blueOnly.g), double(blueOnly.b), double(both.r), double(both.g), double(both.b));
    expectNear(sky, kSky, "the sky");
    expectNear(redOnly, a * kRed + (1.0f - a) * kSky, "red over the sky");
    expectNear(blueOnly, a * kBlue + (1.0f - a) * kSky, "blue over the sky");
    // Back to front: the blue sheet over the sky, then the red one over both (drawn in the
    // level's order, red first, the red would be halved: 10 instead of 20 cd/m^2).
    expectNear(both, a * kRed + (1.0f - a) * (a * kBlue + (1.0f - a) * kSky),
               "red over blue over the sky");
}

TEST(BlendedMaterials, GoOverTheSkyAndEachOtherBackToFront) {
    checkSheets(false);
}

TEST(BlendedMaterials, GoOverASkyImageTheSkyPassDrawsFirst) {
    checkSheets(true);
}

}  // namespace
