// What a static surface's baked shadow mask says of its primary over the whole surface: every
// texel of its lightmap rectangle lit, every one shadowed, or a mix. The renderer draws a wholly
// lit surface without its primary's shadow lookups and a wholly shadowed one without its primary
// (unless a dynamic caster's shadow may reach it): the lookups the mask says cannot matter. And
// whether any of its texels draws the baked direct light's shadow edge.
#pragma once

#include <cstdint>
#include <vector>

#include "world/baked_lighting.hpp"
#include "world/compiled_level.hpp"

namespace onelight::world {

enum class SurfaceShadow : uint8_t {
    kMixed = 0,     // partly shadowed, or not known (no primary, no lightmap, no bake)
    kLit = 1,       // every mask texel of its rectangle fully lit
    kShadowed = 2,  // every mask texel of its rectangle fully shadowed
};

/// Per surface of `level`, from `baked`'s shadow mask (one byte per lightmap texel, 255 lit). A
/// surface whose rectangle or atlas is out of range, or that has no primary, is kMixed.
[[nodiscard]] std::vector<SurfaceShadow> surfaceShadows(const CompiledLevel& level,
                                                        const BakedLighting& baked);

/// Per surface of `level`, whether any texel of its lightmap rectangle draws its baked direct
/// light's shadow edge from the distance field (LightmapTexel::directEdgeSharpness > 0): the
/// renderer draws the others without the edge's fetches. 0 for a surface without a valid one.
[[nodiscard]] std::vector<uint8_t> surfaceDirectEdges(const CompiledLevel& level,
                                                      const BakedLighting& baked);

}  // namespace onelight::world
