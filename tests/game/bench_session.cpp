// Benchmark (not a ctest test): `onelight-bench-session PACKAGE [TICKS]` plays a level's
// simulation without drawing: the player runs forward from the level's spawn, turning 90
// degrees every 2 s, for TICKS ticks (default 3600: a minute at 60 Hz). Prints the entities
// (dynamic objects, items), the ECS update's time per tick (median, 95th percentile, mean),
// the primary re-picks per second (switches of a dynamic object's primary) and the items taken.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "assets/level_assets.hpp"
#include "session.hpp"

using namespace onelight;

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: onelight-bench-session PACKAGE [TICKS]\n");
        return 2;
    }
    try {
        const long ticks = argc == 3 ? std::strtol(argv[2], nullptr, 10) : 3600;
        if (ticks < 1 || ticks > 10000000) {
            std::fprintf(stderr, "onelight-bench-session: TICKS %s; expected 1..10000000\n",
                         argv[2]);
            return 2;
        }
        const assets::LoadedLevel level = assets::loadLevel(argv[1]);
        game::Session session;
        game::startSession(session, level);
        const auto* dynamicPool = session.registry.findPool<game::DynamicLighting>();
        const auto* itemPool = session.registry.findPool<game::Item>();
        const size_t dynamic = dynamicPool ? dynamicPool->size() : 0;
        const size_t items = itemPool ? itemPool->size() : 0;
        std::vector<uint32_t> before;
        uint64_t switches = 0;
        std::vector<double> ms;
        session.input.keysDown.insert("W");
        for (long t = 0; t < ticks; ++t) {
            if (t % 120 == 119) session.input.lookYawDegrees = 90.0f;
            before.clear();
            for (auto [e, lit] : session.registry.view<game::DynamicLighting>().each())
                before.push_back(lit.pick.primary);
            const auto start = std::chrono::steady_clock::now();
            game::stepSession(session);
            ms.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
            size_t i = 0;
            for (auto [e, lit] : session.registry.view<game::DynamicLighting>().each())
                switches += before[i++] != lit.pick.primary && before[i - 1] != world::kNoIndex;
        }
        uint32_t taken = 0;
        for (auto [e, item] : session.registry.view<game::Item>().each()) taken += item.timesTaken;
        const double seconds = double(ticks) * session.tickSeconds;
        double mean = 0.0;
        for (double m : ms) mean += m;
        mean /= double(ms.size());
        std::sort(ms.begin(), ms.end());
        std::printf(
            "onelight-bench-session %s: %ld ticks (%.1f s at %.0f Hz), %zu dynamic objects (%zu "
            "items), %zu primary candidates\n",
            argv[1], ticks, seconds, 1.0 / session.tickSeconds, dynamic, items,
            session.primaryCandidates.size());
        std::printf(
            "  ECS update per tick: median %.3f ms, 95th percentile %.3f ms, mean %.3f ms\n",
            ms[ms.size() / 2], ms[ms.size() * 95 / 100], mean);
        std::printf("  primary re-picks: %llu (%.2f per second); items taken: %u\n",
                    static_cast<unsigned long long>(switches), double(switches) / seconds, taken);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "onelight-bench-session: %s\n", e.what());
        return 1;
    }
}
