// Golden frames: small scenes rendered headless at 320x180 and compared, tonemapped and 8-bit,
// with tests/render/golden/NAME.png under the tolerance stated in tests/support/golden.hpp. On
// failure NAME.png and NAME_diff.png are written to the test output folder;
// ONELIGHT_UPDATE_GOLDENS=1 rewrites the goldens instead.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "golden.hpp"
#include "test_scene.hpp"
#include "world/dynamic_primary.hpp"
#include "world/images/image_files.hpp"
#include "world/light_model.hpp"

namespace {

using namespace onelight;

constexpr uint32_t kWidth = 320, kHeight = 180;
void compareWithGolden(const std::string& name, const render::CapturedFrame& frame) {
    const std::string out = test::outputDir() + "/" + name;
    world::writePngFile(out + ".png", frame.width, frame.height, frame.rgba8);
    const test::GoldenResult result = test::compareWithGolden(
        frame.rgba8, frame.width, frame.height,
        std::string(ONELIGHT_GOLDEN_DIR) + "/" + name + ".png", out + "_diff.png");
    EXPECT_TRUE(result.ok) << name << ": " << result.message;
}

render::RendererOptions smallFrame() {
    render::RendererOptions options;
    options.width = kWidth;
    options.height = kHeight;
    return options;
}

render::EffectSpot flashlightAt(const render::Camera& camera, float intensity) {
    render::EffectSpot spot;
    spot.position = camera.position;
    spot.direction = render::forwardOf(camera);
    spot.intensity = intensity;
    spot.innerCone = 0.2f;
    spot.outerCone = 0.45f;
    return spot;
}

// A sunlit yard: floor, boxes of the four material classes, a sphere and a moved dynamic box.
test::Scene sunScene() {
    test::Scene s;
    s.materials = {{{0.7f, 0.7f, 0.68f, 1.0f}, 0.0f, 1.0f},  // lambert floor
                   {{0.8f, 0.3f, 0.2f, 1.0f}, 0.0f, 0.4f},   // dielectric
                   {{0.95f, 0.8f, 0.5f, 1.0f}, 1.0f, 0.3f},  // metal
                   {{0.3f, 0.6f, 0.9f, 1.0f}, 0.5f, 0.5f}};  // full
    test::addFloor(s, 0.0f, 0.0f, 12.0f, 0.0f, 0);
    test::addBox(s, {-3.0f, 0.0f, -2.0f}, {-1.5f, 2.0f, -0.5f}, 1);
    test::addBox(s, {1.0f, 0.0f, -3.0f}, {2.5f, 1.0f, -1.5f}, 2);
    test::addSphere(s, {0.0f, 0.8f, 1.0f}, 0.8f, 12, 24, 3);
    test::addBox(s, {-0.4f, 0.0f, -0.4f}, {0.4f, 0.8f, 0.4f}, 1, true);
    test::SceneLight sun;
    sun.type = 0;
    sun.intensity = 20000.0f;
    sun.color = {1.0f, 0.95f, 0.85f};
    sun.direction = glm::normalize(glm::vec3(0.7f, -0.8f, 0.45f));
    s.lights.push_back(sun);
    return s;
}

// A room-less night: a spot and an omni primary with shadows, four gun-flash omnis.
test::Scene spotOmniScene() {
    test::Scene s;
    s.materials = {{{0.6f, 0.6f, 0.6f, 1.0f}, 0.0f, 0.8f}, {{0.2f, 0.7f, 0.3f, 1.0f}, 0.0f, 0.35f}};
    test::addFloor(s, 0.0f, 0.0f, 10.0f, 0.0f, 0);
    test::addBox(s, {-2.5f, 0.0f, -1.0f}, {-1.5f, 1.5f, 0.0f}, 1);
    test::addBox(s, {1.5f, 0.0f, -2.0f}, {2.5f, 1.0f, -1.0f}, 1);
    test::SceneLight spot;
    spot.type = 2;
    spot.intensity = 400.0f;
    spot.position = {-4.0f, 4.0f, 2.0f};
    spot.direction = glm::normalize(glm::vec3(0.8f, -1.0f, -0.6f));
    spot.innerCone = 0.35f;
    spot.outerCone = 0.6f;
    s.lights.push_back(spot);
    test::SceneLight omni;
    omni.type = 1;
    omni.intensity = 60.0f;
    omni.range = 15.0f;
    omni.color = {1.0f, 0.7f, 0.4f};
    omni.position = {2.0f, 2.2f, 0.5f};
    s.lights.push_back(omni);
    return s;
}

assets::LoadedLevel generated(const std::string& name, const test::Scene& scene) {
    const std::string gltf = test::outputDir() + "/" + name + ".gltf";
    test::writeGltf(scene, gltf);
    return test::compileAndLoad(gltf, test::outputDir() + "/" + name + ".olpak");
}

// The glTF sample `name` of the shared assets (CI provides them; tests skip without them).
std::string sharedGltf(const std::string& name) {
    return std::string(ONELIGHT_SHARED_ASSETS) + "/" + name + "/glTF/" + name + ".gltf";
}

assets::LoadedLevel shared(const std::string& name) {
    return test::compileAndLoad(sharedGltf(name), test::outputDir() + "/" + name + ".olpak");
}

TEST(RenderGolden, NormalTangentTestWithFlashlight) {
    if (!std::filesystem::exists(sharedGltf("NormalTangentTest")))
        GTEST_SKIP() << "the shared assets are absent: " << sharedGltf("NormalTangentTest");
    const assets::LoadedLevel level = shared("NormalTangentTest");
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({0.2f, 0.1f, 2.4f}, 4.0f, -2.0f);
    inputs.effects.spotOn = true;
    inputs.effects.spot = flashlightAt(inputs.camera, 3.0f);
    const test::RenderedFrame r = test::renderOnce(level, smallFrame(), inputs);
    EXPECT_EQ(r.validationErrors, 0u);
    compareWithGolden("normal_tangent_test", r.frame);
}

TEST(RenderGolden, TextureSettingsTest) {
    if (!std::filesystem::exists(sharedGltf("TextureSettingsTest")))
        GTEST_SKIP() << "the shared assets are absent: " << sharedGltf("TextureSettingsTest");
    const assets::LoadedLevel level = shared("TextureSettingsTest");
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({0.0f, 0.0f, 11.0f}, 0.0f, 0.0f);
    const test::RenderedFrame r = test::renderOnce(level, smallFrame(), inputs);
    EXPECT_EQ(r.validationErrors, 0u);
    compareWithGolden("texture_settings_test", r.frame);
}

TEST(RenderGolden, SunShadowsMaterialClassesAndDynamicObject) {
    const assets::LoadedLevel level = generated("sun_yard", sunScene());
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({1.5f, 3.5f, 7.0f}, 10.0f, -25.0f);
    render::DynamicTransform moved;
    uint32_t dynamicEntities = 0;
    for (uint32_t e = 0; e < level.level.entities.size(); ++e)
        if (level.level.entities[e].flags & world::kEntityDynamic) {
            moved.entity = e;
            ++dynamicEntities;
        }
    ASSERT_EQ(dynamicEntities, 1u);
    const glm::vec3 place(2.5f, 0.0f, 1.5f);
    moved.worldFromObject = glm::translate(glm::mat4(1.0f), place);
    // The game's pick for a level without a grid: the brightest primary, unshadowed.
    std::vector<uint32_t> candidates;
    for (uint32_t l = 0; l < level.level.lights.size(); ++l)
        if (level.level.lights[l].role == world::LightRole::kPrimary) candidates.push_back(l);
    world::DynamicPrimary pick;
    world::updateDynamicPrimary(pick, place, candidates, [&](uint32_t light, glm::vec3 p) {
        return world::unshadowedIlluminance(level.level.lights[light], p);
    });
    ASSERT_NE(pick.primary, world::kNoIndex);
    moved.primary = pick.primary;
    inputs.dynamicTransforms = {&moved, 1};
    const test::RenderedFrame r = test::renderOnce(level, smallFrame(), inputs);
    EXPECT_EQ(r.validationErrors, 0u);
    EXPECT_GT(r.stats.shadowViewsRendered, 0u);
    compareWithGolden("sun_yard", r.frame);
}

// The depth pre-pass only rejects hidden samples earlier: the sunlit yard (four material
// classes, a dynamic box) is the same frame, bit for bit, with it and without it.
TEST(RenderGolden, TheDepthPrepassChangesNoPixel) {
    const assets::LoadedLevel level = generated("sun_yard_prepass", sunScene());
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({-2.0f, 3.0f, 9.0f}, -10.0f, -15.0f);
    render::RendererOptions with = smallFrame(), without = smallFrame();
    with.depthPrepass = true;
    without.depthPrepass = false;
    const test::RenderedFrame a = test::renderOnce(level, with, inputs);
    const test::RenderedFrame b = test::renderOnce(level, without, inputs);
    EXPECT_EQ(a.validationErrors, 0u);
    EXPECT_EQ(b.validationErrors, 0u);
    ASSERT_EQ(a.frame.rgba8.size(), b.frame.rgba8.size());
    EXPECT_TRUE(a.frame.rgba8 == b.frame.rgba8);
    EXPECT_TRUE(a.frame.linearRgba == b.frame.linearRgba);
}

// createRenderer's warm-up frame (every pipeline drawn once, with each material's textures, and
// one light's shadows) leaves no trace in the first frame shown: the same bits with and without.
TEST(RenderGolden, TheWarmUpFrameChangesNoPixel) {
    const assets::LoadedLevel level = generated("spot_omni_warm", spotOmniScene());
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({0.0f, 4.0f, 7.5f}, 0.0f, -30.0f);
    inputs.effects.omniCount = 1;
    inputs.effects.omni[0] = {{0.0f, 0.3f, 3.0f}, {0.3f, 0.5f, 1.0f}, 6.0f, 5.0f};
    render::RendererOptions warm = smallFrame(), cold = smallFrame();
    warm.warmUp = true;
    cold.warmUp = false;
    const test::RenderedFrame a = test::renderOnce(level, warm, inputs);
    const test::RenderedFrame b = test::renderOnce(level, cold, inputs);
    EXPECT_EQ(a.validationErrors + b.validationErrors, 0u);
    EXPECT_EQ(a.stats.shadowViewsRendered, 6u);  // the spot's view was the warm-up's
    EXPECT_EQ(b.stats.shadowViewsRendered, 7u);
    ASSERT_EQ(a.frame.rgba8.size(), b.frame.rgba8.size());
    EXPECT_TRUE(a.frame.rgba8 == b.frame.rgba8);
    EXPECT_TRUE(a.frame.linearRgba == b.frame.linearRgba);
}

TEST(RenderGolden, SpotAndOmniShadowsWithEffectLights) {
    const assets::LoadedLevel level = generated("spot_omni", spotOmniScene());
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({0.0f, 4.0f, 7.5f}, 0.0f, -30.0f);
    const glm::vec3 flashes[4] = {
        {-3.0f, 0.5f, 2.0f}, {0.0f, 0.3f, 3.0f}, {3.5f, 0.5f, 2.5f}, {0.0f, 1.0f, -3.0f}};
    const glm::vec3 colours[4] = {
        {1.0f, 0.5f, 0.2f}, {0.3f, 0.5f, 1.0f}, {1.0f, 1.0f, 0.3f}, {1.0f, 0.2f, 0.8f}};
    inputs.effects.omniCount = 4;
    for (int i = 0; i < 4; ++i) inputs.effects.omni[i] = {flashes[i], colours[i], 6.0f, 5.0f};
    const test::RenderedFrame r = test::renderOnce(level, smallFrame(), inputs);
    EXPECT_EQ(r.validationErrors, 0u);
    // The omni's six views; the spot's one was rendered by createRenderer's warm-up frame (the
    // shadow pipeline drawn once, a spot's static casters kept).
    EXPECT_EQ(r.stats.shadowViewsRendered, 6u);
    compareWithGolden("spot_omni", r.frame);
}

// The same frame twice, from two renderers, is bit-identical (PNG and linear HDR), and the
// second frame of a renderer reuses the cached static shadow maps.
TEST(RenderDeterminism, SameFrameTwiceIsBitIdentical) {
    const assets::LoadedLevel level = generated("sun_yard_twice", sunScene());
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({1.5f, 3.5f, 7.0f}, 10.0f, -25.0f);
    const test::RenderedFrame a = test::renderOnce(level, smallFrame(), inputs);
    const test::RenderedFrame b = test::renderOnce(level, smallFrame(), inputs, 2);
    EXPECT_EQ(a.validationErrors + b.validationErrors, 0u);
    EXPECT_EQ(a.stats.shadowViewsRendered, 3u);  // the sun's three cascades, once...
    EXPECT_EQ(b.stats.shadowViewsRendered, 0u);  // ...then cached: the second frame redraws none
    ASSERT_EQ(a.frame.rgba8.size(), b.frame.rgba8.size());
    EXPECT_TRUE(a.frame.rgba8 == b.frame.rgba8);
    EXPECT_EQ(std::memcmp(a.frame.linearRgba.data(), b.frame.linearRgba.data(),
                          a.frame.linearRgba.size() * sizeof(float)),
              0);
}

}  // namespace

namespace {

// The baked-lighting interface with its placeholder textures fetched gives the frame of the
// fetch-free placeholder permutation (a level without baked lighting): the interface is neutral.
TEST(RenderBakedInterface, PlaceholderTexturesMatchConstantAmbient) {
    const assets::LoadedLevel level = generated("sun_yard_placeholders", sunScene());
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({1.5f, 3.5f, 7.0f}, 10.0f, -25.0f);
    render::RendererOptions options = smallFrame();
    const test::RenderedFrame constant = test::renderOnce(level, options, inputs);
    options.samplePlaceholders = true;
    const test::RenderedFrame fetched = test::renderOnce(level, options, inputs);
    EXPECT_EQ(constant.validationErrors + fetched.validationErrors, 0u);
    ASSERT_EQ(constant.frame.rgba8.size(), fetched.frame.rgba8.size());
    int worst = 0;
    for (size_t i = 0; i < constant.frame.rgba8.size(); ++i)
        worst =
            std::max(worst, std::abs(int(constant.frame.rgba8[i]) - int(fetched.frame.rgba8[i])));
    std::printf("[ baked interface ] worst difference %d/255\n", worst);
    EXPECT_LE(worst, 2);  // half-float texels of the placeholders vs float constants
}

}  // namespace
