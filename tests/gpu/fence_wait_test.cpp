// vk::waitSurvivingSuspend (vk/commands.hpp): a fence wait whose deadline passed while the process
// was stopped gets one more wait, each with the whole timeout; a hung device still times out.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "vk/commands.hpp"

namespace onelight::test {
namespace {

// A wait that answers from `results` in turn and records the timeouts it was given.
struct ScriptedWait {
    std::vector<VkResult> results;
    std::vector<uint64_t> timeouts;
    VkResult operator()(uint64_t timeoutNs) {
        timeouts.push_back(timeoutNs);
        return results.at(timeouts.size() - 1);
    }
};

VkResult waitWith(ScriptedWait& scripted, uint64_t timeoutNs) {
    return vk::waitSurvivingSuspend([&](uint64_t t) { return scripted(t); }, timeoutNs);
}

TEST(FenceWait, AWaitThatASuspendInterruptedIsTriedOnceMore) {
    ScriptedWait resumed{{VK_TIMEOUT, VK_SUCCESS}, {}};
    EXPECT_EQ(waitWith(resumed, 60), VK_SUCCESS);
    EXPECT_EQ(resumed.timeouts, (std::vector<uint64_t>{60, 60}));
}

TEST(FenceWait, AHungDeviceTimesOutTwiceAndNoMore) {
    ScriptedWait hung{{VK_TIMEOUT, VK_TIMEOUT, VK_SUCCESS}, {}};
    EXPECT_EQ(waitWith(hung, 7), VK_TIMEOUT);
    EXPECT_EQ(hung.timeouts.size(), 2u);
}

TEST(FenceWait, SuccessAndErrorsReturnAtOnce) {
    for (VkResult r : {VK_SUCCESS, VK_ERROR_DEVICE_LOST, VK_ERROR_OUT_OF_DEVICE_MEMORY}) {
        ScriptedWait once{{r, VK_SUCCESS}, {}};
        EXPECT_EQ(waitWith(once, 5), r);
        EXPECT_EQ(once.timeouts.size(), 1u);
    }
}

}  // namespace
}  // namespace onelight::test
