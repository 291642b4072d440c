// Each static surface's shadow mask over its lightmap rectangle (surface_shadow.hpp).
#include "world/surface_shadow.hpp"

namespace onelight::world {

std::vector<SurfaceShadow> surfaceShadows(const CompiledLevel& level, const BakedLighting& baked) {
    std::vector<SurfaceShadow> out(level.surfaces.size(), SurfaceShadow::kMixed);
    std::vector<uint64_t> atlasOffset(level.atlases.size(), 0);
    uint64_t total = 0;
    for (size_t a = 0; a < level.atlases.size(); ++a) {
        atlasOffset[a] = total;
        total += uint64_t(level.atlases[a].width) * level.atlases[a].height;
    }
    if (baked.shadowMask.size() != total) return out;
    for (size_t i = 0; i < level.surfaces.size(); ++i) {
        const Surface& s = level.surfaces[i];
        if (s.primaryLight == kNoIndex || s.atlas >= level.atlases.size()) continue;
        const Atlas& atlas = level.atlases[s.atlas];
        if (s.lightmapWidth == 0 || s.lightmapHeight == 0 ||
            uint64_t(s.lightmapX) + s.lightmapWidth > atlas.width ||
            uint64_t(s.lightmapY) + s.lightmapHeight > atlas.height)
            continue;
        bool anyLit = false, anyShadowed = false, anyBetween = false;
        for (uint32_t y = s.lightmapY; y < s.lightmapY + s.lightmapHeight && !anyBetween; ++y) {
            const uint8_t* row =
                &baked.shadowMask[atlasOffset[s.atlas] + uint64_t(y) * atlas.width];
            for (uint32_t x = s.lightmapX; x < s.lightmapX + s.lightmapWidth; ++x) {
                anyLit |= row[x] == 255;
                anyShadowed |= row[x] == 0;
                anyBetween |= row[x] != 0 && row[x] != 255;
            }
        }
        if (anyBetween || (anyLit && anyShadowed)) continue;
        out[i] = anyLit ? SurfaceShadow::kLit : SurfaceShadow::kShadowed;
    }
    return out;
}

std::vector<uint8_t> surfaceDirectEdges(const CompiledLevel& level, const BakedLighting& baked) {
    std::vector<uint8_t> out(level.surfaces.size(), 0);
    std::vector<uint64_t> atlasOffset(level.atlases.size(), 0);
    uint64_t total = 0;
    for (size_t a = 0; a < level.atlases.size(); ++a) {
        atlasOffset[a] = total;
        total += uint64_t(level.atlases[a].width) * level.atlases[a].height;
    }
    if (baked.texels.size() != total) return out;
    for (size_t i = 0; i < level.surfaces.size(); ++i) {
        const Surface& s = level.surfaces[i];
        if (s.atlas >= level.atlases.size()) continue;
        const Atlas& atlas = level.atlases[s.atlas];
        if (uint64_t(s.lightmapX) + s.lightmapWidth > atlas.width ||
            uint64_t(s.lightmapY) + s.lightmapHeight > atlas.height)
            continue;
        for (uint32_t y = s.lightmapY; y < s.lightmapY + s.lightmapHeight && !out[i]; ++y) {
            const LightmapTexel* row =
                &baked.texels[atlasOffset[s.atlas] + uint64_t(y) * atlas.width];
            for (uint32_t x = s.lightmapX; x < s.lightmapX + s.lightmapWidth && !out[i]; ++x)
                out[i] = row[x].directEdgeSharpness > 0.0f ? 1 : 0;
        }
    }
    return out;
}

}  // namespace onelight::world
