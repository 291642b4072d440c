#include "world/images/image_budget.hpp"

#include <cstdio>

#include "world/error.hpp"

namespace onelight::world {

void chargeImage(ImageMemoryBudget& budget, uint32_t width, uint32_t height,
                 const std::string& where) {
    const double bytes = double(width) * double(height) * budget.bytesPerTexel;
    const double total = double(budget.usedBytes) + bytes;
    if (total > double(budget.limitBytes)) {
        char figures[200];
        std::snprintf(figures, sizeof figures,
                      ": a %ux%u image would bring the level's decoded images to %.4g MB; "
                      "expected at most %.4g MB",
                      width, height, total * 1e-6, double(budget.limitBytes) * 1e-6);
        throw Error(where + figures);
    }
    budget.usedBytes += uint64_t(bytes);
}

}  // namespace onelight::world
