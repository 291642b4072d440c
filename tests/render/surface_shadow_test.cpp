// Skipping the shadow lookups a uniform baked mask makes moot (RendererOptions::
// skipUniformShadows, world/surface_shadow.hpp): a baked yard of 2 m floor tiles around a block
// under the sun, with a dynamic box on tiles the mask lights whole. The frame keeps the box's
// shadow and differs from the frame with every lookup on at most 0.1% of its pixels.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include <glm/gtc/matrix_transform.hpp>

#include "test_scene.hpp"

namespace {

using namespace onelight;

constexpr uint32_t kWidth = 320, kHeight = 180;

test::Scene tiledYard() {
    test::Scene s;
    s.materials = {{{0.6f, 0.6f, 0.58f, 1.0f}, 0.0f, 1.0f}, {{0.8f, 0.3f, 0.2f, 1.0f}, 0.0f, 0.5f}};
    test::addTiles(s, {-8.0f, 0.0f, 8.0f}, {8.0f, 0.0f, 8.0f}, {8.0f, 0.0f, -8.0f},
                   {-8.0f, 0.0f, -8.0f}, 8, 8, 0);
    test::addBox(s, {-1.0f, 0.0f, -1.0f}, {1.0f, 2.0f, 1.0f}, 1);
    test::addBox(s, {-0.4f, 0.0f, -0.4f}, {0.4f, 0.8f, 0.4f}, 1, true);
    test::SceneLight sun;
    sun.type = 0;
    sun.intensity = 20000.0f;
    sun.direction = glm::normalize(glm::vec3(0.6f, -0.8f, 0.3f));
    s.lights.push_back(sun);
    return s;
}

// The yard from above and behind the block, the dynamic box at `box`.
test::RenderedFrame yardFrom(const assets::LoadedLevel& level, bool skip, glm::vec3 box) {
    render::RendererOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.skipUniformShadows = skip;
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({0.0f, 7.0f, 11.0f}, 0.0f, -35.0f);
    render::DynamicTransform moved;
    for (uint32_t e = 0; e < level.level.entities.size(); ++e)
        if (level.level.entities[e].flags & world::kEntityDynamic) moved.entity = e;
    moved.worldFromObject = glm::translate(glm::mat4(1.0f), box);
    moved.primary = 0;  // the sun
    inputs.dynamicTransforms = {&moved, 1};
    const test::RenderedFrame r = test::renderOnce(level, options, inputs);
    EXPECT_EQ(r.validationErrors, 0u);
    return r;
}

TEST(SurfaceShadows, SkippingTheLookupsAUniformMaskMakesMootKeepsTheFrameAndDynamicShadows) {
    const std::string dir = test::outputDir();
    test::writeGltf(tiledYard(), dir + "/tiled_yard.gltf");
    const assets::LoadedLevel level =
        test::bakeAndLoad(dir + "/tiled_yard.gltf", dir + "/tiled_yard.olpak");
    const glm::vec3 inTheSun(-4.0f, 0.0f, 3.0f), farAway(200.0f, 0.0f, 200.0f);
    const test::RenderedFrame skipped = yardFrom(level, true, inTheSun);
    const test::RenderedFrame reference = yardFrom(level, false, inTheSun);
    const test::RenderedFrame noBox = yardFrom(level, false, farAway);
    // The mask lights some tiles whole and shadows some faces whole: both variants are drawn.
    EXPECT_TRUE(test::anyNamed(skipped.permutations, "unoccluded"));
    EXPECT_TRUE(test::anyNamed(skipped.permutations, "no-primary"));
    EXPECT_FALSE(test::anyNamed(reference.permutations, "unoccluded"));
    const double boxAndShadow = test::shareOfPixelsOff(reference.frame.rgba8, noBox.frame.rgba8);
    const double changed = test::shareOfPixelsOff(skipped.frame.rgba8, reference.frame.rgba8);
    std::printf(
        "[ surface shadows ] the dynamic box and its shadow: %.2f%% of pixels; skipping "
        "the moot lookups changes %.3f%%\n",
        100.0 * boxAndShadow, 100.0 * changed);
    // The test sees the box's shadow, which falls on tiles the mask lights whole...
    ASSERT_GT(boxAndShadow, 0.005);
    // ...and the skipped lookups keep it (without the dynamic casters' reach, the shadow goes).
    EXPECT_LE(changed, 0.001);
}

}  // namespace
