// The sky image as a light (bake/lighting/sky.hpp): the equirectangular mapping of
// shaders/sky.glsl, the sampled density against the one evaluated, and the irradiance a plane
// gathers from the image, open or under a black roof, against midpoint quadrature of the
// image's radiance (the roof's shadow traced by hand). A synthetic sky with a small hot sun
// runs everywhere; a real HDR runs when the shared assets are beside the repository.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/radiance.hpp"
#include "bake/reference/path_tracer.hpp"
#include "bake_scenes.hpp"
#include "shading.hpp"
#include "world/compile/static_split.hpp"

namespace onelight::bake {
namespace {

std::string outputFolder() {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "onelight_sky";
    std::filesystem::create_directories(dir);
    return dir.string();
}

constexpr uint32_t kSkyWidth = 128, kSkyHeight = 64;
constexpr float kSkyScale = 1000.0f;  // cd/m^2 per unit of the image
// The sun: 2 x 2 texels of 2000 units (2e6 cd/m^2 after the scale) centred 30 degrees up
// (v = 1/3) at u = 0.3, towards (0.268, 0.5, -0.824). It gives ~8.6 klx on a floor, twice the
// whole sky's ~4 klx from 0.2 % of the sphere: cosine-weighted directions find it rarely.
constexpr uint32_t kSunRow = 20, kSunColumn = 37;
constexpr float kSunValue = 2000.0f;

// A blue-white sky brightening towards the horizon over a dark ground, and the sun.
world::HdrImage syntheticSky() {
    world::HdrImage image;
    image.width = kSkyWidth;
    image.height = kSkyHeight;
    image.rgb.resize(size_t(kSkyWidth) * kSkyHeight * 3);
    for (uint32_t i = 0; i < kSkyHeight; ++i)
        for (uint32_t j = 0; j < kSkyWidth; ++j) {
            const float v = (float(i) + 0.5f) / float(kSkyHeight);
            glm::vec3 c = v < 0.5f ? glm::vec3(0.5f, 0.7f, 1.0f) * (0.6f + 1.2f * v)
                                   : glm::vec3(0.08f, 0.07f, 0.05f);
            c *= 1.0f + 0.25f * std::cos(6.2831853f * (float(j) + 0.5f) / float(kSkyWidth));
            if ((i == kSunRow || i == kSunRow + 1) && (j == kSunColumn || j == kSunColumn + 1))
                c = glm::vec3(kSunValue, 0.9f * kSunValue, 0.75f * kSunValue);
            for (int k = 0; k < 3; ++k) image.rgb[(size_t(i) * kSkyWidth + j) * 3 + k] = c[k];
        }
    return image;
}

// Midpoint quadrature over the sphere in (u, v), `n` points per texel each way:
// int f(w) dw = sum f(w_k) 2 pi^2 sin(theta_k) du dv.
double integrateOverSphere(const SkyImage& sky, uint32_t n,
                           const std::function<double(const glm::vec3&)>& f) {
    const uint32_t nu = sky.width * n, nv = sky.height * n;
    const double du = 1.0 / nu, dv = 1.0 / nv;
    double sum = 0.0;
    for (uint32_t i = 0; i < nv; ++i) {
        const double v = (i + 0.5) * dv;
        const double jacobian = 2.0 * M_PI * M_PI * std::sin(M_PI * v) * du * dv;
        for (uint32_t j = 0; j < nu; ++j) {
            const glm::vec2 uv(float((j + 0.5) * du), float(v));
            sum += f(glsl::direction_fromEquirectUv(uv)) * jacobian;
        }
    }
    return sum;
}

// Irradiance (lux, luminance) on an up-facing point at `p`, by quadrature of the sky's
// radiance, optionally shadowed by the square roof |x|, |z| < 1 at height 1.
double quadratureIrradiance(const SkyImage& sky, const glm::vec3& p, bool roof) {
    return integrateOverSphere(sky, 8, [&](const glm::vec3& w) {
        if (w.y <= 0.0f) return 0.0;
        if (roof) {
            const float t = (1.0f - p.y) / w.y;
            const glm::vec3 q = p + w * t;
            if (std::fabs(q.x) < 1.0f && std::fabs(q.z) < 1.0f) return 0.0;
        }
        return double(glsl::luminance(skyRadiance(sky, w))) * double(w.y);
    });
}

TEST(Sky, TheMappingRoundTripsAndNamesItsAxes) {
    const auto near = [](glm::vec2 a, glm::vec2 b) { return glm::length(a - b) < 1e-5f; };
    EXPECT_TRUE(near(glsl::equirectUv_fromDirection({1, 0, 0}), {0.5f, 0.5f}));
    EXPECT_TRUE(near(glsl::equirectUv_fromDirection({0, 0, 1}), {0.75f, 0.5f}));
    EXPECT_TRUE(near(glsl::equirectUv_fromDirection({0, 0, -1}), {0.25f, 0.5f}));
    EXPECT_TRUE(near(glsl::equirectUv_fromDirection({0, 1, 0}), {0.5f, 0.0f}));
    EXPECT_TRUE(near(glsl::equirectUv_fromDirection({0, -1, 0}), {0.5f, 1.0f}));
    Rng rng{seedFrom(3)};
    for (int k = 0; k < 10000; ++k) {
        const glm::vec3 d = sampleUniformSphere({rng.next(), rng.next()});
        const glm::vec3 back = glsl::direction_fromEquirectUv(glsl::equirectUv_fromDirection(d));
        ASSERT_LT(glm::length(back - d), 2e-5f) << d.x << " " << d.y << " " << d.z;
    }
}

// Between texel centres the lookup is the image times the scale, exactly at each centre.
TEST(Sky, TheLookupIsTheImageAtTexelCentres) {
    const world::HdrImage image = syntheticSky();
    const SkyImage sky = makeSkyImage(image, glm::vec3(kSkyScale));
    for (uint32_t i = 0; i < kSkyHeight; i += 3)
        for (uint32_t j = 0; j < kSkyWidth; j += 5) {
            const glm::vec2 uv((float(j) + 0.5f) / kSkyWidth, (float(i) + 0.5f) / kSkyHeight);
            const glm::vec3 l = skyRadiance(sky, glsl::direction_fromEquirectUv(uv));
            const size_t t = (size_t(i) * kSkyWidth + j) * 3;
            for (int k = 0; k < 3; ++k)
                ASSERT_NEAR(l[k], image.rgb[t + k] * kSkyScale,
                            2e-4f * image.rgb[t + k] * kSkyScale)
                    << "texel " << i << ", " << j;
        }
}

// The density sampleSky draws with is the one skyPdf evaluates, it integrates to 1 over the
// sphere, and L / p averages to the quadrature of L (unbiased importance sampling).
TEST(Sky, TheSampledDensityIsTheEvaluatedOneAndIntegratesToOne) {
    const SkyImage sky = makeSkyImage(syntheticSky(), glm::vec3(kSkyScale));
    const double total =
        integrateOverSphere(sky, 4, [&](const glm::vec3& w) { return double(skyPdf(sky, w)); });
    EXPECT_NEAR(total, 1.0, 1e-3);
    const double power = integrateOverSphere(
        sky, 8, [&](const glm::vec3& w) { return double(glsl::luminance(skyRadiance(sky, w))); });
    Rng rng{seedFrom(5)};
    const uint32_t n = 200000;
    double sum = 0.0;
    int mismatched = 0;
    for (uint32_t k = 0; k < n; ++k) {
        const SkySample s = sampleSky(sky, {rng.next(), rng.next()});
        ASSERT_GT(s.pdf, 0.0f);
        ASSERT_NEAR(glm::length(s.direction), 1.0f, 1e-5f);
        const float evaluated = skyPdf(sky, s.direction);
        if (std::fabs(evaluated - s.pdf) > 1e-3f * s.pdf) ++mismatched;  // a texel edge
        sum += double(glsl::luminance(s.radiance)) / double(s.pdf);
    }
    std::printf(
        "[ sky ] int p dw = %.5f; E[Y/p] = %.1f vs quadrature %.1f; %d of %u samples "
        "on a texel edge\n",
        total, sum / n, power, mismatched, n);
    EXPECT_NEAR(sum / n, power, 0.01 * power);
    EXPECT_LT(mismatched, int(n / 1000));
}

// Hard skies: all black (sampled uniformly, no light, no NaN), one texel (uniform), and a
// 2 x 1 image whose only light is one texel: each a density over the sphere that integrates to
// 1 and samples that are finite.
TEST(Sky, BlackTinyAndOneHotTexelSkiesStayFinite) {
    const auto image = [](uint32_t w, uint32_t h, std::vector<float> rgb) {
        world::HdrImage i;
        i.width = w;
        i.height = h;
        i.rgb = std::move(rgb);
        return i;
    };
    const world::HdrImage skies[3] = {image(4, 2, std::vector<float>(24, 0.0f)),
                                      image(1, 1, {2.0f, 2.0f, 2.0f}),
                                      image(2, 1, {0.0f, 0.0f, 0.0f, 5.0f, 5.0f, 5.0f})};
    for (const world::HdrImage& i : skies) {
        const SkyImage sky = makeSkyImage(i, glm::vec3(100.0f));
        const double total = integrateOverSphere(
            sky, 64, [&](const glm::vec3& w) { return double(skyPdf(sky, w)); });
        EXPECT_NEAR(total, 1.0, 2e-3) << i.width << "x" << i.height;
        Rng rng{seedFrom(9)};
        for (int k = 0; k < 2000; ++k) {
            const SkySample s = sampleSky(sky, {rng.next(), rng.next()});
            ASSERT_TRUE(std::isfinite(s.pdf) && s.pdf >= 0.0f);
            ASSERT_TRUE(std::isfinite(s.radiance.x) && s.radiance.x >= 0.0f);
            ASSERT_TRUE(std::isfinite(s.direction.x) && std::isfinite(s.direction.y));
        }
    }
    // Straight up and down, where u is undefined, the lookup is finite and the density 0.
    const SkyImage sky = makeSkyImage(syntheticSky(), glm::vec3(1.0f));
    for (const glm::vec3 pole : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0)}) {
        const glm::vec3 l = skyRadiance(sky, pole);
        EXPECT_TRUE(std::isfinite(l.x) && std::isfinite(l.y) && std::isfinite(l.z));
        EXPECT_EQ(skyPdf(sky, pole), 0.0f);
    }
}

struct SkyScene {
    world::SourceLevel level;
    EmbreeDevice device;
    std::unique_ptr<BakeScene> scene;
    BakeLights lights;
};

// A black 8 x 8 m floor at y = 0 under the sky image, and optionally the black square roof.
void buildSkyScene(SkyScene& s, const std::string& hdrPath, const world::HdrImage& image,
                   float scale, bool roof) {
    const uint32_t black = test::addLambertMaterial(s.level, 0.0f);
    test::addQuad(s.level, {-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, black, "floor");
    if (roof) test::addQuad(s.level, {-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}, black, "roof");
    test::setSkyImage(s.level, hdrPath, image, glm::vec3(scale));
    const world::SplitLevel split = world::splitStaticDynamic(s.level);
    s.scene =
        std::make_unique<BakeScene>(s.device, split.staticGeometry, loadSceneMaterials(s.level));
    s.lights = makeLevelLights(*s.scene, s.level, {}, std::nullopt);
}

// The reference's irradiance at floor points in the open, in the roof's shade with the sun
// visible, with the sun behind the roof, and beside the roof: within 1 % of quadrature.
TEST(Sky, TheReferenceGathersTheImageWithTheRoofsShadow) {
    const world::HdrImage image = syntheticSky();
    for (bool roof : {false, true}) {
        SkyScene s;
        buildSkyScene(s, outputFolder() + "/synthetic.hdr", image, kSkyScale, roof);
        ASSERT_FALSE(s.lights.skyImage.empty());
        for (const glm::vec3 p :
             {glm::vec3(0, 0, 0), glm::vec3(0, 0, 0.9f), glm::vec3(1.6f, 0, -0.4f)}) {
            RayCounts rays;
            const glm::vec3 e =
                referenceIrradiance(*s.scene, s.lights, p, {0, 1, 0}, 65536, 7, {}, rays);
            const double expected = quadratureIrradiance(s.lights.skyImage, p, roof);
            std::printf("[ sky ] %s (%.1f, %.1f): reference %.1f lx, quadrature %.1f lx\n",
                        roof ? "roof" : "open", double(p.x), double(p.z),
                        double(glsl::luminance(e)), expected);
            EXPECT_NEAR(double(glsl::luminance(e)), expected, 0.01 * expected);
        }
    }
}

// Every lightmap texel of the open floor gathers the image's cosine integral. One MIS sample
// (a cosine direction and a sky sample) has a standard deviation of 0.8 E on this sky
// (ImportanceSamplingTheImageLowersTheVariance), so 256 of them leave 5 % per texel before the
// indirect filter: the mean within 1 %, the RMS within 5 % and the worst texel within 20 %.
TEST(Sky, AnOpenFloorsLightmapHoldsTheImagesCosineIntegral) {
    world::SourceLevel level;
    const uint32_t black = test::addLambertMaterial(level, 0.0f);
    test::addQuad(level, {-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, black, "floor");
    const std::string path = outputFolder() + "/synthetic_lightmap.hdr";
    test::setSkyImage(level, path, syntheticSky(), glm::vec3(kSkyScale));
    BakeOptions options = test::testOptions(8.0f);
    options.indirectSamples = 256;
    const BakeResult baked = bakeLevel(level, options);
    ASSERT_TRUE(test::allFiniteNonNegative(baked.baked));
    // The file's texels, as the bake read them (RGBE rounds the synthetic sky's).
    const SkyImage sky = makeSkyImage(world::readHdrFile(path), glm::vec3(kSkyScale));
    const double expected = quadratureIrradiance(sky, {0, 0, 0}, false);
    double sum = 0.0, sumSq = 0.0, worst = 0.0;
    int sampled = 0;
    for (const world::LightmapTexel& t : baked.baked.texels) {
        if (!(t.flags & world::kLightmapTexelSampled)) continue;
        const double y = glsl::luminance(t.irradiance), error = y / expected - 1.0;
        sum += y;
        sumSq += error * error;
        worst = std::max(worst, std::fabs(error));
        ++sampled;
    }
    ASSERT_GT(sampled, 100);
    const double rms = std::sqrt(sumSq / sampled);
    std::printf(
        "[ sky ] lightmap: %d texels, mean %.1f lx (quadrature %.1f), RMS %.2f %%, "
        "worst %.2f %%\n",
        sampled, sum / sampled, expected, 100.0 * rms, 100.0 * worst);
    EXPECT_NEAR(sum / sampled, expected, 0.01 * expected);
    EXPECT_LT(rms, 0.05);
    EXPECT_LT(worst, 0.20);
}

// Per-sample variance of the irradiance estimate at one open point: cosine-weighted directions
// alone against the lightmap's MIS of cosine directions and sky samples. Both are unbiased;
// the sun makes the first one's variance large.
void expectImportanceSamplingHelps(const SkyScene& s, uint32_t n, double atLeast) {
    const glm::vec3 normal(0, 1, 0), origin = normal * s.scene->rayOffset();
    const Frame frame = frameAround(normal);
    Rng rng{seedFrom(11)};
    RayCounts rays;
    double sum[2] = {0, 0}, sumSq[2] = {0, 0};
    for (uint32_t k = 0; k < n; ++k) {
        const glm::vec3 w =
            glm::normalize(frame.toWorld(sampleCosineHemisphere({rng.next(), rng.next()})));
        const float pdf = glm::dot(normal, w) / glsl::PI;
        const double cosine = double(glsl::luminance(
            glsl::PI * traceRadiance(*s.scene, s.lights, {}, origin, w, {}, rng, rays)));
        double mis =
            double(glsl::luminance(glsl::PI * traceRadiance(*s.scene, s.lights, {}, origin, w, {},
                                                            rng, rays, nullptr, pdf)));
        const EmissionEstimate e = sampleEmission(*s.scene, s.lights, origin, normal, rng, rays);
        if (e.pdf > 0.0f) {
            const float c = glm::dot(normal, e.direction);
            mis += double(glsl::luminance(e.radianceOverPdf) * c *
                          powerHeuristic(e.pdf, c / glsl::PI));
        }
        const double x[2] = {cosine, mis};
        for (int i = 0; i < 2; ++i) {
            sum[i] += x[i];
            sumSq[i] += x[i] * x[i];
        }
    }
    double mean[2], variance[2];
    for (int i = 0; i < 2; ++i) {
        mean[i] = sum[i] / n;
        variance[i] = sumSq[i] / n - mean[i] * mean[i];
    }
    const double expected = quadratureIrradiance(s.lights.skyImage, {0, 0, 0}, false);
    std::printf(
        "[ sky ] %u samples: cosine %.1f lx (sd %.0f), MIS %.1f lx (sd %.0f), "
        "quadrature %.1f: variance / %.1f\n",
        n, mean[0], std::sqrt(variance[0]), mean[1], std::sqrt(variance[1]), expected,
        variance[0] / variance[1]);
    EXPECT_NEAR(mean[1], expected, 0.01 * expected);
    EXPECT_NEAR(mean[0], expected, 5.0 * std::sqrt(variance[0] / n));
    EXPECT_GT(variance[0], atLeast * variance[1]);
}

TEST(Sky, ImportanceSamplingTheImageLowersTheVariance) {
    SkyScene s;
    buildSkyScene(s, outputFolder() + "/synthetic_variance.hdr", syntheticSky(), kSkyScale, false);
    expectImportanceSamplingHelps(s, 100000, 10.0);
}

// A real sky: Poly Haven's venice_sunset (1k), the sun low and bright.
TEST(Sky, ARealHdrSkyLightsAnOpenFloorAsItsQuadrature) {
    const std::string path = std::string(ONELIGHT_SHARED_ASSETS) + "/hdr/venice_sunset_1k.hdr";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is not here";
    const world::HdrImage image = world::readHdrFile(path);
    SkyScene s;
    const uint32_t black = test::addLambertMaterial(s.level, 0.0f);
    test::addQuad(s.level, {-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, black, "floor");
    world::Image sky;
    sky.name = "sky";
    sky.uri = path;
    s.level.skyImage = 0;
    s.level.images.push_back(sky);
    s.level.skyRadiance = glm::vec3(kSkyScale);
    const world::SplitLevel split = world::splitStaticDynamic(s.level);
    s.scene =
        std::make_unique<BakeScene>(s.device, split.staticGeometry, loadSceneMaterials(s.level));
    s.lights = makeLevelLights(*s.scene, s.level, {}, std::nullopt);
    ASSERT_EQ(s.lights.skyImage.width, image.width);
    RayCounts rays;
    const glm::vec3 e =
        referenceIrradiance(*s.scene, s.lights, {0, 0, 0}, {0, 1, 0}, 16384, 7, {}, rays);
    const double expected = quadratureIrradiance(s.lights.skyImage, {0, 0, 0}, false);
    std::printf("[ sky ] venice_sunset: reference %.1f lx, quadrature %.1f lx\n",
                double(glsl::luminance(e)), expected);
    EXPECT_NEAR(double(glsl::luminance(e)), expected, 0.01 * expected);
    expectImportanceSamplingHelps(s, 20000, 2.0);
}

// --sky replaces the image by a uniform sky; a sky image that is not a file is a named error.
TEST(Sky, AUniformOverrideWinsAndAMissingFileIsNamed) {
    SkyScene s;
    buildSkyScene(s, outputFolder() + "/synthetic_override.hdr", syntheticSky(), kSkyScale, false);
    const BakeLights uniform = makeLevelLights(*s.scene, s.level, {}, glm::vec3(500.0f));
    EXPECT_TRUE(uniform.skyImage.empty());
    EXPECT_EQ(uniform.skyRadiance, glm::vec3(500.0f));
    EXPECT_FALSE(samplesEmission(uniform));
    s.level.images[s.level.skyImage].uri = outputFolder() + "/no_such_sky.hdr";
    try {
        (void)makeLevelLights(*s.scene, s.level, {}, std::nullopt);
        FAIL() << "a missing sky file was accepted";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("no_such_sky.hdr"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace onelight::bake
