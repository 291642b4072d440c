#include "world/light_grid_sample.hpp"

#include <algorithm>
#include <cmath>

namespace onelight::world {

LightGridSample sampleLightGrid(const LightGrid& grid, glm::vec3 p) {
    LightGridSample out;
    // A grid whose cells do not match its dims (only a package the reader refused could hold
    // one) reads as no grid rather than out of bounds.
    if (grid.cells.empty() || grid.dims.x == 0 || grid.dims.y == 0 || grid.dims.z == 0 ||
        uint64_t(grid.dims.x) * grid.dims.y * grid.dims.z != grid.cells.size())
        return out;
    // Continuous cell coordinate: cell (i, j, k) is centred at origin + (i + 0.5) size.
    const glm::vec3 f = (p - grid.origin) / grid.cellSize - 0.5f;
    glm::uvec3 lo{0u}, hi{0u};
    glm::vec3 t{0.0f};
    for (int a = 0; a < 3; ++a) {
        const float top = float(grid.dims[a] - 1u);
        const float c = std::isfinite(f[a]) ? std::clamp(f[a], 0.0f, top) : 0.0f;
        lo[a] = std::min(uint32_t(std::floor(c)), grid.dims[a] - 1u);
        hi[a] = std::min(lo[a] + 1u, grid.dims[a] - 1u);
        t[a] = c - float(lo[a]);
    }
    float plain[8], total = 0.0f;
    for (uint32_t corner = 0; corner < 8; ++corner) {
        const glm::uvec3 c((corner & 1u) ? hi.x : lo.x, (corner & 2u) ? hi.y : lo.y,
                           (corner & 4u) ? hi.z : lo.z);
        const float w = ((corner & 1u) ? t.x : 1.0f - t.x) * ((corner & 2u) ? t.y : 1.0f - t.y) *
                        ((corner & 4u) ? t.z : 1.0f - t.z);
        const uint64_t cell = c.x + uint64_t(grid.dims.x) * (c.y + uint64_t(grid.dims.y) * c.z);
        out.cells[corner] = uint32_t(cell);  // the reader keeps grids below 2^24 cells
        plain[corner] = w;
        const bool solid = (grid.cells[cell].flags & kLightGridCellInsideSolid) != 0;
        out.weights[corner] = solid ? 0.0f : w;
        total += out.weights[corner];
    }
    if (!(total > 1e-6f)) {  // every corner with weight is inside solid: keep them all
        out.allSolid = true;
        total = 0.0f;
        for (uint32_t corner = 0; corner < 8; ++corner) {
            out.weights[corner] = plain[corner];
            total += plain[corner];
        }
    }
    for (uint32_t corner = 0; corner < 8; ++corner) {
        out.weights[corner] /= total;
        const LightGridCell& cell = grid.cells[out.cells[corner]];
        for (size_t face = 0; face < 6; ++face)
            out.ambientCube[face] += out.weights[corner] * cell.ambientCube[face];
    }
    return out;
}

float dominantVisibility(const LightGrid& grid, const LightGridSample& sample, uint32_t light) {
    float sum = 0.0f;
    for (uint32_t corner = 0; corner < 8; ++corner) {
        const LightGridCell& cell = grid.cells[sample.cells[corner]];
        if (sample.weights[corner] > 0.0f && cell.dominantPrimary == light)
            sum += sample.weights[corner] * cell.primaryVisibility;
    }
    return sum;
}

float bakedVisibility(const LightGrid& grid, const LightGridSample& sample, uint32_t light) {
    float weight = 0.0f, sum = 0.0f;
    for (uint32_t corner = 0; corner < 8; ++corner) {
        const LightGridCell& cell = grid.cells[sample.cells[corner]];
        if (sample.weights[corner] > 0.0f && cell.dominantPrimary == light) {
            weight += sample.weights[corner];
            sum += sample.weights[corner] * cell.primaryVisibility;
        }
    }
    return weight > 0.0f ? sum / weight : 0.0f;
}

}  // namespace onelight::world
