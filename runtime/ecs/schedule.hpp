// Systems run in a fixed order on a fixed tick. A system is a free function of the registry and
// the tick; the schedule only orders and calls them.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "registry.hpp"

namespace onelight::ecs {

struct Tick {
    uint64_t index = 0;                                      // ticks since the start, 0-based
    double seconds = 1.0 / 60.0;                             // fixed duration of one tick
    double time() const { return double(index) * seconds; }  // at the start of this tick
};

struct Schedule {
    struct System {
        std::string name;
        std::function<void(Registry&, const Tick&)> run;
    };
    std::vector<System> systems;  // in run order

    void add(std::string name, std::function<void(Registry&, const Tick&)> run) {
        systems.push_back({std::move(name), std::move(run)});
    }
    void runTick(Registry& registry, const Tick& tick) const {
        for (const System& s : systems) s.run(registry, tick);
    }
};

// Turns wall-clock time into whole fixed ticks: the simulation never depends on frame timing.
struct FixedClock {
    double tickSeconds = 1.0 / 60.0;
    double accumulated = 0.0;
    uint64_t nextTick = 0;

    // Adds elapsed wall time; returns how many ticks are now due (at most maxTicks, dropping
    // the rest of a long stall rather than spiralling).
    int advance(double elapsedSeconds, int maxTicks = 8) {
        accumulated += elapsedSeconds;
        int due = 0;
        while (accumulated >= tickSeconds && due < maxTicks) accumulated -= tickSeconds, ++due;
        if (due == maxTicks) accumulated = 0.0;
        return due;
    }
    Tick take() { return Tick{nextTick++, tickSeconds}; }
};

}  // namespace onelight::ecs
