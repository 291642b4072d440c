// The imported potentially visible set's tree queries (imported_visibility.hpp).
#include "world/imported_visibility.hpp"

#include <cmath>

namespace onelight::world {

uint32_t importedLeafAt(const ImportedVisibility& v, glm::vec3 p) {
    int32_t at = 0;
    while (at >= 0) {
        const ImportedVisibility::Node& n = v.nodes[size_t(at)];
        at = n.children[glm::dot(n.plane.normal, p) >= n.plane.distance ? 0 : 1];
    }
    return uint32_t(-1 - at);
}

void importedLeavesIn(const ImportedVisibility& v, glm::vec3 lo, glm::vec3 hi,
                      std::vector<uint32_t>& out) {
    const glm::vec3 centre = 0.5f * (lo + hi), half = 0.5f * (hi - lo);
    std::vector<int32_t> stack = {0};
    while (!stack.empty()) {
        const int32_t at = stack.back();
        stack.pop_back();
        if (at < 0) {
            out.push_back(uint32_t(-1 - at));
            continue;
        }
        const ImportedVisibility::Node& n = v.nodes[size_t(at)];
        const float d = glm::dot(n.plane.normal, centre) - n.plane.distance;
        const float r = glm::dot(glm::abs(n.plane.normal), half);
        // Back first onto the stack, so that the front side comes out first (tree order).
        if (d - r < 0.0f) stack.push_back(n.children[1]);
        if (d + r >= 0.0f) stack.push_back(n.children[0]);
    }
}

}  // namespace onelight::world
