// onelight-bench-compile [--triangles N] [--keep DIR]: generates a level of about N static
// triangles (default 250000), then times import, compile and package write, and reports the
// peak resident memory (getrusage). A benchmark, not a test.
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tests/world/level_generator.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/compile/compile_level.hpp"
#include "world/file_write.hpp"
#include "world/import/gltf_import.hpp"
#include "world/package/package_writer.hpp"

namespace {

double seconds(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double peakRssMib() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace

int main(int argc, char** argv) {
    uint64_t triangles = 250000;
    std::string keep;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--triangles" && i + 1 < argc)
            triangles = std::strtoull(argv[++i], nullptr, 10);
        else if (a == "--keep" && i + 1 < argc)
            keep = argv[++i];
        else {
            std::fprintf(stderr, "usage: onelight-bench-compile [--triangles N] [--keep DIR]\n");
            return 2;
        }
    }
    using namespace onelight;
    const test::GeneratedLevelOptions options = test::optionsForTriangles(triangles);
    const std::filesystem::path folder =
        keep.empty() ? test::freshFolder("bench") : std::filesystem::path(keep);
    std::filesystem::create_directories(folder);
    const std::string path = test::writeGeneratedLevel(folder, "bench_level", options);
    const double rssAfterGenerate = peakRssMib();
    try {
        auto start = std::chrono::steady_clock::now();
        const world::SourceLevel source = world::importGltf(path);
        const double importS = seconds(start);
        start = std::chrono::steady_clock::now();
        const world::CompileResult result = world::compileLevel(source, world::CompileOptions{});
        const double compileS = seconds(start);
        start = std::chrono::steady_clock::now();
        const std::vector<uint8_t> bytes = package::serializePackage(result.level);
        world::writeFileAtomically((folder / "bench_level.olpak").string(), bytes);
        const double writeS = seconds(start);
        const world::CompileStats& s = result.stats;
        std::printf("level      %s (%llu static triangles generated)\n", path.c_str(),
                    static_cast<unsigned long long>(test::generatedTriangleCount(options)));
        std::printf(
            "result     %llu triangles, %llu surfaces, bsp depth %u / %llu leaves, %llu charts in "
            "%llu atlases, "
            "%zu bytes\n",
            static_cast<unsigned long long>(s.triangles),
            static_cast<unsigned long long>(s.surfaces), s.bspDepth,
            static_cast<unsigned long long>(s.bspLeaves), static_cast<unsigned long long>(s.charts),
            static_cast<unsigned long long>(s.atlases), bytes.size());
        std::printf(
            "time       import %.3f s, compile %.3f s (split %.3f, regions %.3f, charts %.3f, bsp "
            "%.3f, "
            "surfaces %.3f), write %.3f s, total %.3f s\n",
            importS, compileS, s.secondsSplit, s.secondsRegions, s.secondsCharts, s.secondsBsp,
            s.secondsSurfaces, writeS, importS + compileS + writeS);
        std::printf("memory     peak RSS %.1f MiB (%.1f MiB after generating the level)\n",
                    peakRssMib(), rssAfterGenerate);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "onelight-bench-compile: %s\n", e.what());
        return 1;
    }
    if (keep.empty()) std::filesystem::remove_all(folder);
    return 0;
}
