// `onelight LEVEL --view onelight|q3map2`: whose baked light the level is shown with. The
// engine's (the package as it is), or the light its source format baked itself: a Quake 3 map's
// q3map2 lightmaps, which the bake keeps at the engine's own lightmap texels (package section
// 36). That light is all of it, primaries included, so the q3map2 view draws no primary light
// and no shadow map: the same spawn shows the two bakes side by side (static surfaces; a
// Quake 3 map has no dynamic objects).
#pragma once

#include <string>

#include "assets/level_assets.hpp"

namespace onelight::game {

/// Applies `view` ("onelight" or "q3map2") to `level`. Throws world::Error naming the package
/// when it has no q3map2 lightmaps.
void applyLightingView(assets::LoadedLevel& level, const std::string& view);

}  // namespace onelight::game
