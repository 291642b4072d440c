// Each static surface's baked shadow mask over its lightmap rectangle (world/surface_shadow.hpp):
// wholly lit, wholly shadowed or mixed, on hand-made atlases.
#include <gtest/gtest.h>

#include "world/surface_shadow.hpp"

namespace onelight::world {
namespace {

// Two atlases, 8x4 and 4x4; the mask lit (255) everywhere but where a test writes.
struct Fixture {
    CompiledLevel level;
    BakedLighting baked;
    Fixture() {
        level.atlases = {{8, 4}, {4, 4}};
        baked.shadowMask.assign(8 * 4 + 4 * 4, 255);
        level.lights.resize(1);
    }
    // A surface lit by light 0 over texels [x, x + w) x [y, y + h) of `atlas`.
    void addSurface(uint32_t atlas, uint32_t x, uint32_t y, uint32_t w, uint32_t h,
                    uint32_t primary = 0) {
        Surface s;
        s.atlas = atlas;
        s.primaryLight = primary;
        s.lightmapX = x;
        s.lightmapY = y;
        s.lightmapWidth = w;
        s.lightmapHeight = h;
        level.surfaces.push_back(s);
    }
    uint8_t& mask(uint32_t atlas, uint32_t x, uint32_t y) {
        return baked.shadowMask[(atlas == 0 ? 0 : 32) + y * (atlas == 0 ? 8 : 4) + x];
    }
};

TEST(SurfaceShadows, EachSurfaceIsLitShadowedOrMixedOverItsWholeRectangle) {
    Fixture f;
    f.addSurface(0, 0, 0, 4, 4);  // lit whole
    f.addSurface(0, 4, 0, 4, 4);  // shadowed whole
    f.addSurface(1, 0, 0, 2, 2);  // one texel half lit: mixed
    f.addSurface(1, 2, 0, 2, 2);  // one texel shadowed among lit ones: mixed
    f.addSurface(1, 0, 2, 4, 2);  // lit whole, in the second atlas
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 4; x < 8; ++x) f.mask(0, x, y) = 0;
    f.mask(1, 1, 1) = 128;
    f.mask(1, 3, 0) = 0;
    const std::vector<SurfaceShadow> s = surfaceShadows(f.level, f.baked);
    ASSERT_EQ(s.size(), 5u);
    EXPECT_EQ(s[0], SurfaceShadow::kLit);
    EXPECT_EQ(s[1], SurfaceShadow::kShadowed);
    EXPECT_EQ(s[2], SurfaceShadow::kMixed);
    EXPECT_EQ(s[3], SurfaceShadow::kMixed);
    EXPECT_EQ(s[4], SurfaceShadow::kLit);
}

// What cannot be known is mixed: no primary, no atlas, an empty or outlying rectangle, a mask
// that is not the atlases' size (no bake).
TEST(SurfaceShadows, WhatCannotBeKnownIsMixed) {
    Fixture f;
    f.addSurface(0, 0, 0, 2, 2, kNoIndex);
    f.addSurface(kNoIndex, 0, 0, 2, 2);
    f.addSurface(0, 0, 0, 0, 2);
    f.addSurface(0, 7, 0, 2, 2);
    f.addSurface(1, 0, 3, 1, 2);
    f.addSurface(5, 0, 0, 1, 1);
    for (SurfaceShadow s : surfaceShadows(f.level, f.baked)) EXPECT_EQ(s, SurfaceShadow::kMixed);
    f.addSurface(0, 0, 0, 2, 2);
    EXPECT_EQ(surfaceShadows(f.level, f.baked).back(), SurfaceShadow::kLit);
    f.baked.shadowMask.pop_back();
    EXPECT_EQ(surfaceShadows(f.level, f.baked).back(), SurfaceShadow::kMixed);
    f.baked.shadowMask.clear();
    EXPECT_EQ(surfaceShadows(f.level, f.baked).back(), SurfaceShadow::kMixed);
}

}  // namespace
}  // namespace onelight::world
