#include "vk/timestamps.hpp"

#include <algorithm>

#include "vk/vk_check.hpp"

namespace onelight::vk {

namespace {

// How many low bits of a timestamp the queue writes (0: none).
uint32_t validBits(const Context& ctx) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &count, families.data());
    return ctx.queueFamily < count ? families[ctx.queueFamily].timestampValidBits : 0;
}

}  // namespace

bool timestampsSupported(const Context& ctx) {
    return validBits(ctx) > 0 && ctx.properties.limits.timestampPeriod > 0.0f;
}

VkQueryPool createTimestampPool(const Context& ctx, uint32_t count) {
    VkQueryPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = count;
    VkQueryPool pool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateQueryPool(ctx.device, &info, nullptr, &pool));
    return pool;
}

std::vector<double> readTimestampsMs(const Context& ctx, VkQueryPool pool, uint32_t count) {
    std::vector<uint64_t> ticks(count);
    VK_CHECK(vkGetQueryPoolResults(ctx.device, pool, 0, count, count * sizeof(uint64_t),
                                   ticks.data(), sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const double msPerTick = double(ctx.properties.limits.timestampPeriod) * 1e-6;
    std::vector<double> ms(count);
    // Differences modulo the valid bits (the counter may wrap between two readings); a later
    // timestamp a tick or two below the first (stages finish out of order) reads as 0.
    const uint32_t bits = validBits(ctx);
    const uint64_t mask = bits >= 64 ? ~uint64_t(0) : (uint64_t(1) << bits) - 1;
    for (uint32_t i = 0; i < count; ++i) {
        const uint64_t ahead = (ticks[i] - ticks[0]) & mask;
        const bool behind = ahead > mask / 2;  // more than half the range: a small step back
        ms[i] = behind ? 0.0 : double(ahead) * msPerTick;
    }
    return ms;
}

}  // namespace onelight::vk
