// Window backend under Xvfb: `onelight` opens a GLFW window, renders three frames into its
// swapchain, and a screenshot of the swapchain image (read back in-app) matches the offscreen
// frame of a separate headless run of the same view. ctest runs this under
// `xvfb-run -a -s '-screen 0 1280x720x24'`; without xvfb-run the test is skipped.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "test_scene.hpp"
#include "world/images/image_decode.hpp"
#include "world/images/image_files.hpp"

namespace {

using namespace onelight;

// A floor and an orange box under a sun, written to DIR/NAME.gltf and compiled to
// DIR/NAME.olpak; returns the compiler's exit code.
int compileWindowLevel(const std::string& dir, const std::string& name) {
    test::Scene scene;
    scene.materials = {{{0.7f, 0.7f, 0.7f, 1.0f}, 0.0f, 0.9f},
                       {{0.8f, 0.4f, 0.2f, 1.0f}, 0.0f, 0.4f}};
    test::addFloor(scene, 0.0f, 0.0f, 8.0f, 0.0f, 0);
    test::addBox(scene, {-1.0f, 0.0f, -1.0f}, {1.0f, 1.5f, 1.0f}, 1);
    test::SceneLight sun;
    sun.intensity = 10000.0f;
    sun.direction = glm::normalize(glm::vec3(0.6f, -0.8f, 0.4f));
    scene.lights.push_back(sun);
    std::filesystem::create_directories(dir);
    const std::string gltf = dir + "/" + name + ".gltf";
    test::writeGltf(scene, gltf);
    return test::compileLevel(gltf, dir + "/" + name + ".olpak");
}

TEST(RenderWindow, ScreenshotMatchesOffscreenFrame) {
    if (!ONELIGHT_HAVE_XVFB_RUN) GTEST_SKIP() << "xvfb-run is not installed";
    ASSERT_NE(std::getenv("DISPLAY"), nullptr)
        << "run under xvfb-run (see tests/render/CMakeLists.txt)";

    const std::string dir = test::outputDir() + "/window";
    ASSERT_EQ(compileWindowLevel(dir, "window_level"), 0);

    const std::vector<std::string> view = {dir + "/window_level.olpak", "--size", "320x180",
                                           "--camera", "2,3,6,15,-25"};
    std::vector<std::string> windowed = view, headless = view;
    windowed.insert(windowed.end(),
                    {"--frames", "3", "--render-scale", "1", "--capture", dir + "/windowed"});
    headless.insert(headless.end(), {"--headless", "--capture", dir + "/headless"});
    const world::ChildResult w = test::runOnelight(windowed);
    ASSERT_EQ(w.exitCode, 0) << w.err;
    const world::ChildResult h = test::runOnelight(headless);
    ASSERT_EQ(h.exitCode, 0) << h.err;

    const world::DecodedImage windowShot = world::readImageFile(dir + "/windowed_window.png");
    const world::DecodedImage headlessShot = world::readImageFile(dir + "/headless.png");
    ASSERT_EQ(windowShot.width, headlessShot.width);
    ASSERT_EQ(windowShot.height, headlessShot.height);
    const std::vector<uint8_t>& screenshot = windowShot.rgba;
    const std::vector<uint8_t>& offscreen = headlessShot.rgba;
    const uint32_t sw = windowShot.width, sh = windowShot.height;
    // Same device, same pipelines: the screenshot equals the offscreen frame within the golden
    // tolerance (tests/render/golden_test.cpp), and in practice exactly.
    uint64_t over = 0;
    double sum = 0.0;
    for (size_t i = 0; i < screenshot.size(); ++i) {
        if (i % 4 == 3) continue;
        const int d = std::abs(int(screenshot[i]) - int(offscreen[i]));
        sum += d;
        if (d > 8) ++over;
    }
    const double pixels = double(sw) * sh;
    std::printf(
        "[ window ] %ux%u screenshot vs offscreen: %llu channels over 8/255, mean %.4f/255\n", sw,
        sh, static_cast<unsigned long long>(over), sum / (pixels * 3));
    EXPECT_LE(double(over), 0.005 * pixels);
    EXPECT_LE(sum / (pixels * 3), 0.5);
}

// At render scale 0.5 the window shows a 160x90 frame scaled up to its 320x180: the screenshot,
// averaged back over 2x2 blocks, matches a headless 160x90 frame of the same view. A bilinear
// blit up and a box filter down return each pixel blended with at most a quarter of each
// neighbour, so the tolerance is the mean absolute difference over smooth shading plus edges.
TEST(RenderWindow, RenderScaleDrawsSmallerAndScalesUp) {
    if (!ONELIGHT_HAVE_XVFB_RUN) GTEST_SKIP() << "xvfb-run is not installed";
    ASSERT_NE(std::getenv("DISPLAY"), nullptr);
    const std::string dir = test::outputDir() + "/window_scale";
    ASSERT_EQ(compileWindowLevel(dir, "level"), 0);
    const std::string camera = "2,3,6,15,-25";
    const world::ChildResult w = test::runOnelight(
        {dir + "/level.olpak", "--size", "320x180", "--camera", camera, "--frames", "2",
         "--render-scale", "0.5", "--capture", dir + "/windowed"});
    ASSERT_EQ(w.exitCode, 0) << w.err;
    const world::ChildResult h =
        test::runOnelight({dir + "/level.olpak", "--size", "160x90", "--camera", camera,
                           "--headless", "--capture", dir + "/headless"});
    ASSERT_EQ(h.exitCode, 0) << h.err;
    const world::DecodedImage window = world::readImageFile(dir + "/windowed_window.png");
    const world::DecodedImage frame = world::readImageFile(dir + "/windowed.png");
    const world::DecodedImage small = world::readImageFile(dir + "/headless.png");
    ASSERT_EQ(window.width, 320u);
    ASSERT_EQ(window.height, 180u);
    EXPECT_EQ(frame.width, 160u) << "the captured frame is the renderer's, at the render scale";
    ASSERT_EQ(small.width, 160u);
    double sum = 0.0;
    for (uint32_t y = 0; y < 90; ++y)
        for (uint32_t x = 0; x < 160; ++x)
            for (int c = 0; c < 3; ++c) {
                int box = 0;
                for (uint32_t dy = 0; dy < 2; ++dy)
                    for (uint32_t dx = 0; dx < 2; ++dx)
                        box += window.rgba[4 * ((2 * y + dy) * 320 + 2 * x + dx) + c];
                sum += std::abs(box / 4.0 - small.rgba[4 * (y * 160 + x) + c]);
            }
    const double mean = sum / (160.0 * 90.0 * 3.0);
    std::printf("[ window ] render scale 0.5: 2x2 means of the window vs 160x90: mean %.3f/255\n",
                mean);
    EXPECT_LE(mean, 3.0);
}

}  // namespace
