#include "lighting_view.hpp"

#include "world/error.hpp"
#include "world/no_index.hpp"

namespace onelight::game {

void applyLightingView(assets::LoadedLevel& level, const std::string& view) {
    if (view == "onelight") return;
    if (view != "q3map2") throw world::Error("--view '" + view + "': expected onelight or q3map2");
    if (!level.hasBakedLighting || level.baked.importedTexels.empty())
        throw world::Error(level.path +
                           ": no q3map2 lightmaps (only a Quake 3 map baked by onelight-bake "
                           "carries them, in package section 36)");
    level.baked.texels = level.baked.importedTexels;
    for (world::Surface& surface : level.level.surfaces) surface.primaryLight = world::kNoIndex;
    for (world::Light& light : level.level.lights) light.role = world::LightRole::kBaked;
}

}  // namespace onelight::game
