// The Pareto front of a table of settings, each with three costs where less is better.
#pragma once

#include <vector>

namespace onelight::lab {

struct Costs {
    double frameMs = 0.0;      // the runtime's GPU time per frame
    double bakeSeconds = 0.0;  // the bake's time
    double error = 0.0;        // mean relative error against the reference
};

// True when `a` is at least as good as `b` in every cost and strictly better in one.
[[nodiscard]] bool dominates(const Costs& a, const Costs& b);

// For each row, whether it is on the front: no other row dominates it.
[[nodiscard]] std::vector<bool> paretoFront(const std::vector<Costs>& rows);

}  // namespace onelight::lab
