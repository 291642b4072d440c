// onelight-bench-ecs: ns per entity to update 100k entities with two components each.
//   build/bin/onelight-bench-ecs
#include <benchmark/benchmark.h>

#include "ecs/registry.hpp"

using namespace onelight::ecs;

namespace {
struct Position {
    float x, y, z;
};
struct Velocity {
    float x, y, z;
};

Registry makeWorld(int count) {
    Registry r;
    for (int i = 0; i < count; ++i) {
        Entity e = r.create();
        r.emplace<Position>(e, float(i), 0.f, 0.f);
        r.emplace<Velocity>(e, 1.f, 2.f, 3.f);
    }
    return r;
}

void BM_UpdateForEach(benchmark::State& state) {
    Registry r = makeWorld(int(state.range(0)));
    auto view = r.view<Position, Velocity>();
    for (auto _ : state) {
        view.forEach([](Entity, Position& p, const Velocity& v) {
            p.x += v.x / 60.f, p.y += v.y / 60.f, p.z += v.z / 60.f;
        });
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_UpdateEach(benchmark::State& state) {
    Registry r = makeWorld(int(state.range(0)));
    for (auto _ : state) {
        for (auto [e, p, v] : r.view<Position, Velocity>().each())
            p.x += v.x / 60.f, p.y += v.y / 60.f, p.z += v.z / 60.f;
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

// The floor: the same update over two plain arrays.
void BM_UpdatePlainArrays(benchmark::State& state) {
    std::vector<Position> p(size_t(state.range(0)), Position{0, 0, 0});
    std::vector<Velocity> v(size_t(state.range(0)), Velocity{1, 2, 3});
    for (auto _ : state) {
        for (size_t i = 0; i < p.size(); ++i)
            p[i].x += v[i].x / 60.f, p[i].y += v[i].y / 60.f, p[i].z += v[i].z / 60.f;
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
}  // namespace

BENCHMARK(BM_UpdateForEach)->Arg(100000);
BENCHMARK(BM_UpdateEach)->Arg(100000);
BENCHMARK(BM_UpdatePlainArrays)->Arg(100000);
BENCHMARK_MAIN();
