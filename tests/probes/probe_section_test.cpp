// Environment probes' storage and normalization: probeNormalize / probeDenormalize at the
// capture point (shaders/probe.glsl), E_avg of an ambient cube, RGB9E5 round trip, section 35
// round trip and rejection of corrupted records (world/package/probe_section.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "bake/grid/light_grid.hpp"
#include "bake/probes/probe_capture.hpp"
#include "shading.hpp"
#include "tests/support/error_message.hpp"
#include "world/package/format.hpp"
#include "world/package/package_reader.hpp"

using namespace onelight;
using namespace onelight::bake;
namespace glsl = onelight::glsl;

namespace {

// Unit normals on a Fibonacci sphere: equal-area points, so their plain mean is the sphere mean.
glm::vec3 fibonacci(int i, int n) {
    const float z = 1.0f - (2.0f * float(i) + 1.0f) / float(n);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = float(i) * 2.39996322972865332f;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

world::LightGridCell randomCell(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.05f, 20.0f);
    world::LightGridCell cell;
    for (glm::vec3& f : cell.ambientCube) f = glm::vec3(u(rng), u(rng), u(rng));
    return cell;
}

world::EnvironmentProbe smallProbe(uint32_t face, uint32_t seed) {
    world::EnvironmentProbe p;
    p.position = glm::vec3(1.0f, 2.0f, 3.0f);
    p.irradianceAverage = glm::vec3(0.5f, 1.0f, 2.0f);
    p.faceSize = face;
    p.mipCount = 0;
    for (uint32_t s = face; s > 0; s /= 2) ++p.mipCount;
    p.texels.resize(world::probeTexelCount(face));
    for (size_t i = 0; i < p.texels.size(); ++i)
        p.texels[i] = package::encodeRgb9e5(glm::vec3(float(i % 7 + seed), 0.25f, 3.0f));
    return p;
}

}  // namespace

TEST(ProbeNormalization, AmbientCubeAverageIsTheMeanOverNormals) {
    std::mt19937 rng(11);
    constexpr int kNormals = 200000;
    for (int trial = 0; trial < 5; ++trial) {
        const world::LightGridCell cell = randomCell(rng);
        glm::dvec3 mean(0.0);
        for (int i = 0; i < kNormals; ++i)
            mean += glm::dvec3(ambientCubeIrradiance(cell, fibonacci(i, kNormals)));
        mean /= double(kNormals);
        const glm::vec3 average = ambientCubeAverage(cell.ambientCube);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c] / double(average[c]), 1.0, 1e-3) << trial;
    }
}

// The test: normalize at the capture point, de-normalize with the irradiance the
// runtime reconstructs for each normal there, average over all normals: the captured radiance.
TEST(ProbeNormalization, DenormalizedAverageOverNormalsIsTheCapturedRadiance) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> radiance(0.0f, 500.0f);
    constexpr int kNormals = 100000;
    for (int trial = 0; trial < 5; ++trial) {
        const world::LightGridCell cell = randomCell(rng);
        const glm::vec3 average = ambientCubeAverage(cell.ambientCube);
        const glm::vec3 captured(radiance(rng), radiance(rng), radiance(rng));
        const glm::vec3 stored = glsl::probeNormalize(captured, average);
        // What the package holds: RGB9E5.
        const glm::vec3 decoded = package::decodeRgb9e5(package::encodeRgb9e5(stored));
        glm::dvec3 mean(0.0);
        for (int i = 0; i < kNormals; ++i)
            mean += glm::dvec3(glsl::probeDenormalize(
                decoded, ambientCubeIrradiance(cell, fibonacci(i, kNormals))));
        mean /= double(kNormals);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(mean[c], double(captured[c]), 0.01 * double(captured[c]) + 1e-6)
                << trial << " " << c;
    }
}

TEST(ProbeRgb9e5, RoundTripErrorIsAtMostHalfAStepOfTheLargestChannel) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> exponent(-20.0f, 16.0f), unit(0.0f, 1.0f);
    for (int i = 0; i < 200000; ++i) {
        const float scale = std::exp2(exponent(rng));
        glm::vec3 v(unit(rng) * scale, unit(rng) * scale, unit(rng) * scale);
        if (i % 5 == 0) v.y = 0.0f;
        v = glm::min(v, glm::vec3(65408.0f));
        const glm::vec3 back = package::decodeRgb9e5(package::encodeRgb9e5(v));
        const float maxC = std::max(v.x, std::max(v.y, v.z));
        const float bound = maxC / 512.0f + std::ldexp(1.0f, -25);
        for (int c = 0; c < 3; ++c) ASSERT_LE(std::fabs(back[c] - v[c]), bound) << i << " " << c;
    }
    // Exact values, clamping and the unrepresentable.
    EXPECT_EQ(package::decodeRgb9e5(package::encodeRgb9e5(glm::vec3(1.0f, 0.5f, 0.0f))),
              glm::vec3(1.0f, 0.5f, 0.0f));
    EXPECT_EQ(package::decodeRgb9e5(package::encodeRgb9e5(glm::vec3(1e9f))), glm::vec3(65408.0f));
    EXPECT_EQ(package::decodeRgb9e5(package::encodeRgb9e5(glm::vec3(-1.0f, NAN, 0.0f))),
              glm::vec3(0.0f));
    // A mantissa that rounds up to 512 moves to the next exponent.
    const float almost = 1.0f - 1.0f / 2048.0f;
    EXPECT_NEAR(package::decodeRgb9e5(package::encodeRgb9e5(glm::vec3(almost))).x, 1.0f, 1e-6f);
}

TEST(ProbeSection, RoundTripsAndCountsBytes) {
    world::CompiledLevel level;
    world::Entity e;
    e.flags = world::kEntityProbe;
    level.entities.push_back(e);
    std::vector<world::EnvironmentProbe> probes = {smallProbe(8, 0), smallProbe(4, 1)};
    probes[0].entity = 0;
    probes[0].boxMin = glm::vec3(-1.0f);
    probes[0].boxMax = glm::vec3(2.0f);
    const package::RawSection section = package::encodeProbeSection(probes);
    EXPECT_EQ(section.id, package::kSectionProbes);
    EXPECT_EQ(section.bytes.size(),
              sizeof(package::DiskProbeHeader) + 2 * sizeof(package::DiskProbe) +
                  4 * (world::probeTexelCount(8) + world::probeTexelCount(4)));
    const package::ProbeContents read =
        package::decodeProbeSection(std::span(&section, 1), level, "test");
    ASSERT_TRUE(read.present);
    ASSERT_EQ(read.probes.size(), 2u);
    for (size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(read.probes[i].texels, probes[i].texels);
        EXPECT_EQ(read.probes[i].faceSize, probes[i].faceSize);
        EXPECT_EQ(read.probes[i].mipCount, probes[i].mipCount);
        EXPECT_EQ(read.probes[i].position, probes[i].position);
        EXPECT_EQ(read.probes[i].irradianceAverage, probes[i].irradianceAverage);
        EXPECT_EQ(read.probes[i].boxMin, probes[i].boxMin);
        EXPECT_EQ(read.probes[i].entity, probes[i].entity);
    }
    EXPECT_EQ(world::probeTexelCount(64), 6u * (64 * 64 + 32 * 32 + 16 * 16 + 8 * 8 + 16 + 4 + 1));
    const package::ProbeContents none = package::decodeProbeSection({}, level, "test");
    EXPECT_FALSE(none.present);
}

TEST(ProbeSection, RejectsCorruptedAndOutOfRangeRecords) {
    world::CompiledLevel level;
    world::Entity e;  // not a probe entity
    level.entities.push_back(e);
    const package::RawSection good = package::encodeProbeSection({smallProbe(4, 0)});
    const size_t probeAt = sizeof(package::DiskProbeHeader);
    struct Case {
        const char* what;
        size_t offset;  // bytes into the section; SIZE_MAX: truncate by 4 bytes
        uint32_t value;
        const char* expect;  // in the error
    };
    const auto field = [&](size_t member) { return probeAt + member; };
    const float nan = NAN;
    uint32_t nanBits;
    std::memcpy(&nanBits, &nan, 4);
    const std::vector<Case> cases = {
        {"truncated", SIZE_MAX, 0, "bytes"},
        {"probe count", 0, 2, "probeCount 2"},
        {"texel format", 8, 7, "texelFormat 7"},
        {"position NaN", field(offsetof(package::DiskProbe, position)), nanBits, "not finite"},
        {"boxMax NaN", field(offsetof(package::DiskProbe, boxMax) + 8), nanBits,
         "boxMax[2] = nan: not finite"},
        {"E_avg zero", field(offsetof(package::DiskProbe, irradianceAverage)), 0,
         "irradianceAverage"},
        {"face size", field(offsetof(package::DiskProbe, faceSize)), 3, "faceSize 3"},
        {"mip count", field(offsetof(package::DiskProbe, mipCount)), 5, "mipCount 5"},
        {"texel count", field(offsetof(package::DiskProbe, texelCount)), 12, "texelCount 12"},
        {"first texel", field(offsetof(package::DiskProbe, firstTexel)), 1, "texels [1"},
        {"entity", field(offsetof(package::DiskProbe, entity)), 0, "entity 0"},
        {"entity range", field(offsetof(package::DiskProbe, entity)), 9, "entity 9"},
        {"reserved", field(offsetof(package::DiskProbe, reserved)), 1, "reserved 1"},
    };
    for (const Case& c : cases) {
        package::RawSection bad = good;
        if (c.offset == SIZE_MAX) {
            bad.bytes.resize(bad.bytes.size() - 4);
            bad.count -= 4;
        } else {
            std::memcpy(bad.bytes.data() + c.offset, &c.value, 4);
        }
        const std::string error = test::errorMessage(
            [&] { (void)package::decodeProbeSection(std::span(&bad, 1), level, "pkg"); });
        ASSERT_NE(error, "") << c.what;
        EXPECT_NE(error.find("section probes"), std::string::npos) << error;
        EXPECT_NE(error.find(c.expect), std::string::npos) << c.what << ": " << error;
    }
    const std::vector<package::RawSection> twice = {good, good};
    EXPECT_NE(test::errorMessage([&] {
                  (void)package::decodeProbeSection(twice, level, "pkg");
              }).find("appears twice"),
              std::string::npos);
}

TEST(ProbeSection, SurvivesAWholePackage) {
    world::CompiledLevel level;
    level.bspLeaves.resize(1);
    level.settings.texelsPerMetre = 8.0f;
    const package::RawSection section = package::encodeProbeSection({smallProbe(16, 2)});
    // Probes without the rest of a bake, which a loader refuses: the writer's unchecked bytes.
    const std::vector<uint8_t> bytes =
        package::serializeUncheckedPackage(level, std::span(&section, 1));
    const package::PackageContents read = package::parsePackage(bytes, "pkg");
    const package::ProbeContents probes =
        package::decodeProbeSection(read.bakedSections, read.level, "pkg");
    ASSERT_EQ(probes.probes.size(), 1u);
    EXPECT_EQ(probes.probes[0].texels, smallProbe(16, 2).texels);
}
