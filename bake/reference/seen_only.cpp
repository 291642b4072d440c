#include "bake/reference/seen_only.hpp"

namespace onelight::bake {

void appendShadowlessSurfaces(const world::StaticGeometry& geometry,
                              const std::vector<world::Material>& materials,
                              world::StaticGeometry& seenOnly) {
    for (const world::StaticTriangle& t : geometry.triangles) {
        if (t.material >= materials.size() || materials[t.material].castsShadows) continue;
        world::StaticTriangle copy = t;
        for (int c = 0; c < 3; ++c) {
            copy.v[size_t(c)] = uint32_t(seenOnly.vertices.size());
            seenOnly.vertices.push_back(geometry.vertices.at(t.v[size_t(c)]));
        }
        seenOnly.triangles.push_back(copy);
    }
}

SceneMaterials seenOnlyMaterials(SceneMaterials materials) {
    for (world::Material& m : materials.materials) m.castsShadows = true;
    return materials;
}

}  // namespace onelight::bake
