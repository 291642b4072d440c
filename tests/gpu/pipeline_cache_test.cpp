// The pipeline cache kept between runs (vk/pipeline_cache.hpp): bytes this device wrote are
// handed back to it, and bytes of another device, driver or file are refused before the driver
// sees them, each with the field that differed.
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "vk/context.hpp"
#include "vk/pipeline_cache.hpp"

namespace onelight::test {
namespace {

// The cache's bytes with the 32-bit word at `offset` replaced by `value`.
std::vector<uint8_t> withWord(std::vector<uint8_t> bytes, size_t offset, uint32_t value) {
    std::memcpy(bytes.data() + offset, &value, sizeof(value));
    return bytes;
}

TEST(PipelineCache, BytesOfThisDeviceAreTakenAndOthersRefusedByField) {
    vk::Context ctx;
    vk::createContext(ctx, vk::ContextOptions{});
    EXPECT_FALSE(vk::createPipelineCache(ctx, {}));  // nothing to start from: an empty cache
    const std::vector<uint8_t> bytes = vk::pipelineCacheData(ctx);
    vk::destroyPipelineCache(ctx);
    ASSERT_GE(bytes.size(), 16u + VK_UUID_SIZE);  // at least the header

    std::string why;
    EXPECT_TRUE(vk::pipelineCacheFits(ctx, bytes, &why)) << why;
    const auto refusal = [&](const std::vector<uint8_t>& b) {
        std::string reason;
        EXPECT_FALSE(vk::pipelineCacheFits(ctx, b, &reason));
        return reason;
    };
    EXPECT_EQ(refusal(std::vector<uint8_t>(bytes.begin(), bytes.begin() + 20)),
              "shorter than the cache header");
    EXPECT_EQ(refusal(withWord(bytes, 0, uint32_t(bytes.size() + 1))),
              "header length out of range");
    EXPECT_EQ(refusal(withWord(bytes, 4, 7u)), "header version");
    EXPECT_EQ(refusal(withWord(bytes, 8, ctx.properties.vendorID + 1)), "vendor ID");
    EXPECT_EQ(refusal(withWord(bytes, 12, ctx.properties.deviceID + 1)), "device ID");
    std::vector<uint8_t> otherDriver = bytes;
    otherDriver[16] ^= 0xFF;
    EXPECT_EQ(refusal(otherDriver), "pipeline cache UUID (another driver version)");

    // What fits seeds the cache; what does not leaves it empty, and nothing fails.
    EXPECT_TRUE(vk::createPipelineCache(ctx, bytes));
    EXPECT_NE(ctx.pipelineCache, VkPipelineCache(VK_NULL_HANDLE));
    vk::destroyPipelineCache(ctx);
    EXPECT_FALSE(vk::createPipelineCache(ctx, otherDriver));
    EXPECT_NE(ctx.pipelineCache, VkPipelineCache(VK_NULL_HANDLE));
    vk::destroyContext(ctx);  // destroys the cache it still holds
    EXPECT_EQ(ctx.pipelineCache, VkPipelineCache(VK_NULL_HANDLE));
}

}  // namespace
}  // namespace onelight::test
