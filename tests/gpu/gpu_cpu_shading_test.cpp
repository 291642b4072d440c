// GPU vs CPU shading: a flat quad lit by one primary light of each type renders, in the linear
// EXR (before exposure and tonemapping), the radiance that the C++ build of the same shared
// shaders (shaders/lighting.glsl, material.glsl, brdf.glsl) gives at the pixel centres, within 1%.
// The placeholder ambient is 0, so the primary light is the only term; nothing casts a shadow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "env_brdf_table.hpp"
#include "shading.hpp"
#include "test_scene.hpp"
#include "world/images/image_files.hpp"

namespace {

using namespace onelight;
namespace glsl = onelight::glsl;

constexpr uint32_t kWidth = 96, kHeight = 64;
constexpr double kRelTolerance = 0.01;  // the 1%
constexpr double kFloorOfPeak = 1e-3;   // absolute floor: 0.1% of the brightest pixel

// The C++ radiance at the centre of pixel (x, y): the camera ray meets the plane y = 0.
glm::vec3 cpuRadiance(const world::CompiledLevel& level, const render::Camera& camera, uint32_t x,
                      uint32_t y) {
    const glm::mat4 viewProj =
        render::projectionMatrix(camera, float(kWidth) / float(kHeight), 1000.0f) *
        render::viewMatrix(camera);
    const glm::mat4 inv = glm::inverse(viewProj);
    const float ndcX = (2.0f * (float(x) + 0.5f)) / float(kWidth) - 1.0f;
    const float ndcY = (2.0f * (float(y) + 0.5f)) / float(kHeight) - 1.0f;
    glm::vec4 far = inv * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    const glm::vec3 dir = glm::normalize(glm::vec3(far) / far.w - camera.position);
    const float t = -camera.position.y / dir.y;
    const glm::vec3 p = camera.position + t * dir;
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    const glm::vec3 v = glm::normalize(camera.position - p);

    const world::Material& m = level.materials.at(0);
    const glm::vec3 base(m.baseColor);
    const glm::vec3 albedo = glsl::albedo_fromMetallic(base, m.metallic);
    const glm::vec3 f0 = m.materialClass == world::MaterialClass::kDielectric
                             ? glm::vec3(m.specularColor.x)
                             : glsl::specularColor_fromMetallic(base, m.metallic);
    const float gloss = glsl::gloss_fromRoughness(m.roughness);
    const world::Light& l = level.lights.at(0);
    const glsl::LightSample s = glsl::evaluatePunctualLight(
        int(l.type), l.color * l.intensity, 1.0f, l.range, l.position, glm::normalize(l.direction),
        std::cos(l.innerCone), std::cos(l.outerCone), p);
    const glsl::BrdfDots d = glsl::brdfDots(n, v, s.l);
    if (glm::dot(n, s.l) <= 0.0f || d.NoL <= 0.0f) return glm::vec3(0.0f);
    // The split-sum term as the GPU's sampler reads its table (in half floats there).
    const glm::vec2 env = m.materialClass == world::MaterialClass::kLambert
                              ? glm::vec2(0.0f)
                              : glsl::sampleEnvBrdfTable(glsl::envBrdfTableCoord(d.NoV, gloss));
    return glsl::surfaceReflectance(int(m.materialClass), DIFFUSE_LAMBERT, albedo, f0, gloss, env,
                                    1.0f, d) *
           s.illuminance;
}

struct Comparison {
    double maxRelative = 0.0;  // over pixels above the floor
    uint32_t failures = 0;
    double peak = 0.0;
};

void checkLight(const char* name, const test::SceneLight& light,
                const test::SceneMaterial& material) {
    test::Scene scene;
    scene.materials.push_back(material);
    test::addFloor(scene, 0.0f, -10.0f, 30.0f, 0.0f, 0);
    scene.lights.push_back(light);
    const std::string dir = test::outputDir();
    const std::string gltf = dir + "/gpu_cpu_" + name + ".gltf";
    test::writeGltf(scene, gltf);
    const assets::LoadedLevel level =
        test::compileAndLoad(gltf, dir + "/gpu_cpu_" + name + ".olpak");
    ASSERT_EQ(level.level.lights.size(), 1u);

    render::RendererOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.placeholderAmbientLux = 0.0f;
    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({0.3f, 3.0f, 3.0f}, 10.0f, -40.0f);
    const test::RenderedFrame rendered = test::renderOnce(level, options, inputs);
    EXPECT_EQ(rendered.validationErrors, 0u);

    // Through the EXR file, as a capture writes it.
    const std::string exr = dir + "/gpu_cpu_" + name + ".exr";
    world::writeExrFile(exr, kWidth, kHeight, rendered.frame.linearRgba);
    const world::FloatImage image = world::readExrFile(exr);
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);
    const std::vector<float>& gpu = image.rgba;

    std::vector<glm::vec3> cpu(size_t(kWidth) * kHeight);
    Comparison c;
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            cpu[y * kWidth + x] = cpuRadiance(level.level, inputs.camera, x, y);
            for (int k = 0; k < 3; ++k) c.peak = std::max(c.peak, double(cpu[y * kWidth + x][k]));
        }
    ASSERT_GT(c.peak, 0.0);
    const double floor = kFloorOfPeak * c.peak;
    for (uint32_t i = 0; i < kWidth * kHeight; ++i)
        for (int k = 0; k < 3; ++k) {
            const double want = cpu[i][k], got = gpu[4 * i + k];
            ASSERT_TRUE(std::isfinite(got));
            const double err = std::fabs(got - want);
            if (want > floor) c.maxRelative = std::max(c.maxRelative, err / want);
            if (err > kRelTolerance * want + floor) {
                if (c.failures < 5)
                    ADD_FAILURE() << name << " pixel (" << i % kWidth << ", " << i / kWidth
                                  << ") channel " << k << ": gpu " << got << " cpu " << want;
                ++c.failures;
            }
        }
    std::printf(
        "[ gpu-cpu ] %s: max relative error %.3e over pixels above %.1e cd/m^2 (peak %.3g)\n", name,
        c.maxRelative, floor, c.peak);
    EXPECT_EQ(c.failures, 0u);
}

TEST(GpuCpuAgreement, DirectionalLightMatchesCpu) {
    test::SceneLight sun;
    sun.type = 0;
    sun.intensity = 3.0f;
    sun.color = {1.0f, 0.9f, 0.8f};
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.6f));
    checkLight("directional", sun, {{0.8f, 0.6f, 0.4f, 1.0f}, 0.3f, 0.45f});
}

TEST(GpuCpuAgreement, PointLightMatchesCpu) {
    test::SceneLight omni;
    omni.type = 1;
    omni.intensity = 8.0f;
    omni.range = 12.0f;
    omni.position = {0.5f, 1.2f, -1.0f};
    checkLight("point", omni, {{0.5f, 0.7f, 0.9f, 1.0f}, 0.0f, 0.35f});
}

TEST(GpuCpuAgreement, SpotLightMatchesCpu) {
    test::SceneLight spot;
    spot.type = 2;
    spot.intensity = 20.0f;
    spot.position = {-0.5f, 2.0f, -1.5f};
    spot.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
    spot.innerCone = 0.25f;
    spot.outerCone = 0.6f;
    checkLight("spot", spot, {{0.9f, 0.8f, 0.3f, 1.0f}, 1.0f, 0.4f});
}

}  // namespace
