// onelight-bench-ecs: ns per entity to update 100k entities with two components each, through
// a view (each, forEach), the owning group (forEach, each) and plain arrays; the summary at the
// end gives ns per entity (CPU time, median of the repetitions) and the group / plain arrays
// ratios measured in this one run.
//   build/bin/onelight-bench-ecs [--benchmark_repetitions=5]
// (The console output is this program's own; --benchmark_out=FILE still writes other formats.)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "ecs_fixtures.hpp"

using namespace onelight::ecs;
using namespace onelight::ecs::fixtures;

namespace {
constexpr int kEntities = 100000;

void BM_UpdateViewEach(benchmark::State& state) {
    Registry r = makeWorld(int(state.range(0)));
    for (auto _ : state) {
        for (auto [e, p, v] : r.view<Position, const Velocity>().each()) integrate(p, v);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_UpdateViewForEach(benchmark::State& state) {
    Registry r = makeWorld(int(state.range(0)));
    auto view = r.view<Position, const Velocity>();
    for (auto _ : state) {
        view.forEach([](Entity, Position& p, const Velocity& v) { integrate(p, v); });
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_UpdateGroupForEach(benchmark::State& state) {
    Registry r = makeWorld(int(state.range(0)));
    auto group = r.group<Position, Velocity>();
    for (auto _ : state) {
        group.forEach([](Entity, Position& p, const Velocity& v) { integrate(p, v); });
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_UpdateGroupEach(benchmark::State& state) {
    Registry r = makeWorld(int(state.range(0)));
    auto group = r.group<Position, Velocity>();
    for (auto _ : state) {
        for (auto [e, p, v] : group.each()) integrate(p, v);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

// The floor: the same update over two plain arrays.
void BM_UpdatePlainArrays(benchmark::State& state) {
    std::vector<Position> p(size_t(state.range(0)), Position{0, 0, 0});
    std::vector<Velocity> v(size_t(state.range(0)), Velocity{1, 2, 3});
    for (auto _ : state) {
        for (size_t i = 0; i < p.size(); ++i) integrate(p[i], v[i]);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

// What the group costs where it is maintained: building the world with and without it.
void BM_BuildWorld(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(makeWorld(int(state.range(0))).alive());
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_BuildWorldGrouped(benchmark::State& state) {
    for (auto _ : state) {
        Registry r;
        r.group<Position, Velocity>();
        for (int i = 0; i < int(state.range(0)); ++i) {
            Entity e = r.create();
            r.emplace<Position>(e, float(i), 0.f, 0.f);
            r.emplace<Velocity>(e, 1.f, 2.f, 3.f);
        }
        benchmark::DoNotOptimize(r.alive());
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

// The console reporter, also keeping every run's CPU ns per entity for the summary.
class SummaryReporter : public benchmark::ConsoleReporter {
public:
    SummaryReporter() : ConsoleReporter(OO_None) {}

    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            if (run.error_occurred) continue;
            double ns = run.GetAdjustedCPUTime() * 1e9 /
                        benchmark::GetTimeUnitMultiplier(run.time_unit) / kEntities;
            const std::string& name = run.run_name.function_name;
            if (run.run_type == Run::RT_Iteration) samples_[name].push_back(ns);
            if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median")
                medians_[name] = ns;
        }
    }

    // The median of the benchmark's runs (or its reported median), in ns per entity; 0 if it
    // did not run.
    double nsPerEntity(const std::string& name) const {
        if (auto it = samples_.find(name); it != samples_.end()) {
            std::vector<double> v = it->second;
            std::sort(v.begin(), v.end());
            size_t n = v.size();
            return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
        }
        auto it = medians_.find(name);
        return it != medians_.end() ? it->second : 0.0;
    }

private:
    std::map<std::string, std::vector<double>> samples_;
    std::map<std::string, double> medians_;
};

void printSummary(const SummaryReporter& reporter) {
    struct Line {
        const char* label;
        const char* benchmark;
    };
    const Line lines[] = {{"view.each", "BM_UpdateViewEach"},
                          {"view.forEach", "BM_UpdateViewForEach"},
                          {"group.forEach", "BM_UpdateGroupForEach"},
                          {"group.each", "BM_UpdateGroupEach"},
                          {"plain arrays", "BM_UpdatePlainArrays"}};
    double plain = reporter.nsPerEntity("BM_UpdatePlainArrays");
    std::printf("\nns per entity, %d entities (CPU time, median of the runs):\n", kEntities);
    for (const Line& l : lines) {
        double ns = reporter.nsPerEntity(l.benchmark);
        if (ns <= 0) continue;
        std::printf("  %-14s %6.3f ns", l.label, ns);
        if (plain > 0) std::printf("   %5.2fx plain arrays", ns / plain);
        std::printf("\n");
    }
    double group = reporter.nsPerEntity("BM_UpdateGroupForEach");
    if (group > 0 && plain > 0)
        std::printf("group.forEach / plain arrays = %.2fx (goal: at most 1.5x)\n", group / plain);
}
}  // namespace

BENCHMARK(BM_UpdateViewEach)->Arg(kEntities);
BENCHMARK(BM_UpdateViewForEach)->Arg(kEntities);
BENCHMARK(BM_UpdateGroupForEach)->Arg(kEntities);
BENCHMARK(BM_UpdateGroupEach)->Arg(kEntities);
BENCHMARK(BM_UpdatePlainArrays)->Arg(kEntities);
BENCHMARK(BM_BuildWorld)->Arg(kEntities)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BuildWorldGrouped)->Arg(kEntities)->Unit(benchmark::kMicrosecond);

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    SummaryReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    printSummary(reporter);
    benchmark::Shutdown();
    return 0;
}
