// A source's own potentially visible set, in the level's space (metres, Y up): a Quake 3 map's,
// as q3map2 -vis computed it. The map's BSP tree finds the leaves at a point or in a box; each
// leaf lies in one visibility cluster (or in solid); each cluster's row says which clusters may
// be seen from anywhere in it. Imported with the map (world/import/q3), for the bake to take
// instead of sampling a set with rays (bake/visibility).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "world/collision.hpp"

namespace onelight::world {

struct ImportedVisibility {
    struct Node {
        CollisionPlane plane;            // a point p is in front when dot(normal, p) >= distance
        int32_t children[2] = {-1, -1};  // front, back: >= 0 a later node, < 0 the leaf -(c + 1)
    };
    struct Leaf {
        int32_t cluster = -1;  // -1: inside solid
        glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
    };
    std::vector<Node> nodes;  // the root first
    std::vector<Leaf> leafs;
    uint32_t clusterCount = 0, bytesPerCluster = 0;
    std::vector<uint8_t> rows;  // clusterCount rows of bytesPerCluster bytes

    [[nodiscard]] bool empty() const { return clusterCount == 0 || nodes.empty(); }
};

/// The leaf holding point p (the tree must be well formed: children later than their node).
[[nodiscard]] uint32_t importedLeafAt(const ImportedVisibility& v, glm::vec3 p);

/// Appends to `out` every leaf the box [lo, hi] reaches, in tree order.
void importedLeavesIn(const ImportedVisibility& v, glm::vec3 lo, glm::vec3 hi,
                      std::vector<uint32_t>& out);

/// Whether cluster `to` may be seen from cluster `from` (both >= 0).
[[nodiscard]] inline bool importedClusterSees(const ImportedVisibility& v, uint32_t from,
                                              uint32_t to) {
    return (v.rows[size_t(from) * v.bytesPerCluster + to / 8] >> (to % 8)) & 1u;
}

}  // namespace onelight::world
