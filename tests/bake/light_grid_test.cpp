// The light grid (bake/grid): cells inside solid geometry are flagged and hold no light.
#include <gtest/gtest.h>

#include "bake_scenes.hpp"

namespace onelight::bake {
namespace {

using world::LightRole;

// Cells whose centre is inside a solid block are flagged and hold no light; the others see
// the primary and hold it as dominant with full visibility.
TEST(LightGrid, CellsInsideSolidsAreMarked) {
    world::SourceLevel level;
    const uint32_t m = test::addLambertMaterial(level, 0.5f);
    test::addBox(level, {0.0f, 0.0f, 0.0f}, {4.0f, 4.0f, 4.0f}, m, true, "room");
    // The block stands 1 cm clear of the room's walls: where a block's face lies in a wall's
    // plane, which of the two coplanar faces a ray meets first is the BVH's arbitrary choice.
    test::addBox(level, {0.01f, 0.01f, 0.01f}, {2.0f, 3.99f, 3.99f}, m, false, "solid");
    level.lights.push_back(test::pointLight({3.0f, 2.0f, 2.0f}, 50.0f, LightRole::kPrimary));
    BakeOptions o = test::fastBakeOptions();
    o.gridCellSize = 1.0f;
    const BakeResult r = bakeLevel(level, o);
    const world::LightGrid& g = r.baked.grid;
    ASSERT_EQ(g.dims, glm::uvec3(4, 4, 4));
    for (uint32_t i = 0; i < g.cells.size(); ++i) {
        const uint32_t x = i % 4;
        const world::LightGridCell& c = g.cells[i];
        if (x < 2) {
            EXPECT_EQ(c.flags, uint32_t(world::kLightGridCellInsideSolid)) << i;
            EXPECT_EQ(c.dominantPrimary, world::kNoIndex);
        } else {
            EXPECT_EQ(c.flags, 0u) << i;  // no flag
            EXPECT_EQ(c.dominantPrimary, 0u);
            EXPECT_EQ(c.primaryVisibility, 1.0f);
        }
    }
}

}  // namespace
}  // namespace onelight::bake
