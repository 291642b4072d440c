#include "probe_capture.hpp"

#include <tbb/enumerable_thread_specific.h>

#include "bake/lighting/sampling.hpp"
#include "bake/parallel_for.hpp"
#include "shading.hpp"

namespace onelight::bake {
namespace {

constexpr uint32_t kProbePass = 6;  // seedFrom's pass id (reference 4 and 5)

}  // namespace

glm::vec3 ambientCubeAverage(const std::array<glm::vec3, 6>& ambientCube) {
    glm::vec3 sum(0.0f);
    for (const glm::vec3& face : ambientCube) sum += face;
    return sum / 6.0f;
}

Cubemap captureProbe(const BakeScene& scene, const BakeLights& lights, glm::vec3 position,
                     uint32_t probeIndex, const ProbeCaptureSettings& settings, Progress* progress,
                     RayCounts& rays) {
    const int size = int(settings.faceSize);
    Cubemap cube = makeCubemap(size);
    const uint32_t n = std::max(1u, settings.samplesPerTexel);
    const float area = (2.0f / float(size)) * (2.0f / float(size));
    // Each ray's footprint: its share of the texel's solid angle (about area at the face centre).
    const RayCone cone{0.0f, sampleSpread(area, n)};
    tbb::enumerable_thread_specific<RayCounts> counts;
    bake::parallelFor(tbb::blocked_range<int>(0, 6 * size), [&](const auto& rows) {
        RayCounts& local = counts.local();
        for (int row = rows.begin(); row != rows.end(); ++row) {
            const int face = row / size, y = row % size;
            for (int x = 0; x < size; ++x) {
                Rng rng{seedFrom(probeIndex, uint32_t(face), uint32_t(y * size + x), kProbePass)};
                const float s0 = rng.next(), s1 = rng.next();
                glm::dvec3 sum(0.0);
                for (uint32_t i = 0; i < n; ++i) {
                    const glm::vec2 jitter = rotatedHammersley(i, n, s0, s1);
                    const glm::vec2 uv((float(x) + jitter.x) / float(size),
                                       (float(y) + jitter.y) / float(size));
                    const float px = 2.0f * uv.x - 1.0f, py = 2.0f * uv.y - 1.0f;
                    const float r2 = px * px + py * py + 1.0f;
                    const float weight = 1.0f / (r2 * std::sqrt(r2));  // pdf(w) = r^3 / A
                    const glm::vec3 dir = glsl::cubeDirection(face, uv);
                    sum += glm::dvec3(traceRadiance(scene, lights, settings.transport, position,
                                                    dir, cone, rng, local)) *
                           double(weight);
                }
                cube.mips[0].at(face, x, y) = glm::vec3(
                    sum * double(area) / (double(n) * double(texelSolidAngle(x, y, size))));
            }
        }
        if (progress) progress->advance(rows.size());
    });
    for (const RayCounts& r : counts) rays += r;
    return cube;
}

std::vector<uint32_t> packProbeTexels(const Cubemap& cube) {
    std::vector<uint32_t> texels;
    for (const CubeMip& mip : cube.mips)
        for (const glm::vec3& t : mip.texels) texels.push_back(package::encodeRgb9e5(t));
    return texels;
}

Cubemap unpackProbeTexels(const world::EnvironmentProbe& probe) {
    Cubemap cube = makeCubemap(int(probe.faceSize));
    size_t next = 0;
    for (CubeMip& mip : cube.mips)
        for (glm::vec3& t : mip.texels)
            t = next < probe.texels.size() ? package::decodeRgb9e5(probe.texels[next++])
                                           : glm::vec3(0.0f);
    return cube;
}

world::EnvironmentProbe finishProbe(Cubemap radiance, const ProbePlacement& placement,
                                    const IrradianceCube& irradiance,
                                    const PrefilterOptions& options) {
    const glm::vec3 averageIrradiance = ambientCubeAverage(irradiance);
    world::EnvironmentProbe probe;
    probe.position = placement.position;
    probe.boxMin = placement.boxMin;
    probe.boxMax = placement.boxMax;
    probe.entity = placement.entity;
    probe.irradianceAverage = glm::max(averageIrradiance, glm::vec3(glsl::PROBE_MIN_IRRADIANCE));
    for (size_t f = 0; f < 6; ++f)
        probe.irradianceCube[f] = glm::max(irradiance[f], glm::vec3(0.0f));
    for (glm::vec3& t : radiance.mips[0].texels) t = glsl::probeNormalize(t, averageIrradiance);
    const Cubemap filtered = prefilterGGX(std::move(radiance), options);
    probe.faceSize = uint32_t(filtered.mips[0].size);
    probe.mipCount = uint32_t(filtered.mipCount());
    probe.texels = packProbeTexels(filtered);
    return probe;
}

std::vector<world::EnvironmentProbe> bakeProbes(const BakeScene& scene, const BakeLights& lights,
                                                const std::vector<ProbePlacement>& placements,
                                                const std::vector<IrradianceCube>& irradiance,
                                                const ProbeCaptureSettings& settings, size_t begin,
                                                size_t end, bool showProgress, RayCounts& rays) {
    std::vector<world::EnvironmentProbe> probes;
    end = std::min(end, placements.size());
    begin = std::min(begin, end);
    Progress progress("probes", uint64_t(end - begin) * 6 * settings.faceSize, showProgress);
    for (size_t i = begin; i < end; ++i) {
        Cubemap cube = captureProbe(scene, lights, placements[i].position, uint32_t(i), settings,
                                    &progress, rays);
        const IrradianceCube around = i < irradiance.size() ? irradiance[i] : IrradianceCube{};
        probes.push_back(finishProbe(std::move(cube), placements[i], around, settings.prefilter));
    }
    progress.finish();
    return probes;
}

}  // namespace onelight::bake
