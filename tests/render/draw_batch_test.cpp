// Draw batching (render/frame_view.hpp batchDraws): which culled draws merge into one.
#include <gtest/gtest.h>

#include <vector>

#include "render/frame_view.hpp"

namespace {

using namespace onelight;
using render::Draw;

Draw staticDraw(uint32_t firstIndex, uint32_t indexCount, uint32_t material = 0,
                uint32_t primary = 0, uint32_t atlas = 0) {
    Draw d;
    d.firstIndex = firstIndex;
    d.indexCount = indexCount;
    d.material = material;
    d.primaryLight = primary;
    d.atlas = atlas;
    return d;
}

// Adjacent ranges of the same state merge whatever order culling left them in; a gap (a culled
// surface between them) or any difference in what the draw binds or pushes keeps them apart.
TEST(DrawBatching, AdjacentRangesOfTheSameStateMergeAndNothingElse) {
    std::vector<Draw> draws = {
        staticDraw(6, 6),     staticDraw(0, 6),        staticDraw(12, 3),         staticDraw(18, 3),
        staticDraw(21, 3, 1), staticDraw(24, 3, 1, 1), staticDraw(27, 3, 1, 1, 2)};
    render::batchDraws(draws, false);
    ASSERT_EQ(draws.size(), 5u);
    uint32_t total = 0;
    for (const Draw& d : draws) total += d.indexCount;
    EXPECT_EQ(total, 6u + 6 + 3 + 3 + 3 + 3 + 3);  // no index lost or drawn twice
    EXPECT_EQ(draws[0].firstIndex, 0u);
    EXPECT_EQ(draws[0].indexCount, 15u);  // 0..6, 6..12, 12..15
    EXPECT_EQ(draws[1].firstIndex, 18u);  // after the gap 15..18
    EXPECT_EQ(draws[1].indexCount, 3u);
}

// A dynamic mesh (an entity's transform and object lighting) is never merged, even with an
// adjacent range of the same material; dynamic draws stay front to back.
TEST(DrawBatching, DynamicMeshesStayOneDrawEachFrontToBack) {
    std::vector<Draw> draws = {staticDraw(0, 3), staticDraw(3, 3), staticDraw(6, 3)};
    draws[1].entity = 4;
    draws[1].distance2 = 9.0f;
    draws[2].entity = 5;
    draws[2].distance2 = 1.0f;
    render::batchDraws(draws, false);
    ASSERT_EQ(draws.size(), 3u);
    EXPECT_EQ(draws[0].entity, render::kNoIndex);
    EXPECT_EQ(draws[1].entity, 5u);
    EXPECT_EQ(draws[2].entity, 4u);
}

// The raster floor merges every adjacent static range whatever it binds.
TEST(DrawBatching, TheRasterFloorMergesEveryAdjacentRange) {
    std::vector<Draw> draws = {staticDraw(0, 3, 0), staticDraw(3, 3, 1, 2), staticDraw(6, 3, 2),
                               staticDraw(12, 3, 3)};
    render::batchDraws(draws, true);
    ASSERT_EQ(draws.size(), 2u);
    EXPECT_EQ(draws[0].indexCount, 9u);
}

}  // namespace
