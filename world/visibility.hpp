// The potentially visible set (package section 37, baked by bake/visibility/): a grid of view
// cells over the level, each naming a row of bits over clusters of static surfaces, bit c set
// when cluster c may be seen from somewhere in the cell. Plain data and the two queries the runtime
// makes per frame. An empty Visibility, a point outside the grid or a cell whose row is kNoIndex
// culls nothing.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "world/no_index.hpp"

namespace onelight::world {

inline constexpr uint32_t kMaxVisibilityCellsPerAxis = 1024;
inline constexpr uint64_t kMaxVisibilityCells = 1u << 24;

struct Visibility {
    glm::vec3 origin{0.0f};  // metres, the grid's minimum corner
    float cellSize = 0.0f;   // metres, cubes
    glm::uvec3 dims{0u};     // cells per axis; 0: no visibility
    uint32_t clusterCount = 0;
    std::vector<uint32_t> surfaceCluster;  // per static surface, < clusterCount
    std::vector<uint32_t> cellRow;         // per cell (x fastest): a row, or kNoIndex (all visible)
    std::vector<uint32_t> rows;            // rowCount() rows of wordsPerRow() words

    [[nodiscard]] bool empty() const { return cellRow.empty(); }
    [[nodiscard]] uint32_t wordsPerRow() const { return (clusterCount + 31) / 32; }
    [[nodiscard]] uint32_t rowCount() const {
        return wordsPerRow() == 0 ? 0u : uint32_t(rows.size() / wordsPerRow());
    }
    bool operator==(const Visibility&) const = default;
};

/// The row of the cell holding p, or kNoIndex (cull nothing) outside the grid or without one.
[[nodiscard]] uint32_t visibilityRowAt(const Visibility& visibility, glm::vec3 p);

/// Whether cluster `cluster` is in row `row`; every cluster is in row kNoIndex.
[[nodiscard]] inline bool clusterInRow(const Visibility& visibility, uint32_t row,
                                       uint32_t cluster) {
    if (row == kNoIndex) return true;
    const uint32_t word = visibility.rows[size_t(row) * visibility.wordsPerRow() + cluster / 32];
    return (word >> (cluster % 32)) & 1u;
}

}  // namespace onelight::world
