#include "pareto.hpp"

#include <cstddef>

namespace onelight::lab {

bool dominates(const Costs& a, const Costs& b) {
    const bool noWorse =
        a.frameMs <= b.frameMs && a.bakeSeconds <= b.bakeSeconds && a.error <= b.error;
    const bool better = a.frameMs < b.frameMs || a.bakeSeconds < b.bakeSeconds || a.error < b.error;
    return noWorse && better;
}

std::vector<bool> paretoFront(const std::vector<Costs>& rows) {
    std::vector<bool> front(rows.size(), true);
    for (size_t i = 0; i < rows.size(); ++i)
        for (size_t j = 0; j < rows.size() && front[i]; ++j)
            if (j != i && dominates(rows[j], rows[i])) front[i] = false;
    return front;
}

}  // namespace onelight::lab
