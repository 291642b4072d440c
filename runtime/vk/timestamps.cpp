#include "vk/timestamps.hpp"

#include <algorithm>

#include "vk/vk_check.hpp"

namespace onelight::vk {

bool timestampsSupported(const Context& ctx) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &count, families.data());
    return ctx.queueFamily < count && families[ctx.queueFamily].timestampValidBits > 0 &&
           ctx.properties.limits.timestampPeriod > 0.0f;
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
    // Later timestamps may read a tick or two below the first (stages finish out of order).
    for (uint32_t i = 0; i < count; ++i)
        ms[i] = double(std::max<int64_t>(int64_t(ticks[i] - ticks[0]), 0)) * msPerTick;
    return ms;
}

}  // namespace onelight::vk
