// The materials' records are read from a uniform array bound once for the pass, a page of
// MAX_MATERIAL_RECORDS at a time (shaders/gpu_interface.glsl, BINDING_MATERIAL_RECORDS): a level
// of more materials than a page rebinds the frame's set where its draws cross into the next page.
// A grid of emissive tiles, each its own material (black base colour, no light: a pixel's
// radiance is its tile's emission plus the placeholder environment's specular, the same on every
// tile), more tiles than a page holds: every tile, on either page, shows its own emission.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "render/camera.hpp"
#include "render/gpu_types.hpp"
#include "test_scene.hpp"

namespace onelight::test {
namespace {

constexpr uint32_t kWidth = 416, kHeight = 320;
constexpr int kColumns = 26, kRows = 20;  // 520 tiles, one material each: two pages
static_assert(kColumns * kRows > int(glsl::MAX_MATERIAL_RECORDS));

// Tile k's emission: a colour of its own among the 520 (8 x 8 x 9 steps), as KHR factors.
glm::vec3 emissionOf(int k) {
    return glm::vec3(float(1 + k % 8), float(1 + (k / 8) % 8), float(1 + k / 64)) / 9.0f;
}

TEST(RenderMaterials, MoreMaterialsThanAPageOfRecordsEachDrawWithItsOwnRecord) {
    Scene s;
    for (int k = 0; k < kColumns * kRows; ++k) {
        SceneMaterial m;
        m.baseColor = {0.0f, 0.0f, 0.0f, 1.0f};
        m.emissive = emissionOf(k);
        m.emissiveStrength = 10.0f;
        s.materials.push_back(m);
        const float x = float(k % kColumns) - 0.5f * kColumns + 0.5f;
        const float z = float(k / kColumns) - 0.5f * kRows + 0.5f;
        addFloor(s, x, z, 0.5f, 0.0f, uint32_t(k));
    }
    const std::string gltf = outputDir() + "/material_pages.gltf";
    writeGltf(s, gltf);
    const assets::LoadedLevel level = compileAndLoad(gltf, outputDir() + "/material_pages.olpak");
    ASSERT_EQ(level.level.materials.size(), size_t(kColumns * kRows));

    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({0.0f, 20.0f, 0.0f}, 0.0f, -90.0f);
    inputs.camera.hasExposure = true;  // ev100 0: the pixels are the emission times one scale
    render::RendererOptions options;
    options.width = kWidth;
    options.height = kHeight;
    const RenderedFrame frame = renderOnce(level, options, inputs);
    EXPECT_EQ(frame.validationErrors, 0u);
    // One pipeline, draws sorted by material: page 0's, then one rebind for page 1's.
    EXPECT_EQ(frame.stats.frameSetBinds, 1u);

    // Each tile's centre pixel, channel by channel, against a + b e where e is its emission, with
    // a (the environment's specular) and b (the exposure) from two tiles of page 0 that differ
    // in that channel (half floats: 2^-10 relative each, so 0.3% covers the three pixels'
    // rounding).
    const glm::mat4 clip =
        render::projectionMatrix(inputs.camera, float(kWidth) / float(kHeight), 100.0f) *
        render::viewMatrix(inputs.camera);
    auto pixelOf = [&](int k) {
        const glm::vec4 c = clip * glm::vec4(float(k % kColumns) - 0.5f * kColumns + 0.5f, 0.0f,
                                             float(k / kColumns) - 0.5f * kRows + 0.5f, 1.0f);
        const uint32_t x = uint32_t((c.x / c.w * 0.5f + 0.5f) * float(kWidth));
        const uint32_t y = uint32_t((c.y / c.w * 0.5f + 0.5f) * float(kHeight));
        EXPECT_LT(x, kWidth);
        EXPECT_LT(y, kHeight);
        const float* p = &frame.frame.linearRgba[(size_t(y) * kWidth + x) * 4];
        return glm::vec3(p[0], p[1], p[2]);
    };
    glm::vec3 a, b;
    const int references[3] = {7, 56, 448};  // the first tile whose channel c is the largest
    for (int c = 0; c < 3; ++c) {
        const float low = pixelOf(0)[c], high = pixelOf(references[c])[c];
        b[c] = (high - low) / (emissionOf(references[c])[c] - emissionOf(0)[c]);
        a[c] = low - b[c] * emissionOf(0)[c];
        ASSERT_GT(b[c], 0.0f);
        EXPECT_LT(a[c], 0.05f * b[c] * emissionOf(0)[c]);  // the emission dominates
    }
    int wrong = 0;
    for (int k = 0; k < kColumns * kRows; ++k) {
        const glm::vec3 expected = a + b * emissionOf(k);
        const glm::vec3 got = pixelOf(k);
        for (int c = 0; c < 3; ++c) {
            if (std::fabs(got[c] - expected[c]) <= 3e-3f * expected[c]) continue;
            if (++wrong <= 5)
                ADD_FAILURE() << "tile " << k << " (page " << k / int(glsl::MAX_MATERIAL_RECORDS)
                              << ") channel " << c << ": " << got[c] << ", expected "
                              << expected[c];
        }
    }
    EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace onelight::test
