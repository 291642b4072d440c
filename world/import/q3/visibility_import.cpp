// A Quake 3 map's potentially visible set in the level's space (visibility_import.hpp).
#include "world/import/q3/visibility_import.hpp"

#include <algorithm>

#include "world/error.hpp"
#include "world/import/q3/map_axes.hpp"

namespace onelight::world::q3 {

ImportedVisibility importVisibility(const BspFile& bsp, const std::string& where) {
    ImportedVisibility v;
    if (bsp.clusterCount <= 0 || bsp.nodes.empty()) return v;
    v.clusterCount = uint32_t(bsp.clusterCount);
    v.bytesPerCluster = uint32_t(bsp.bytesPerCluster);
    v.rows = bsp.visibility;
    for (size_t i = 0; i < bsp.nodes.size(); ++i) {
        const BspNode& node = bsp.nodes[i];
        const BspBrushPlane& plane = bsp.planes[size_t(node.plane)];
        const glm::vec3 n = levelDirection(plane.normal);
        const float length = glm::length(n);
        if (!(length > 0.5f && length < 2.0f))
            throw Error(where + ": node " + std::to_string(i) + ": plane " +
                        std::to_string(node.plane) + " has a normal of length " +
                        std::to_string(length) + "; expected a unit normal");
        ImportedVisibility::Node out;
        out.plane = {n / length, float(double(plane.dist) * kQuake3MetresPerUnit / double(length))};
        out.children[0] = node.children[0];
        out.children[1] = node.children[1];
        v.nodes.push_back(out);
    }
    for (const BspLeaf& leaf : bsp.leafs) {
        ImportedVisibility::Leaf out;
        out.cluster = leaf.cluster;
        const float lo[3] = {float(leaf.mins[0]), float(leaf.mins[1]), float(leaf.mins[2])};
        const float hi[3] = {float(leaf.maxs[0]), float(leaf.maxs[1]), float(leaf.maxs[2])};
        const glm::vec3 a = levelPoint(lo), b = levelPoint(hi);
        out.boundsMin = glm::min(a, b);
        out.boundsMax = glm::max(a, b);
        v.leafs.push_back(out);
    }
    return v;
}

}  // namespace onelight::world::q3
