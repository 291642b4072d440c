// Probe capture against the reference path tracer: a closed box room lit by one point light,
// captured through traceRadiance; the cube's solid-angle-weighted mean radiance (whole sphere
// and per face) against independent uniform-sphere paths of the same routine; determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <tbb/parallel_for.h>

#include "bake/lighting/sampling.hpp"
#include "bake/probes/probe_capture.hpp"
#include "bake_scenes.hpp"
#include "shading.hpp"
#include "world/compile/static_split.hpp"

using namespace onelight;
using namespace onelight::bake;
namespace glsl = onelight::glsl;

namespace {

// A closed 4 x 3 x 2.5 m room (albedo 0.6) with one primary point light of 60 cd.
world::SourceLevel boxRoom() {
    world::SourceLevel level;
    const uint32_t walls = test::addLambertMaterial(level, 0.6f);
    test::addBox(level, {-2.0f, -1.5f, 0.0f}, {2.0f, 1.5f, 2.5f}, walls, true, "room");
    level.lights.push_back(
        test::pointLight({-1.0f, 0.5f, 2.0f}, 60.0f, world::LightRole::kPrimary));
    return level;
}

struct Room {
    world::SourceLevel source = boxRoom();
    EmbreeDevice device;
    world::SplitLevel split = world::splitStaticDynamic(source);
    BakeScene scene{device, split.staticGeometry, source.materials};
    BakeLights lights = makeBakeLights(scene, source.lights, LightSizes{}, glm::vec3(0.0f));
};

const glm::vec3 kCapturePoint(0.3f, -0.2f, 1.2f);

}  // namespace

TEST(ProbeCapture, BoxRoomMatchesThePathTracerWithinItsNoise) {
    Room room;
    ProbeCaptureSettings settings;
    settings.faceSize = 16;
    settings.samplesPerTexel = 128;
    RayCounts rays;
    const Cubemap cube =
        captureProbe(room.scene, room.lights, kCapturePoint, 0, settings, nullptr, rays);
    const int size = int(settings.faceSize);

    // The cube's mean radiance per face and over the sphere (solid-angle weighted), and the
    // sum of squared weights for its noise.
    double faceMean[6] = {}, faceWeight2[6] = {}, sphere = 0.0, sphereWeight2 = 0.0;
    const double faceAngle = 4.0 * M_PI / 6.0;
    for (int f = 0; f < 6; ++f)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const glm::vec3 l = cube.mips[0].at(f, x, y);
                ASSERT_TRUE(std::isfinite(l.x) && std::isfinite(l.y) && std::isfinite(l.z));
                ASSERT_GE(std::min(l.x, std::min(l.y, l.z)), 0.0f);
                const double w = texelSolidAngle(x, y, size);
                faceMean[f] += w / faceAngle * double(luminance(l));
                faceWeight2[f] += (w / faceAngle) * (w / faceAngle);
                sphere += w / (4.0 * M_PI) * double(luminance(l));
                sphereWeight2 += (w / (4.0 * M_PI)) * (w / (4.0 * M_PI));
            }

    // The reference: uniform sphere directions (pdf 1 / (4 pi)) from the same point, binned by
    // face; each bin's plain mean estimates that face's mean radiance.
    // Chunks of paths with their own streams, summed in order: the same on any thread count.
    constexpr uint32_t kChunks = 64, kPathsPerChunk = 50000, kPaths = kChunks * kPathsPerChunk;
    struct Sums {
        double sum[6] = {}, sum2[6] = {};
        uint32_t count[6] = {};
        RayCounts rays;
    };
    std::vector<Sums> chunks(kChunks);
    tbb::parallel_for(0u, kChunks, [&](uint32_t c) {
        Sums& out = chunks[c];
        Rng rng{seedFrom(77, c, 0, 99)};
        for (uint32_t i = 0; i < kPathsPerChunk; ++i) {
            const glm::vec3 w = sampleUniformSphere({rng.next(), rng.next()});
            const double l = luminance(traceRadiance(room.scene, room.lights, settings.transport,
                                                     kCapturePoint, w, RayCone{}, rng, out.rays));
            const int f = glsl::cubeFace(w);
            out.sum[f] += l;
            out.sum2[f] += l * l;
            ++out.count[f];
        }
    });
    double sum[6] = {}, sum2[6] = {}, all = 0.0, all2 = 0.0;
    uint32_t count[6] = {};
    for (const Sums& c : chunks)
        for (int f = 0; f < 6; ++f) {
            sum[f] += c.sum[f];
            sum2[f] += c.sum2[f];
            count[f] += c.count[f];
            all += c.sum[f];
            all2 += c.sum2[f];
        }
    // Tolerance: 4 standard errors of the difference. The reference's from its sample
    // variance; the cube's from the same per-path variance over samplesPerTexel paths per
    // texel, weighted by the texels' solid angles.
    const auto check = [&](const char* what, double cubeMean, double weight2, double s, double s2,
                           uint32_t n) {
        const double mean = s / n;
        const double var = std::max(0.0, s2 / n - mean * mean);
        const double seRef = std::sqrt(var / n);
        const double seCube = std::sqrt(var * weight2 / settings.samplesPerTexel);
        const double tolerance = 4.0 * std::sqrt(seRef * seRef + seCube * seCube);
        std::printf("%-7s cube %.4f reference %.4f cd/m^2, difference %+.2f%%, tolerance %.2f%%\n",
                    what, cubeMean, mean, 100.0 * (cubeMean - mean) / mean,
                    100.0 * tolerance / mean);
        EXPECT_NEAR(cubeMean, mean, tolerance) << what;
        EXPECT_LT(tolerance / mean, 0.04) << what << ": the test is too noisy to mean anything";
    };
    check("sphere", sphere, sphereWeight2, all, all2, kPaths);
    const char* names[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    for (int f = 0; f < 6; ++f)
        check(names[f], faceMean[f], faceWeight2[f], sum[f], sum2[f], count[f]);
}

TEST(ProbeCapture, IsDeterministicAndPacksToTheSameBytes) {
    Room room;
    ProbeCaptureSettings settings;
    settings.faceSize = 16;
    settings.samplesPerTexel = 8;
    IrradianceCube irradiance;
    irradiance.fill(glm::vec3(2.0f, 3.0f, 4.0f));
    std::vector<uint8_t> bytes[2];
    for (auto& out : bytes) {
        RayCounts rays;
        const Cubemap cube =
            captureProbe(room.scene, room.lights, kCapturePoint, 3, settings, nullptr, rays);
        const world::EnvironmentProbe probe =
            finishProbe(cube, ProbePlacement{kCapturePoint}, irradiance, settings.prefilter);
        EXPECT_EQ(probe.texels.size(), world::probeTexelCount(16));
        EXPECT_EQ(probe.mipCount, 5u);
        out = package::encodeProbeSection({probe}).bytes;
    }
    EXPECT_EQ(bytes[0], bytes[1]);
    // The whole stage gives probe 3 of a list the same bytes, and so does a shard's range.
    RayCounts rays;
    const std::vector<ProbePlacement> placements(4, ProbePlacement{kCapturePoint});
    const std::vector<IrradianceCube> cubes(4, irradiance);
    const std::vector<world::EnvironmentProbe> probes =
        bakeProbes(room.scene, room.lights, placements, cubes, settings, 0, 4, false, rays);
    ASSERT_EQ(probes.size(), 4u);
    EXPECT_EQ(package::encodeProbeSection({probes[3]}).bytes, bytes[0]);
    const std::vector<world::EnvironmentProbe> tail =
        bakeProbes(room.scene, room.lights, placements, cubes, settings, 3, 4, false, rays);
    ASSERT_EQ(tail.size(), 1u);
    EXPECT_EQ(package::encodeProbeSection(tail).bytes, bytes[0]);
}

TEST(ProbeCapture, StoredMipZeroIsTheCapturedRadianceOverEAvg) {
    Room room;
    ProbeCaptureSettings settings;
    settings.faceSize = 8;
    settings.samplesPerTexel = 8;
    RayCounts rays;
    const Cubemap cube =
        captureProbe(room.scene, room.lights, kCapturePoint, 1, settings, nullptr, rays);
    // A cube whose faces differ, of mean (0.5, 2, 8): the mean normalises, the faces are kept.
    const glm::vec3 average(0.5f, 2.0f, 8.0f);
    const IrradianceCube irradiance = {average * 2.0f, average * 0.5f, average * 1.5f,
                                       average * 0.0f, average,        average};
    const world::EnvironmentProbe probe =
        finishProbe(cube, ProbePlacement{kCapturePoint}, irradiance, settings.prefilter);
    EXPECT_EQ(probe.irradianceAverage, average);
    EXPECT_EQ(probe.irradianceCube, irradiance);
    const Cubemap stored = unpackProbeTexels(probe);
    for (size_t i = 0; i < cube.mips[0].texels.size(); ++i) {
        const glm::vec3 back = glsl::probeDenormalize(stored.mips[0].texels[i], average);
        const glm::vec3 l = cube.mips[0].texels[i];
        // RGB9E5's bound on the normalised texel, scaled back per channel.
        const glm::vec3 normalised = l / average;
        const float step = std::max(normalised.x, std::max(normalised.y, normalised.z)) / 512.0f;
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(back[c], l[c], average[c] * (step + 1e-7f)) << i;
    }
}
