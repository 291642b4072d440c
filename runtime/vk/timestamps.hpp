// GPU timestamps: a query pool of N timestamps and their reading in milliseconds.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "vk/context.hpp"

namespace onelight::vk {

// Whether ctx's queue writes timestamps (valid bits and a positive period).
[[nodiscard]] bool timestampsSupported(const Context& ctx);

// A pool of `count` timestamp queries. The caller destroys it with vkDestroyQueryPool.
[[nodiscard]] VkQueryPool createTimestampPool(const Context& ctx, uint32_t count);

// The `count` timestamps of `pool` (written and finished), as milliseconds since the first.
[[nodiscard]] std::vector<double> readTimestampsMs(const Context& ctx, VkQueryPool pool,
                                                   uint32_t count);

}  // namespace onelight::vk
