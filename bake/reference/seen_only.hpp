// What the reference's camera rays alone see (traceRadiance's `seenOnly`): surfaces the frame
// draws but that take no part in the level's light. A Quake 3 translucent surface (water, slime,
// glass; world::Material::castsShadows false) is drawn by the frame while light passes it, as
// q3map2 lights it; the bake's scene never hits it (BakeScene's coverage), so without this the
// reference showed what lies behind it.
#pragma once

#include <vector>

#include "bake/materials/scene_materials.hpp"
#include "world/compiled_level.hpp"
#include "world/static_geometry.hpp"

namespace onelight::bake {

/// Appends the triangles of `geometry` whose material casts no shadow to `seenOnly`, each with
/// its own three vertices.
void appendShadowlessSurfaces(const world::StaticGeometry& geometry,
                              const std::vector<world::Material>& materials,
                              world::StaticGeometry& seenOnly);

/// `materials` with every material casting shadows: a seen-only scene's, every triangle of which
/// camera rays must hit.
[[nodiscard]] SceneMaterials seenOnlyMaterials(SceneMaterials materials);

}  // namespace onelight::bake
