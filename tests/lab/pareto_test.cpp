// level-report's arithmetic: the Pareto rule and the 8x8-block error, on hand-made inputs.
#include <cmath>

#include <gtest/gtest.h>

#include <vector>

#include "block_error.hpp"
#include "pareto.hpp"

namespace {

using onelight::lab::Costs;

TEST(LevelReportPareto, ARowIsOnTheFrontUnlessAnotherIsNoWorseAndBetterInOne) {
    const std::vector<Costs> rows = {
        {10.0, 5.0, 0.20},  // 0: front (fastest frame)
        {12.0, 5.0, 0.10},  // 1: front (lowest error)
        {12.0, 5.0, 0.20},  // 2: dominated by 0 and 1
        {10.0, 5.0, 0.20},  // 3: equal to 0: neither dominates, both on the front
        {11.0, 1.0, 0.30},  // 4: front (cheapest bake)
        {13.0, 6.0, 0.25},  // 5: dominated
    };
    const std::vector<bool> front = onelight::lab::paretoFront(rows);
    EXPECT_EQ(front, (std::vector<bool>{true, true, false, true, true, false}));
    EXPECT_FALSE(onelight::lab::dominates(rows[0], rows[3]));
    EXPECT_TRUE(onelight::lab::dominates(rows[1], rows[2]));
}

onelight::world::FloatImage flat(uint32_t w, uint32_t h, float value) {
    return {w, h, std::vector<float>(size_t(w) * h * 4, value)};
}

TEST(LevelReportBlockError, MeanRelativeErrorOfBlockLuminance) {
    onelight::world::FloatImage reference = flat(16, 8, 2.0f), frame = flat(16, 8, 2.0f);
    // The right block 50% too bright: errors 0 and 0.5, mean 0.25.
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 8; x < 16; ++x)
            for (int c = 0; c < 3; ++c) frame.rgba[(y * 16 + x) * 4 + c] = 3.0f;
    const onelight::lab::BlockErrors e = onelight::lab::blockErrors(frame, reference);
    ASSERT_EQ(e.columns, 2u);
    ASSERT_EQ(e.rows, 1u);
    EXPECT_DOUBLE_EQ(e.relative[0], 0.0);
    EXPECT_NEAR(e.relative[1], 0.5, 1e-12);
    EXPECT_NEAR(e.mean, 0.25, 1e-12);
    EXPECT_NEAR(e.level, (2.0 + 3.0) / (2.0 + 2.0), 1e-12);  // mean luminance, frame over reference
    // A black reference block is measured against the floor, not divided by zero.
    onelight::world::FloatImage dark = reference;
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) dark.rgba[(y * 16 + x) * 4 + c] = 0.0f;
    const double floor = onelight::lab::kErrorFloor * 1.0;  // 5% of the mean luminance 1
    EXPECT_NEAR(onelight::lab::blockErrors(reference, dark).relative[0], 2.0 / floor, 1e-9);
    // Both black: level 1; a lit frame over a black reference: large but finite.
    EXPECT_DOUBLE_EQ(onelight::lab::blockErrors(flat(8, 8, 0.0f), flat(8, 8, 0.0f)).level, 1.0);
    EXPECT_TRUE(
        std::isfinite(onelight::lab::blockErrors(flat(8, 8, 1.0f), flat(8, 8, 0.0f)).level));
    EXPECT_THROW((void)onelight::lab::blockErrors(flat(8, 8, 1.0f), reference),
                 std::invalid_argument);
}

// The median block's level: five blocks at 2x the reference and a lamp's block at 100x make a
// mean level of 18.3 but a median of 2; an even count takes the two middle blocks' mean.
TEST(LevelReportBlockError, TheMedianBlocksLevelIgnoresALampsPixels) {
    const onelight::world::FloatImage reference = flat(48, 8, 1.0f);
    onelight::world::FloatImage frame = flat(48, 8, 2.0f);
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 40; x < 48; ++x)
            for (int c = 0; c < 3; ++c) frame.rgba[(y * 48 + x) * 4 + c] = 100.0f;
    const onelight::lab::BlockErrors e = onelight::lab::blockErrors(frame, reference);
    EXPECT_NEAR(e.level, (5.0 * 2.0 + 100.0) / 6.0, 1e-9);
    EXPECT_NEAR(e.medianLevel, 2.0, 1e-12);
    onelight::world::FloatImage halves = flat(16, 8, 3.0f);
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) halves.rgba[(y * 16 + x) * 4 + c] = 1.0f;
    EXPECT_NEAR(onelight::lab::blockErrors(halves, flat(16, 8, 1.0f)).medianLevel, 2.0, 1e-12);
    EXPECT_DOUBLE_EQ(onelight::lab::blockErrors(flat(8, 8, 0.0f), flat(8, 8, 0.0f)).medianLevel,
                     1.0);
    // Blocks darker than the floor (5% of the mean) in both are level, whatever their ratio:
    // three black-ish blocks and two lit ones, the same in both, have a median of 1.
    onelight::world::FloatImage dim = flat(40, 8, 1e-4f), dimmer = flat(40, 8, 1e-5f);
    for (onelight::world::FloatImage* f : {&dim, &dimmer})
        for (uint32_t y = 0; y < 8; ++y)
            for (uint32_t x = 24; x < 40; ++x)
                for (int c = 0; c < 3; ++c) f->rgba[(y * 40 + x) * 4 + c] = 1.0f;
    EXPECT_NEAR(onelight::lab::blockErrors(dim, dimmer).medianLevel, 1.0, 1e-12);
}

}  // namespace
