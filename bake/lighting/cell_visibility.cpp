#include "bake/lighting/cell_visibility.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "bake/lighting/sampling.hpp"

namespace onelight::bake {

CellSurfacePoints surfacePointsOfCells(const BakeScene& scene, const LightCells& cells) {
    CellSurfacePoints out;
    const uint32_t count = cellCount(cells);
    out.first.assign(count + 1, 0);
    if (count == 0) return out;
    // About kPointsPerCell points per cell face's area, at least one per triangle.
    const double density = double(CellSurfacePoints::kPointsPerCell) /
                           (double(cells.cellSize) * double(cells.cellSize));
    struct Candidate {
        uint32_t cell, hash;
        glm::vec3 position, normal;
    };
    std::vector<Candidate> candidates;
    for (uint32_t t = 0; t < scene.triangleCount(); ++t) {
        const std::array<glm::vec3, 3> v = scene.triangleVertices(t);
        const double area =
            0.5 * glm::length(glm::cross(glm::dvec3(v[1] - v[0]), glm::dvec3(v[2] - v[0])));
        if (!(area > 0.0) || !std::isfinite(area)) continue;
        const glm::vec3 n = scene.triangleNormal(t);
        const uint32_t samples =
            static_cast<uint32_t>(std::clamp(std::ceil(area * density), 1.0, 1e6));
        for (uint32_t i = 0; i < samples; ++i) {
            Rng rng{seedFrom(t, i, 0, 7)};
            const float r = std::sqrt(rng.next()), b = rng.next();
            const glm::vec3 p = v[0] + r * (1.0f - b) * (v[1] - v[0]) + r * b * (v[2] - v[0]);
            const uint32_t cell = cellOf(cells, p);
            if (cell >= count) continue;
            candidates.push_back({cell, rng.seed, p + n * (4.0f * scene.rayOffset()), n});
        }
    }
    // Per cell, the kPointsPerCell candidates of smallest hash: a uniform choice among them.
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
        return std::tie(a.cell, a.hash) < std::tie(b.cell, b.hash);
    });
    for (size_t i = 0; i < candidates.size();) {
        const uint32_t cell = candidates[i].cell;
        size_t end = i;
        while (end < candidates.size() && candidates[end].cell == cell) ++end;
        for (size_t k = i; k < std::min(end, i + CellSurfacePoints::kPointsPerCell); ++k) {
            out.position.push_back(candidates[k].position);
            out.normal.push_back(candidates[k].normal);
        }
        out.first[cell + 1] =
            static_cast<uint32_t>(std::min<size_t>(end - i, CellSurfacePoints::kPointsPerCell));
        i = end;
    }
    for (uint32_t c = 0; c < count; ++c) out.first[c + 1] += out.first[c];
    return out;
}

}  // namespace onelight::bake
