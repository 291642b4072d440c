// Forward pipelines specialized by what their draws need (RendererOptions::specializeDraws:
// the texture slots a material fills, a surface's primary light and its type, where its secondary
// lighting comes from, a frame's effect lights) draw the same displayed bits as the general
// pipelines that choose at run time, on
// levels whose draws need each choice: textured and untextured materials, surfaces with and
// without a primary, lightmapped static surfaces and a grid-lit dynamic object, effect lights on.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "bumpy_floor.hpp"
#include "render/camera.hpp"
#include "test_scene.hpp"

namespace onelight::test {
namespace {

constexpr uint32_t kWidth = 192, kHeight = 108;

// Two floors, glossy and emissive blocks, a dynamic box, a baked omni, and an omni over one end
// and a spot over the other that are the primaries (every static surface then has one: the
// compiler gives unlit surfaces the first primary) or baked too (no surface has a primary).
Scene twoEndsScene(bool primaryLight) {
    Scene s;
    s.materials = {{{0.5f, 0.5f, 0.5f, 1.0f}, 0.0f, 1.0f},  // floor
                   {{0.6f, 0.3f, 0.2f, 1.0f}, 0.0f, 0.4f},  // block, glossy
                   {{0.7f, 0.7f, 0.7f, 1.0f}, 0.0f, 1.0f},  // dynamic box
                   {{0.2f, 0.2f, 0.2f, 1.0f}, 0.0f, 1.0f, {1.0f, 0.5f, 0.2f}, 20.0f}};  // glow
    addFloor(s, -6.0f, 0.0f, 4.0f, 0.0f, 0);
    addFloor(s, 6.0f, 0.0f, 4.0f, 0.0f, 0);
    addBox(s, {-7.0f, 0.0f, -1.0f}, {-5.0f, 1.5f, 1.0f}, 1);
    addBox(s, {5.0f, 0.0f, -1.0f}, {7.0f, 1.0f, 1.0f}, 1);
    addBox(s, {8.0f, 0.0f, 2.0f}, {8.5f, 0.5f, 2.5f}, 3);
    addBox(s, {-0.3f, 0.0f, -0.3f}, {0.3f, 0.6f, 0.3f}, 2, true);
    SceneLight primary;
    primary.type = 1;
    primary.intensity = 400.0f;
    primary.range = 5.0f;
    primary.position = {-6.0f, 3.0f, 0.0f};
    if (!primaryLight) primary.role = "baked";
    s.lights.push_back(primary);
    SceneLight spot;  // over the far end: a spot primary's surfaces there
    spot.type = 2;
    spot.intensity = 2000.0f;
    spot.position = {6.0f, 4.0f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.innerCone = 0.4f;
    spot.outerCone = 0.7f;
    if (!primaryLight) spot.role = "baked";
    s.lights.push_back(spot);
    SceneLight baked;
    baked.type = 1;
    baked.intensity = 300.0f;
    baked.color = {1.0f, 0.8f, 0.6f};
    baked.position = {6.0f, 2.5f, -2.0f};
    baked.role = "baked";
    s.lights.push_back(baked);
    return s;
}

render::RendererOptions smallFrame(bool specialize) {
    render::RendererOptions o;
    o.width = kWidth;
    o.height = kHeight;
    o.specializeDraws = specialize;
    // The exact optimisation alone: skipping the shadows a uniform mask makes moot is not exact
    // (surface_shadow_test.cpp measures it).
    o.skipUniformShadows = false;
    return o;
}

// The frame with specialized pipelines and with general ones: the same bits, PNG and linear.
void expectSameFrame(const assets::LoadedLevel& level, const render::FrameInputs& inputs,
                     std::vector<std::string>& permutations) {
    const RenderedFrame special = renderOnce(level, smallFrame(true), inputs);
    const RenderedFrame general = renderOnce(level, smallFrame(false), inputs);
    EXPECT_EQ(special.validationErrors + general.validationErrors, 0u);
    ASSERT_EQ(special.frame.rgba8.size(), general.frame.rgba8.size());
    size_t differing = 0;
    for (size_t i = 0; i < special.frame.rgba8.size(); ++i)
        differing += special.frame.rgba8[i] != general.frame.rgba8[i];
    EXPECT_EQ(differing, 0u);
    // The linear frame (RGBA16F) likewise, but for one half-float step on a rare value: LLVM
    // may fuse a multiply-add in one pipeline and not in the other (seen: 1 channel of 1 pixel
    // in 20736, 7e-4 relative, in the level without primaries), which the display never shows.
    ASSERT_EQ(special.frame.linearRgba.size(), general.frame.linearRgba.size());
    size_t apart = 0;
    for (size_t i = 0; i < special.frame.linearRgba.size(); ++i) {
        const float a = special.frame.linearRgba[i], b = general.frame.linearRgba[i];
        if (a == b) continue;
        ++apart;
        EXPECT_LE(std::fabs(a - b), std::ldexp(std::fabs(b), -10)) << "value " << i;
    }
    EXPECT_LE(apart, special.frame.linearRgba.size() / 10000);
    permutations = special.permutations;
    for (const std::string& p : permutations) std::printf("[ specialized ] %s\n", p.c_str());
}

TEST(RenderSpecialization, DrawsWithAndWithoutPrimariesLightmapsAndGridLightChangeNoPixel) {
    std::vector<std::string> seen;
    for (const bool primaryLight : {true, false}) {
        const std::string name = primaryLight ? "two_ends" : "two_ends_baked";
        const std::string gltf = outputDir() + "/" + name + ".gltf";
        writeGltf(twoEndsScene(primaryLight), gltf);
        const assets::LoadedLevel level =
            bakeAndLoad(gltf, outputDir() + "/" + name + ".olpak", "--texels-per-metre 4");
        ASSERT_TRUE(level.hasBakedLighting);
        uint32_t entity = world::kNoIndex;
        for (uint32_t e = 0; e < level.level.entities.size(); ++e)
            if (level.level.entities[e].flags & world::kEntityDynamic) entity = e;
        ASSERT_NE(entity, world::kNoIndex);

        render::FrameInputs inputs;
        inputs.camera = render::cameraFromYawPitch({0.0f, 6.0f, 11.0f}, 0.0f, -30.0f);
        // The dynamic box near the end omni, drawn with it as its primary when it is one; one
        // gun flash and the flashlight.
        const render::DynamicTransform moved{
            entity, glm::translate(glm::mat4(1.0f), glm::vec3(-3.0f, 0.0f, 2.0f)),
            primaryLight ? 0u : world::kNoIndex};
        inputs.dynamicTransforms = {&moved, 1};
        inputs.effects.omniCount = 1;
        inputs.effects.omni[0] = {{2.0f, 0.5f, 2.0f}, {1.0f, 0.6f, 0.3f}, 4.0f, 5.0f};
        inputs.effects.spotOn = true;
        inputs.effects.spot.position = inputs.camera.position;
        inputs.effects.spot.direction = render::forwardOf(inputs.camera);
        inputs.effects.spot.intensity = 2000.0f;
        inputs.effects.spot.range = 30.0f;
        inputs.effects.spot.innerCone = 0.25f;
        inputs.effects.spot.outerCone = 0.45f;
        std::vector<std::string> permutations;
        expectSameFrame(level, inputs, permutations);
        seen.insert(seen.end(), permutations.begin(), permutations.end());
    }
    // Each choice was specialized in a frame compared.
    EXPECT_TRUE(test::anyNamed(seen, "no-primary"));
    EXPECT_TRUE(test::anyNamed(seen, " point"));
    EXPECT_TRUE(test::anyNamed(seen, " spot"));
    EXPECT_TRUE(test::anyNamed(seen, " lightmap"));
    EXPECT_TRUE(test::anyNamed(seen, " lightmap edges"));       // a baked shadow edge's surfaces...
    EXPECT_TRUE(test::anyNamed(seen, " lightmap no-effects"));  // ...and the others
    EXPECT_TRUE(test::anyNamed(seen, " object"));
    EXPECT_TRUE(test::anyNamed(seen, "textures=none"));
    // A dynamic object is drawn by its primary's type, as a static surface is (the box under the
    // point primary, and with none), not by a pipeline that evaluates every type under a mask.
    EXPECT_TRUE(test::anyNamed(seen, " point object"));
    EXPECT_TRUE(test::anyNamed(seen, " no-primary object"));
}

TEST(RenderSpecialization, MaterialsWithSomeTextureSlotsChangeNoPixel) {
    // A bump-mapped glossy floor (normal map, and the cavity map and facet table made from it)
    // under a low sun.
    const std::string gltf = writeBumpyGlossyFloor(outputDir() + "/specialized_bumps", "black_ops",
                                                   float(kWidth) / float(kHeight));
    const assets::LoadedLevel level =
        bakeAndLoad(gltf, outputDir() + "/specialized_bumps.olpak", "--texels-per-metre 1");
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromLevel(level.level.cameras.at(0));
    std::vector<std::string> permutations;
    expectSameFrame(level, inputs, permutations);
    // The floor's slots: no base colour texture, so its fetch is compiled out.
    EXPECT_TRUE(
        test::anyNamed(permutations, "textures=metal-rough,normal,cavity,facets directional"));
}

}  // namespace
}  // namespace onelight::test
