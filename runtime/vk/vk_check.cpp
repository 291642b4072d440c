#include "vk/vk_check.hpp"

#include <stdexcept>
#include <string>

namespace onelight::vk {

const char* resultName(VkResult result) {
    switch (result) {
#define ONELIGHT_VK_RESULT(name) \
    case name:                   \
        return #name;
        ONELIGHT_VK_RESULT(VK_SUCCESS)
        ONELIGHT_VK_RESULT(VK_NOT_READY)
        ONELIGHT_VK_RESULT(VK_TIMEOUT)
        ONELIGHT_VK_RESULT(VK_EVENT_SET)
        ONELIGHT_VK_RESULT(VK_EVENT_RESET)
        ONELIGHT_VK_RESULT(VK_INCOMPLETE)
        ONELIGHT_VK_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
        ONELIGHT_VK_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        ONELIGHT_VK_RESULT(VK_ERROR_INITIALIZATION_FAILED)
        ONELIGHT_VK_RESULT(VK_ERROR_DEVICE_LOST)
        ONELIGHT_VK_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
        ONELIGHT_VK_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        ONELIGHT_VK_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
        ONELIGHT_VK_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        ONELIGHT_VK_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
        ONELIGHT_VK_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        ONELIGHT_VK_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
        ONELIGHT_VK_RESULT(VK_ERROR_FRAGMENTED_POOL)
        ONELIGHT_VK_RESULT(VK_ERROR_UNKNOWN)
        ONELIGHT_VK_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
        ONELIGHT_VK_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        ONELIGHT_VK_RESULT(VK_ERROR_FRAGMENTATION)
        ONELIGHT_VK_RESULT(VK_ERROR_SURFACE_LOST_KHR)
        ONELIGHT_VK_RESULT(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
        ONELIGHT_VK_RESULT(VK_SUBOPTIMAL_KHR)
        ONELIGHT_VK_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
        ONELIGHT_VK_RESULT(VK_ERROR_VALIDATION_FAILED_EXT)
#undef ONELIGHT_VK_RESULT
        default:
            return nullptr;
    }
}

void check(VkResult result, const char* call, const char* file, int line) {
    if (result == VK_SUCCESS) return;
    const char* name = resultName(result);
    std::string what = std::string(call) + " failed with " +
                       (name ? std::string(name) : "VkResult " + std::to_string(int(result))) +
                       " at " + file + ":" + std::to_string(line);
    throw std::runtime_error(what);
}

}  // namespace onelight::vk
