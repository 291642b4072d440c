// onelight-bench-bake: issue 5's benchmark (not a test). In one run:
//  1. Ray throughput. The rays the lightmap stage traces on a generated level (tests/world's
//     level generator, ~250k triangles) are recorded through BakeScene::observeRays, then
//     replayed, same scene, same thread count, same grain: (a) through the baker's own per-ray
//     path (BakeScene::occluded / intersect), (b) through raw rtcOccluded1 / rtcIntersect1 and
//     (c) through raw rtcOccluded16 / rtcIntersect16 in packets of 16 in trace order. The whole
//     level is baked at a density giving ~20k texels (the bounce passes read every texel, so a
//     part of a level costs its whole cache). The lightmap stage (shading, sampling,
//     cache, denoiser) is also timed on the same texels: its
//     rays/s against raw Embree on its own rays is the baker's ratio (issue goal >= 0.85).
//  2. Speed against error: the lightmap-vs-reference agreement test's room baked at draft,
//     default and high; wall time and RMS relative error of texel irradiance against
//     referenceIrradiance at the same points (computed once, in two independent halves so its
//     own noise is measured too). Also written as CSV with --csv.
//  3. Scaling: the same room at 1x, 2x and 4x texels (texels_per_metre x1, x sqrt 2, x2).
//  4. Peak memory per bake: ru_maxrss after resetting the high-water mark (/proc/self/clear_refs).
//  5. Materials: a textured room (bake_scenes.hpp texturedRoomWithProbes: base colour, a normal
//     map, an emissive panel, a MASK grate) against the same room with its factors only; the
//     rays/s ratio is the cost of reading textures at every hit.
// Timings on 2 cores spread up to 1.6x between runs: compare ratios within one run.
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "bake/bake_level.hpp"
#include "bake/lightmap/lightmap_bake.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "bake/materials/bake_textures.hpp"
#include "bake/reference/path_tracer.hpp"
#include "bake_scenes.hpp"
#include "tests/world/level_generator.hpp"
#include "world/compile/compile_level.hpp"
#include "world/import/gltf_import.hpp"

namespace onelight::bake {
namespace {

struct BenchOptions {
    uint64_t triangles = 250000;         // generated level for the ray throughput
    uint64_t texels = 20000;             // about this many lightmap texels: their rays are replayed
    uint32_t referenceSpp = 65536;       // referenceIrradiance samples per point (two halves)
    uint32_t stride = 11;                // every stride-th texel sample is an error point
    float roomTexelsPerMetre = 6.0f;     // speed-against-error room (the agreement test's)
    float scalingTexelsPerMetre = 8.0f;  // 1x of the scaling bakes
    uint32_t repeats = 3;                // replays per path; the fastest counts
    uint32_t threads = 0;                // 0: every core
    bool throughputOnly = false;         // part 1 only (for profiling)
    bool materialsOnly = false;          // part 5 only
    bool lightsOnly = false;             // part 4 only
    float lightsTexelsPerMetre = 16.0f;  // the many-lights floor
    std::string csv;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string line;
    std::getline(in, line);
    return line.empty() ? "unknown" : line;
}

/// Resets the process's peak resident set ("5" to /proc/self/clear_refs, Linux >= 4.0), so the
/// next ru_maxrss is the peak of what runs after it. False when the kernel refuses.
bool resetPeakMemory() {
    std::ofstream out("/proc/self/clear_refs");
    out << "5";
    out.flush();
    return static_cast<bool>(out);
}

/// Resident memory now (/proc/self/statm, second field, in pages).
uint64_t residentBytes() {
    std::ifstream in("/proc/self/statm");
    uint64_t size = 0, resident = 0;
    in >> size >> resident;
    return resident * uint64_t(sysconf(_SC_PAGESIZE));
}

double mib(uint64_t bytes) {
    return double(bytes) / (1024.0 * 1024.0);
}

// ---------------------------------------------------------------------------------------------
// 1. Ray throughput

/// Every ray of a stage, per thread in trace order (so a replay keeps the baker's coherence).
struct RayLog {
    tbb::enumerable_thread_specific<std::vector<TracedRay>> perThread;
    static void record(void* user, const TracedRay& ray) {
        static_cast<RayLog*>(user)->perThread.local().push_back(ray);
    }
};

/// Same grain for every replay: each task traces this many rays.
constexpr size_t kReplayGrain = 256;

/// Wall and process CPU seconds of a measured run. The CPU time is what the process's own
/// threads spent, so a ratio of CPU times holds when other processes share the cores.
struct Timing {
    double wall = 1e30, cpu = 1e30;
    void keepFastest(const Timing& t) {
        wall = std::min(wall, t.wall);
        cpu = std::min(cpu, t.cpu);
    }
};

double processCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

template <typename Run>
Timing measure(const Run& run) {
    const double cpu = processCpuSeconds();
    const auto start = std::chrono::steady_clock::now();
    run();
    return {secondsSince(start), processCpuSeconds() - cpu};
}

/// Runs body(begin, end) over [0, n) in parallel.
template <typename Body>
Timing timeParallel(size_t n, const Body& body) {
    return measure([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kReplayGrain),
                          [&](const tbb::blocked_range<size_t>& r) { body(r.begin(), r.end()); });
    });
}

/// The baker's per-ray path: BakeScene::occluded / intersect (context, ray set-up, hit data).
Timing replayBaker(const BakeScene& scene, const std::vector<TracedRay>& rays, bool occlusion,
                   std::atomic<uint64_t>& hits) {
    return timeParallel(rays.size(), [&](size_t begin, size_t end) {
        uint64_t counter = 0, found = 0;
        for (size_t i = begin; i < end; ++i) {
            const TracedRay& r = rays[i];
            if (occlusion)
                found += scene.occluded(r.origin, r.dir, r.maxDistance, counter);
            else
                found += scene.intersect(r.origin, r.dir, r.maxDistance, counter).found;
        }
        hits += found;
    });
}

/// Raw Embree on the same rays: one context per task, the ray filled from the record, nothing
/// read back but the hit flag.
Timing replayRaw(RTCScene scene, const std::vector<TracedRay>& rays, bool occlusion,
                 std::atomic<uint64_t>& hits) {
    return timeParallel(rays.size(), [&](size_t begin, size_t end) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        uint64_t found = 0;
        for (size_t i = begin; i < end; ++i) {
            const TracedRay& r = rays[i];
            RTCRayHit q = embreeRay(r.origin, r.dir, r.maxDistance);
            if (occlusion) {
                rtcOccluded1(scene, &context, &q.ray);
                found += q.ray.tfar < 0.0f;
            } else {
                rtcIntersect1(scene, &context, &q);
                found += q.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            }
        }
        hits += found;
    });
}

/// Raw Embree on the same rays in packets of 16 consecutive rays of a thread's trace order
/// (rtcOccluded16 / rtcIntersect16, the last packet masked): what tracing in packets would buy
/// on the baker's own rays, before any cost of gathering them into packets.
Timing replayPackets(RTCScene scene, const std::vector<TracedRay>& rays, bool occlusion,
                     std::atomic<uint64_t>& hits) {
    return timeParallel(rays.size(), [&](size_t begin, size_t end) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        uint64_t found = 0;
        alignas(64) RTCRayHit16 q;
        alignas(64) int valid[16];
        for (size_t first = begin; first < end; first += 16) {
            const size_t n = std::min<size_t>(16, end - first);
            for (size_t k = 0; k < 16; ++k) {
                const TracedRay& r = rays[first + std::min(k, n - 1)];
                valid[k] = k < n ? -1 : 0;
                q.ray.org_x[k] = r.origin.x;
                q.ray.org_y[k] = r.origin.y;
                q.ray.org_z[k] = r.origin.z;
                q.ray.tnear[k] = 0.0f;
                q.ray.dir_x[k] = r.dir.x;
                q.ray.dir_y[k] = r.dir.y;
                q.ray.dir_z[k] = r.dir.z;
                q.ray.time[k] = 0.0f;
                q.ray.tfar[k] = r.maxDistance;
                q.ray.mask[k] = 0xFFFFFFFFu;
                q.ray.id[k] = 0;
                q.ray.flags[k] = 0;
                q.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                q.hit.primID[k] = RTC_INVALID_GEOMETRY_ID;
                q.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
            }
            if (occlusion) {
                rtcOccluded16(valid, scene, &context, &q.ray);
                for (size_t k = 0; k < n; ++k) found += q.ray.tfar[k] < 0.0f;
            } else {
                rtcIntersect16(valid, scene, &context, &q);
                for (size_t k = 0; k < n; ++k) found += q.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
            }
        }
        hits += found;
    });
}

double mrays(uint64_t rays, double seconds) {
    return seconds > 0.0 ? double(rays) / seconds * 1e-6 : 0.0;
}

/// The lightmap stage over every range.
LightmapStats bakeRanges(const BakeScene& scene, const BakeLights& lights,
                         const world::CompiledLevel& level, const std::vector<TexelSample>& samples,
                         const LightmapSettings& settings,
                         const std::vector<std::pair<uint64_t, uint64_t>>& ranges,
                         world::BakedLighting& baked) {
    LightmapStats all;
    for (const auto& [begin, end] : ranges) {
        const LightmapStats s =
            bakeLightmapTexels(scene, lights, level, samples, settings, begin, end, baked, nullptr);
        all.rays += s.rays;
        all.texelsBaked += s.texelsBaked;
    }
    return all;
}

bool rayThroughput(const BenchOptions& o) {
    std::printf("\n== 1. Ray throughput: lightmap rays of a generated level ==\n");
    const auto start = std::chrono::steady_clock::now();
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / "onelight-bench-bake";
    std::filesystem::create_directories(folder);
    const onelight::test::GeneratedLevelOptions generated =
        onelight::test::optionsForTriangles(o.triangles);
    const std::string path = onelight::test::writeGeneratedLevel(folder, "bench_level", generated);
    const world::SourceLevel source = world::importGltf(path);
    // The whole level is baked (its bounce passes read every texel, so a part of the level
    // costs the cache of all of it): the density is chosen for about o.texels texels.
    world::CompileOptions compile;
    compile.charts.texelsPerMetre = 4.0;
    world::CompiledLevel level = world::compileLevel(source, compile).level;
    const uint64_t firstCount = placeTexels(level).size();
    if (firstCount > 0) {
        compile.charts.texelsPerMetre =
            std::min(4.0, 4.0 * std::sqrt(double(o.texels) / double(firstCount)));
        level = world::compileLevel(source, compile).level;
    }
    const EmbreeDevice device;
    BakeScene scene(device, level);
    const BakeLights lights = makeBakeLights(scene, level.lights, {}, glm::vec3(0.0f));
    const std::vector<TexelSample> samples = placeTexels(level);
    if (samples.empty()) {
        std::printf("the generated level has no lightmap texels\n");
        return false;
    }
    const std::vector<std::pair<uint64_t, uint64_t>> ranges = {{0, totalTexels(level)}};
    BakeOptions draft;
    draft.quality = BakeQuality::kDraft;
    const LightmapSettings settings = lightmapSettings(draft);
    world::BakedLighting baked;
    baked.texels.assign(totalTexels(level), world::LightmapTexel{});
    baked.shadowMask.assign(totalTexels(level), 0);
    std::printf(
        "level      %u triangles, %zu lights, %zu texel samples (%.2f texels/m); setup %.1f s\n",
        scene.triangleCount(), lights.lights.size(), samples.size(), compile.charts.texelsPerMetre,
        secondsSince(start));

    // Record the rays of a draft lightmap bake of the chosen texels.
    RayLog log;
    scene.observeRays(&RayLog::record, &log);
    const LightmapStats recorded =
        bakeRanges(scene, lights, level, samples, settings, ranges, baked);
    scene.observeRays(nullptr, nullptr);
    std::vector<TracedRay> occlusion, closest;
    for (const std::vector<TracedRay>& rays : log.perThread)
        for (const TracedRay& r : rays) (r.occlusion ? occlusion : closest).push_back(r);
    log.perThread.clear();

    // The whole stage again, unobserved, and the replays, interleaved so that changes in the
    // machine's load hit every path alike; the fastest of the repeats counts.
    Timing stage, occlusionBaker, occlusionRaw, closestBaker, closestRaw, occlusionPackets,
        closestPackets;
    LightmapStats stats;
    std::atomic<uint64_t> hits[6] = {0, 0, 0, 0, 0, 0};
    for (uint32_t i = 0; i < o.repeats; ++i) {
        stage.keepFastest(measure(
            [&] { stats = bakeRanges(scene, lights, level, samples, settings, ranges, baked); }));
        occlusionBaker.keepFastest(replayBaker(scene, occlusion, true, hits[0]));
        occlusionRaw.keepFastest(replayRaw(scene.embreeScene(), occlusion, true, hits[1]));
        closestBaker.keepFastest(replayBaker(scene, closest, false, hits[2]));
        closestRaw.keepFastest(replayRaw(scene.embreeScene(), closest, false, hits[3]));
        occlusionPackets.keepFastest(replayPackets(scene.embreeScene(), occlusion, true, hits[4]));
        closestPackets.keepFastest(replayPackets(scene.embreeScene(), closest, false, hits[5]));
    }
    const uint64_t total = occlusion.size() + closest.size();
    std::printf(
        "texels     %llu, the whole level (draft: %u shadow rays per light, %u bounce passes of "
        "%u directions, then %u)\n",
        static_cast<unsigned long long>(stats.texelsBaked), settings.shadowSamples,
        settings.bouncePasses, settings.cacheSamples, settings.indirectSamples);
    std::printf(
        "rays       %llu recorded = %llu counted by the stage (shadow %llu, bounce %llu, "
        "probe %llu)\n",
        static_cast<unsigned long long>(total),
        static_cast<unsigned long long>(recorded.rays.total()),
        static_cast<unsigned long long>(recorded.rays.shadow),
        static_cast<unsigned long long>(recorded.rays.bounce),
        static_cast<unsigned long long>(recorded.rays.probe));
    if (hits[0] != hits[1] || hits[2] != hits[3] || hits[1] != hits[4] || hits[3] != hits[5])
        std::printf("WARNING: the baker's, raw and packet replays disagree on hits\n");
    const Timing raw{occlusionRaw.wall + closestRaw.wall, occlusionRaw.cpu + closestRaw.cpu};
    const Timing bakerPath{occlusionBaker.wall + closestBaker.wall,
                           occlusionBaker.cpu + closestBaker.cpu};
    std::printf("\n%-44s %9s %11s %9s %13s %11s\n", "same rays, same scene, same threads", "count",
                "baker Mr/s", "raw Mr/s", "ratio (wall)", "ratio (CPU)");
    const auto row = [](const char* name, uint64_t count, const Timing& baker, const Timing& rawT,
                        const char* note) {
        std::printf("%-44s %9llu %11.2f %9.2f %13.3f %11.3f%s\n", name,
                    static_cast<unsigned long long>(count), mrays(count, baker.wall),
                    mrays(count, rawT.wall), rawT.wall / baker.wall, rawT.cpu / baker.cpu, note);
    };
    row("occlusion: shadow (+ filter visibility)", occlusion.size(), occlusionBaker, occlusionRaw,
        "");
    row("closest hit: bounce (+ inside probes)", closest.size(), closestBaker, closestRaw, "");
    row("all, baker's per-ray path", total, bakerPath, raw, "");
    row("all, whole lightmap stage (shading incl.)", stats.rays.total(), stage, raw,
        "   <- issue goal >= 0.85");
    std::printf("%-44s %9zu %11.2f %9.2f %13.3f %11.3f\n",
                "occlusion in packets of 16 (raw / packets)", occlusion.size(),
                mrays(occlusion.size(), occlusionPackets.wall),
                mrays(occlusion.size(), occlusionRaw.wall),
                occlusionRaw.wall / occlusionPackets.wall, occlusionRaw.cpu / occlusionPackets.cpu);
    std::printf("%-44s %9zu %11.2f %9.2f %13.3f %11.3f\n",
                "closest hit in packets of 16 (raw / packets)", closest.size(),
                mrays(closest.size(), closestPackets.wall), mrays(closest.size(), closestRaw.wall),
                closestRaw.wall / closestPackets.wall, closestRaw.cpu / closestPackets.cpu);
    std::printf(
        "wall s: stage %.3f, raw Embree on its rays %.3f (occlusion %.3f + closest hit "
        "%.3f); CPU s: stage %.3f, raw %.3f; peak memory so far %.1f MiB\n",
        stage.wall, raw.wall, occlusionRaw.wall, closestRaw.wall, stage.cpu, raw.cpu,
        mib(peakMemoryBytes()));
    std::filesystem::remove_all(folder);
    return true;
}

// ---------------------------------------------------------------------------------------------
// 2. Speed against error, 3. scaling, 4. peak memory

struct Bake {
    BakeResult result;
    double seconds = 0.0;
    uint64_t peakBytes = 0;       // ru_maxrss after the bake
    uint64_t residentBefore = 0;  // what the process held before it (the floor of the peak)
    bool peakIsPerBake = false;
};

Bake timedBake(const world::SourceLevel& level, const BakeOptions& options) {
    Bake b;
    b.residentBefore = residentBytes();
    b.peakIsPerBake = resetPeakMemory();
    const auto start = std::chrono::steady_clock::now();
    b.result = bakeLevel(level, options);
    b.seconds = secondsSince(start);
    b.peakBytes = peakMemoryBytes();
    return b;
}

double stageSeconds(const BakeReport& report, const std::string& name) {
    for (const StageReport& s : report.stages)
        if (s.name == name) return s.seconds;
    return 0.0;
}

RayCounts stageRays(const BakeReport& report) {
    RayCounts all;
    for (const StageReport& s : report.stages) all += s.rays;
    return all;
}

/// A reference point: a texel centre inside its triangle.
struct ErrorPoint {
    size_t sample = 0;
    float reference = 0.0f;  // luminance, lux
};

bool speedAgainstError(const BenchOptions& o) {
    std::printf("\n== 2. Speed against error: the agreement test's room (%.0f texels/m) ==\n",
                double(o.roomTexelsPerMetre));
    const world::SourceLevel level = test::agreementRoom();
    const BakeQuality qualities[3] = {BakeQuality::kDraft, BakeQuality::kDefault,
                                      BakeQuality::kHigh};
    std::vector<Bake> bakes;
    std::vector<TexelSample> samples;
    std::vector<ErrorPoint> points;
    double referenceNoise = 0.0, referenceSeconds = 0.0;
    for (const BakeQuality q : qualities) {
        bakes.push_back(timedBake(level, test::testOptions(o.roomTexelsPerMetre, q)));
        const BakeResult& r = bakes.back().result;
        if (!points.empty()) {
            if (placeTexels(r.level).size() != samples.size()) {
                std::printf("the room compiled differently at %s\n", qualityName(q));
                return false;
            }
            continue;
        }
        // The reference at the first bake's points, once: two halves with independent seeds;
        // their difference measures its own noise.
        const auto start = std::chrono::steady_clock::now();
        samples = placeTexels(r.level);
        const EmbreeDevice device;
        const BakeScene scene(device, r.level);
        const BakeLights lights = makeBakeLights(scene, level.lights, {}, glm::vec3(0.0f));
        std::vector<size_t> chosen;
        for (size_t i = 0; i < samples.size(); i += o.stride)
            if (samples[i].centreInside) chosen.push_back(i);
        std::vector<float> first(chosen.size()), second(chosen.size());
        tbb::parallel_for(size_t(0), chosen.size(), [&](size_t k) {
            RayCounts rays;
            const TexelSample& s = samples[chosen[k]];
            const uint32_t half = std::max(1u, o.referenceSpp / 2);
            first[k] = luminance(referenceIrradiance(scene, lights, s.position, s.normal, half,
                                                     uint32_t(2 * chosen[k]), {}, rays));
            second[k] = luminance(referenceIrradiance(scene, lights, s.position, s.normal, half,
                                                      uint32_t(2 * chosen[k] + 1), {}, rays));
        });
        double noiseSq = 0.0;
        for (size_t k = 0; k < chosen.size(); ++k) {
            const float want = 0.5f * (first[k] + second[k]);
            if (want < 1.0f) continue;  // relative error of near-black points is noise
            points.push_back({chosen[k], want});
            const double halfDifference = 0.5 * double(first[k] - second[k]) / double(want);
            noiseSq += halfDifference * halfDifference;
        }
        referenceNoise = std::sqrt(noiseSq / double(std::max<size_t>(1, points.size())));
        referenceSeconds = secondsSince(start);
    }
    const BakeLights lights = makePunctualLights(level.lights, {}, glm::vec3(0.0f));
    std::printf(
        "reference  %zu points (every %u-th texel centre, >= 1 lux), %u samples each, "
        "%.1f s; its own RMS noise %.3f%%\n",
        points.size(), o.stride, o.referenceSpp, referenceSeconds, 100.0 * referenceNoise);
    std::printf("\n%-8s %7s %7s %9s %9s %11s %8s %10s %11s %10s %10s\n", "quality", "shadow",
                "paths", "bake s", "lightmap s", "rays", "Mrays/s", "est.noise", "RMS error",
                "peak MiB", "before MiB");
    std::FILE* csv = o.csv.empty() ? nullptr : std::fopen(o.csv.c_str(), "w");
    if (!o.csv.empty() && !csv) std::printf("cannot write %s\n", o.csv.c_str());
    if (csv)
        std::fprintf(csv,
                     "quality,shadow_samples,indirect_samples,bake_seconds,lightmap_seconds,rays,"
                     "rms_relative_error,reference_noise,peak_memory_mib\n");
    for (const Bake& b : bakes) {
        const BakeResult& r = b.result;
        double sumSq = 0.0;
        for (const ErrorPoint& p : points) {
            const float got =
                luminance(lightmapTotalIrradiance(lights, r.level, r.baked, samples[p.sample]));
            const double rel = (double(got) - double(p.reference)) / double(p.reference);
            sumSq += rel * rel;
        }
        const double rms = std::sqrt(sumSq / double(std::max<size_t>(1, points.size())));
        const uint64_t rays = stageRays(r.report).total();
        std::printf("%-8s %7u %7u %9.2f %10.2f %11llu %8.2f %9.2f%% %10.3f%% %10.1f %10.1f\n",
                    r.report.quality.c_str(), r.report.shadowSamplesPerLight,
                    r.report.indirectSamplesPerTexel, b.seconds,
                    stageSeconds(r.report, "lightmaps"), static_cast<unsigned long long>(rays),
                    mrays(rays, b.seconds), 100.0 * r.report.lightmapMeanRelativeNoise, 100.0 * rms,
                    mib(b.peakBytes), mib(b.residentBefore));
        if (csv)
            std::fprintf(csv, "%s,%u,%u,%.4f,%.4f,%llu,%.6f,%.6f,%.1f\n", r.report.quality.c_str(),
                         r.report.shadowSamplesPerLight, r.report.indirectSamplesPerTexel,
                         b.seconds, stageSeconds(r.report, "lightmaps"),
                         static_cast<unsigned long long>(rays), rms, referenceNoise,
                         mib(b.peakBytes));
    }
    if (csv) {
        std::fclose(csv);
        std::printf("curve written to %s\n", o.csv.c_str());
    }
    std::printf(
        "(the RMS error includes the reference's own noise: sqrt(err^2 - %.3f%%^2) is the "
        "bake's)\n",
        100.0 * referenceNoise);
    std::printf("peak memory: %s; 'before' is what the process already held\n",
                bakes.front().peakIsPerBake ? "per bake (high-water mark reset before each)"
                                            : "process peak so far (reset refused)");
    return true;
}

void scaling(const BenchOptions& o) {
    std::printf("\n== 3. Scaling: the room at default quality, 1x 2x 4x texels ==\n");
    const world::SourceLevel level = test::agreementRoom();
    const float factors[3] = {1.0f, std::sqrt(2.0f), 2.0f};
    std::printf("%-6s %10s %9s %9s %10s %13s %12s %10s %10s\n", "texels", "texels/m", "sampled",
                "bake s", "lightmap s", "us per texel", "vs linear", "peak MiB", "before MiB");
    double firstPerTexel = 0.0;
    for (int i = 0; i < 3; ++i) {
        const float tpm = o.scalingTexelsPerMetre * factors[i];
        const Bake b = timedBake(level, test::testOptions(tpm, BakeQuality::kDefault));
        const BakeReport& r = b.result.report;
        const double lightmap = stageSeconds(r, "lightmaps");
        const double perTexel = lightmap / double(std::max<uint64_t>(1, r.texelsSampled));
        if (i == 0) firstPerTexel = perTexel;
        std::printf("%-6s %10.2f %9llu %9.2f %10.2f %13.1f %12.3f %10.1f %10.1f\n",
                    i == 0   ? "1x"
                    : i == 1 ? "2x"
                             : "4x",
                    double(tpm), static_cast<unsigned long long>(r.texelsSampled), b.seconds,
                    lightmap, perTexel * 1e6, perTexel / firstPerTexel, mib(b.peakBytes),
                    mib(b.residentBefore));
    }
    std::printf(
        "(vs linear: lightmap seconds per sampled texel over the 1x bake's; 1.0 is "
        "linear. bake s includes compile and grid, which do not scale with texels)\n");
}

/// Bake time against light count: the many-lights floor with 8 (approximately: 3 x 3 = 9),
/// 32 (6 x 6 = 36) and 128 (11 x 11 = 121) lights at default quality, as the baker bakes it
/// (lights by importance, cached bounces) and with every light along whole paths.
void lightScaling(const BenchOptions& o) {
    std::printf("\n== 4. Lights: the many-lights floor at default quality, %.0f texels/m ==\n",
                double(o.lightsTexelsPerMetre));
    std::printf("%-7s %-22s %9s %11s %13s %12s\n", "lights", "estimator", "bake s", "lightmap s",
                "shadow/texel", "vs fewest");
    const uint32_t sides[3] = {3, 6, 11};
    for (int mode = 0; mode < 2; ++mode) {
        double first = 0.0;
        for (uint32_t side : sides) {
            BakeOptions options = test::testOptions(o.lightsTexelsPerMetre, BakeQuality::kDefault);
            options.gridCellSize = 2.0f;
            options.allLights = options.pathsOnly = mode == 1;
            const Bake b = timedBake(test::manyLightsFloor(side), options);
            const BakeReport& r = b.result.report;
            const double lightmap = stageSeconds(r, "lightmaps");
            if (side == sides[0]) first = b.seconds;
            uint64_t shadow = 0;
            for (const StageReport& s : r.stages)
                if (s.name == "lightmaps") shadow = s.rays.shadow;
            std::printf("%-7u %-22s %9.2f %11.2f %13.1f %12.2f\n", side * side,
                        mode == 0 ? "by importance, cached" : "every light, paths", b.seconds,
                        lightmap, double(shadow) / double(std::max<uint64_t>(1, r.texelsSampled)),
                        b.seconds / first);
        }
    }
}

bool parse(int argc, char** argv, BenchOptions& o) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--triangles" && has_value)
            o.triangles = std::strtoull(argv[++i], nullptr, 10);
        else if (a == "--texels" && has_value)
            o.texels = std::strtoull(argv[++i], nullptr, 10);
        else if (a == "--reference-spp" && has_value)
            o.referenceSpp = uint32_t(std::strtoul(argv[++i], nullptr, 10));
        else if (a == "--stride" && has_value)
            o.stride = std::max(1u, uint32_t(std::strtoul(argv[++i], nullptr, 10)));
        else if (a == "--scaling-texels-per-metre" && has_value)
            o.scalingTexelsPerMetre = std::strtof(argv[++i], nullptr);
        else if (a == "--repeats" && has_value)
            o.repeats = std::max(1u, uint32_t(std::strtoul(argv[++i], nullptr, 10)));
        else if (a == "--threads" && has_value)
            o.threads = uint32_t(std::strtoul(argv[++i], nullptr, 10));
        else if (a == "--throughput-only")
            o.throughputOnly = true;
        else if (a == "--lights-only")
            o.lightsOnly = true;
        else if (a == "--materials-only")
            o.materialsOnly = true;
        else if (a == "--csv" && has_value)
            o.csv = argv[++i];
        else
            return false;
    }
    return o.triangles > 0 && o.texels > 0 && o.referenceSpp > 1 && o.scalingTexelsPerMetre > 0.0f;
}

// ---------------------------------------------------------------------------------------------
// 5. Materials

void materials(const BenchOptions& o) {
    std::printf("\n== 5. Materials: a textured room against the same room with factors only ==\n");
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / "onelight_bench_materials";
    std::filesystem::create_directories(folder);
    BakeOptions options = test::testOptions(24.0f, BakeQuality::kDefault);
    options.compile.charts.atlasSize = 1024;
    world::SourceLevel textured = test::texturedRoomWithProbes(folder.string());
    // The same geometry and emitter; each base colour texture's mean (its last mip, linear)
    // moved into the factor, so both levels reflect alike and trace about as many rays.
    world::SourceLevel factors = textured;
    for (world::Material& m : factors.materials) {
        if (m.baseColorTexture != world::kNoIndex) {
            const world::Texture& t = textured.textures[m.baseColorTexture];
            const glm::vec4 mean =
                makeBakeTexture(world::readImageFile(textured.images[t.image].uri), true, false,
                                t.sampler)
                    .texels.back();
            m.baseColor *= glm::vec4(glm::vec3(mean), 1.0f);
            m.albedo *= glm::vec3(mean);
        }
        m.baseColorTexture = m.metallicRoughnessTexture = m.normalTexture = m.occlusionTexture =
            m.emissiveTexture = world::kNoIndex;
    }
    const world::SourceLevel* levels[2] = {&factors, &textured};
    const char* names[2] = {"factors only (texture means)", "textured (base colour, normal, MASK)"};
    double rate[2] = {0.0, 0.0}, seconds[2] = {0.0, 0.0};
    std::printf("%-42s %9s %12s %9s\n", "textured room, default quality", "bake s", "rays",
                "Mrays/s");
    for (int k = 0; k < 2; ++k) {
        double best = 1e30;
        uint64_t rays = 0;
        for (uint32_t r = 0; r < std::max(1u, o.repeats); ++r) {
            const Bake b = timedBake(*levels[k], options);
            best = std::min(best, b.seconds);
            rays = stageRays(b.result.report).total();
        }
        rate[k] = mrays(rays, best);
        seconds[k] = best;
        std::printf("%-42s %9.3f %12llu %9.2f\n", names[k], best,
                    static_cast<unsigned long long>(rays), rate[k]);
    }
    std::printf("textured / factors only: rays/s %.2f, bake time %.2f (fastest of %u each)\n",
                rate[1] / rate[0], seconds[1] / seconds[0], std::max(1u, o.repeats));
}

}  // namespace
}  // namespace onelight::bake

int main(int argc, char** argv) {
    using namespace onelight::bake;
    BenchOptions o;
    if (!parse(argc, argv, o)) {
        std::fprintf(stderr,
                     "usage: onelight-bench-bake [--triangles N] [--texels N] [--reference-spp N] "
                     "[--stride N] [--scaling-texels-per-metre X] [--repeats N] [--threads N] "
                     "[--throughput-only] [--materials-only] [--lights-only] [--csv PATH]\n");
        return 2;
    }
    const uint32_t threads =
        o.threads ? o.threads : std::max(1u, std::thread::hardware_concurrency());
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    std::printf("onelight-bench-bake: %u threads, Embree %s; load average at start: %s\n", threads,
                RTC_VERSION_STRING, loadAverage().c_str());
    const auto start = std::chrono::steady_clock::now();
    try {
        if (o.materialsOnly) {
            materials(o);
        } else if (o.lightsOnly) {
            lightScaling(o);
        } else if (!rayThroughput(o)) {
            return 1;
        } else if (!o.throughputOnly) {
            if (!speedAgainstError(o)) return 1;
            scaling(o);
            lightScaling(o);
            materials(o);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "onelight-bench-bake: %s\n", e.what());
        return 1;
    }
    std::printf("\ntotal %.1f s; load average at end: %s\n", secondsSince(start),
                loadAverage().c_str());
    return 0;
}
