// Probe bake figures: capture and prefilter time per probe and bytes per probe, at a quality
// preset, in the agreement room (tests/bake/bake_scenes.hpp) from its centre.
//   onelight-bench-probes [draft|default|high]
#include <chrono>
#include <cstdio>
#include <string>

#include <tbb/global_control.h>

#include "bake/bake_level.hpp"
#include "bake_scenes.hpp"
#include "world/compile/static_split.hpp"
#include "world/package/format.hpp"

using namespace onelight;
using namespace onelight::bake;

int main(int argc, char** argv) {
    BakeOptions options;
    if (argc > 1 && !parseQuality(argv[1], options.quality)) {
        std::fprintf(stderr, "usage: onelight-bench-probes [draft|default|high]\n");
        return 2;
    }
    const ProbeCaptureSettings settings = probeSettings(options);
    const world::SourceLevel source = test::agreementRoom();
    const EmbreeDevice device;
    const world::SplitLevel split = world::splitStaticDynamic(source);
    const BakeScene scene(device, split.staticGeometry, loadSceneMaterials(source));
    const BakeLights lights = makeBakeLights(scene, source.lights, LightSizes{}, glm::vec3(0.0f));
    const glm::vec3 position(0.0f, 0.0f, 1.5f);

    using clock = std::chrono::steady_clock;
    auto start = clock::now();
    RayCounts rays;
    Cubemap cube = captureProbe(scene, lights, position, 0, settings, nullptr, rays);
    const double capture = std::chrono::duration<double>(clock::now() - start).count();
    start = clock::now();
    const world::EnvironmentProbe probe = finishProbe(std::move(cube), ProbePlacement{position},
                                                      IrradianceCube{}, settings.prefilter);
    const double prefilter = std::chrono::duration<double>(clock::now() - start).count();
    const size_t bytes = sizeof(package::DiskProbe) + probe.texels.size() * sizeof(uint32_t);
    const size_t threads =
        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
    std::printf("quality %s: face %u, %u paths/texel, %u mips, %zu threads\n",
                qualityName(options.quality), settings.faceSize, settings.samplesPerTexel,
                probe.mipCount, threads);
    std::printf("capture   %.3f s (%.2f Mrays, %.2f Mrays/s)\n", capture,
                double(rays.total()) * 1e-6, double(rays.total()) * 1e-6 / capture);
    std::printf("prefilter %.3f s (normalise, GGX mips, RGB9E5 pack)\n", prefilter);
    std::printf("bytes per probe %zu (%zu texels x 4 + %zu record)\n", bytes, probe.texels.size(),
                sizeof(package::DiskProbe));
    return 0;
}
