// Post-process anti-aliasing (RendererOptions::fxaa, runtime/render/shaders/fxaa.frag): on a
// sunlit yard of boxes at MSAA 1x, FXAA brings the edge pixels (where MSAA 1x and 4x differ)
// towards the 4x frame and leaves the rest of the frame as it was.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "test_scene.hpp"

namespace {

using namespace onelight;

constexpr uint32_t kWidth = 320, kHeight = 180;

test::Scene boxYard() {
    test::Scene s;
    s.materials = {{{0.7f, 0.7f, 0.68f, 1.0f}, 0.0f, 1.0f},
                   {{0.1f, 0.1f, 0.12f, 1.0f}, 0.0f, 0.6f}};
    test::addFloor(s, 0.0f, 0.0f, 12.0f, 0.0f, 0);
    test::addBox(s, {-3.0f, 0.0f, -2.0f}, {-1.5f, 2.0f, -0.5f}, 1);
    test::addBox(s, {1.0f, 0.0f, -3.0f}, {2.5f, 1.0f, -1.5f}, 1);
    test::addSphere(s, {0.0f, 0.8f, 1.0f}, 0.8f, 12, 24, 1);
    test::SceneLight sun;
    sun.type = 0;
    sun.intensity = 20000.0f;
    sun.direction = glm::normalize(glm::vec3(0.7f, -0.8f, 0.45f));
    s.lights.push_back(sun);
    return s;
}

std::vector<uint8_t> frameOf(const assets::LoadedLevel& level, uint32_t msaa, bool fxaa) {
    render::RendererOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.requestedMsaa = msaa;
    options.fxaa = fxaa;
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({1.5f, 3.5f, 7.0f}, 10.0f, -25.0f);
    const test::RenderedFrame r = test::renderOnce(level, options, inputs);
    EXPECT_EQ(r.validationErrors, 0u);
    return r.frame.rgba8;
}

TEST(PostAntiAliasing, FxaaBringsTheEdgesTowardsMsaaAndLeavesTheRest) {
    const std::string dir = test::outputDir();
    test::writeGltf(boxYard(), dir + "/fxaa_yard.gltf");
    const assets::LoadedLevel level =
        test::compileAndLoad(dir + "/fxaa_yard.gltf", dir + "/fxaa_yard.olpak");
    const std::vector<uint8_t> one = frameOf(level, 1, false), four = frameOf(level, 4, false),
                               fxaa = frameOf(level, 1, true);
    double edgeOne = 0.0, edgeFxaa = 0.0;
    size_t edges = 0, restChanged = 0, rest = 0;
    for (size_t p = 0; p < one.size() / 4; ++p) {
        if (test::worstChannelDifference(one, four, p) > 2) {
            ++edges;
            edgeOne += test::worstChannelDifference(one, four, p);
            edgeFxaa += test::worstChannelDifference(fxaa, four, p);
        } else {
            ++rest;
            restChanged += test::worstChannelDifference(fxaa, one, p) > 8 ? 1 : 0;
        }
    }
    ASSERT_GT(edges, 200u) << "the yard's edges should alias at MSAA 1x";
    std::printf(
        "[ fxaa ] %zu edge pixels: MSAA 1x %.1f/255 from the 4x frame, with FXAA %.1f; "
        "%.2f%% of the other pixels changed by more than 8/255\n",
        edges, edgeOne / double(edges), edgeFxaa / double(edges),
        100.0 * double(restChanged) / double(rest));
    EXPECT_LT(edgeFxaa, 0.8 * edgeOne);
    EXPECT_LT(double(restChanged) / double(rest), 0.01);
}

}  // namespace
