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
#include "world/import/gltf_import.hpp"
#include "world/package/package_writer.hpp"

namespace {

double seconds(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double peak_rss_mib() {
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
    const test::GeneratedLevelOptions options = test::options_for_triangles(triangles);
    const std::filesystem::path folder =
        keep.empty() ? test::fresh_folder("bench") : std::filesystem::path(keep);
    std::filesystem::create_directories(folder);
    const std::string path = test::write_generated_level(folder, "bench_level", options);
    const double rss_after_generate = peak_rss_mib();
    try {
        auto start = std::chrono::steady_clock::now();
        const world::SourceLevel source = world::import_gltf(path);
        const double import_s = seconds(start);
        start = std::chrono::steady_clock::now();
        const world::CompileResult result = world::compile_level(source, world::CompileOptions{});
        const double compile_s = seconds(start);
        start = std::chrono::steady_clock::now();
        const std::vector<uint8_t> bytes = package::serialize_package(result.level);
        package::write_file_atomically((folder / "bench_level.olpak").string(), bytes);
        const double write_s = seconds(start);
        const world::CompileStats& s = result.stats;
        std::printf("level      %s (%llu static triangles generated)\n", path.c_str(),
                    static_cast<unsigned long long>(test::generated_triangle_count(options)));
        std::printf(
            "result     %llu triangles, %llu surfaces, bsp depth %u / %llu leaves, %llu charts in "
            "%llu atlases, "
            "%zu bytes\n",
            static_cast<unsigned long long>(s.triangles),
            static_cast<unsigned long long>(s.surfaces), s.bsp_depth,
            static_cast<unsigned long long>(s.bsp_leaves),
            static_cast<unsigned long long>(s.charts), static_cast<unsigned long long>(s.atlases),
            bytes.size());
        std::printf(
            "time       import %.3f s, compile %.3f s (split %.3f, regions %.3f, charts %.3f, bsp "
            "%.3f, "
            "surfaces %.3f), write %.3f s, total %.3f s\n",
            import_s, compile_s, s.seconds_split, s.seconds_regions, s.seconds_charts,
            s.seconds_bsp, s.seconds_surfaces, write_s, import_s + compile_s + write_s);
        std::printf("memory     peak RSS %.1f MiB (%.1f MiB after generating the level)\n",
                    peak_rss_mib(), rss_after_generate);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "onelight-bench-compile: %s\n", e.what());
        return 1;
    }
    if (keep.empty()) std::filesystem::remove_all(folder);
    return 0;
}
