// Each static surface's shadow mask over its lightmap rectangle (surface_shadow.hpp).
#include "world/surface_shadow.hpp"

namespace onelight::world {
namespace {

uint64_t totalTexels(const CompiledLevel& level) {
    return atlasTexelOffset(level, uint32_t(level.atlases.size()));
}

/// The surface's lightmap rectangle is a non-empty one inside its atlas.
bool rectangleInAtlas(const CompiledLevel& level, const Surface& s) {
    if (s.atlas >= level.atlases.size() || s.lightmapWidth == 0 || s.lightmapHeight == 0)
        return false;
    const Atlas& atlas = level.atlases[s.atlas];
    return uint64_t(s.lightmapX) + s.lightmapWidth <= atlas.width &&
           uint64_t(s.lightmapY) + s.lightmapHeight <= atlas.height;
}

}  // namespace

std::vector<SurfaceShadow> surfaceShadows(const CompiledLevel& level, const BakedLighting& baked) {
    std::vector<SurfaceShadow> out(level.surfaces.size(), SurfaceShadow::kMixed);
    if (baked.shadowMask.size() != totalTexels(level)) return out;
    for (size_t i = 0; i < level.surfaces.size(); ++i) {
        const Surface& s = level.surfaces[i];
        if (s.primaryLight == kNoIndex || !rectangleInAtlas(level, s)) continue;
        const Atlas& atlas = level.atlases[s.atlas];
        const uint64_t first = atlasTexelOffset(level, s.atlas);
        bool anyLit = false, anyShadowed = false, anyBetween = false;
        for (uint32_t y = s.lightmapY; y < s.lightmapY + s.lightmapHeight && !anyBetween; ++y) {
            const uint8_t* row = &baked.shadowMask[first + uint64_t(y) * atlas.width];
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
    if (baked.texels.size() != totalTexels(level)) return out;
    for (size_t i = 0; i < level.surfaces.size(); ++i) {
        const Surface& s = level.surfaces[i];
        if (!rectangleInAtlas(level, s)) continue;
        const uint32_t width = level.atlases[s.atlas].width;
        const uint64_t first = atlasTexelOffset(level, s.atlas);
        for (uint32_t y = s.lightmapY; y < s.lightmapY + s.lightmapHeight && !out[i]; ++y)
            for (uint32_t x = s.lightmapX; x < s.lightmapX + s.lightmapWidth && !out[i]; ++x)
                out[i] = baked.texels[first + uint64_t(y) * width + x].directEdgeSharpness > 0.0f;
    }
    return out;
}

}  // namespace onelight::world
