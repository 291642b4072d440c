// VK_CHECK: the one way onelight checks a Vulkan result.
#pragma once

#include <vulkan/vulkan.h>

namespace onelight::vk {

// The name of a VkResult ("VK_ERROR_DEVICE_LOST"), or nullptr for a code not listed here.
[[nodiscard]] const char* resultName(VkResult result);

// Throws std::runtime_error "CALL failed with RESULT at FILE:LINE" unless result is VK_SUCCESS.
// Positive success codes (VK_TIMEOUT, VK_INCOMPLETE, VK_SUBOPTIMAL_KHR) throw too: a caller
// that expects one checks it by hand.
void check(VkResult result, const char* call, const char* file, int line);

}  // namespace onelight::vk

#define VK_CHECK(call) ::onelight::vk::check((call), #call, __FILE__, __LINE__)
