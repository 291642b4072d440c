#include "world/visibility.hpp"

#include <cmath>

namespace onelight::world {

uint32_t visibilityRowAt(const Visibility& visibility, glm::vec3 p) {
    if (visibility.empty()) return kNoIndex;
    const glm::vec3 f = glm::floor((p - visibility.origin) / visibility.cellSize);
    if (!(f.x >= 0.0f && f.y >= 0.0f && f.z >= 0.0f && f.x < float(visibility.dims.x) &&
          f.y < float(visibility.dims.y) && f.z < float(visibility.dims.z)))
        return kNoIndex;
    const glm::uvec3 c(f);
    return visibility
        .cellRow[c.x + size_t(visibility.dims.x) * (c.y + size_t(visibility.dims.y) * c.z)];
}

}  // namespace onelight::world
