// The Vulkan context: instance, optional validation messenger, physical and logical device, one
// queue that does graphics and compute, and a command pool on it.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <vector>

namespace onelight::vk {

// What the debug-utils messenger has seen. Lives inside Context, which never moves, so the
// messenger reaches it through pUserData; it is still readable after destroyContext().
struct ValidationCounts {
    std::atomic<uint32_t> errors{0};    // messages of severity ERROR
    std::atomic<uint32_t> warnings{0};  // messages of severity WARNING
};

// True when the environment variable ONELIGHT_VALIDATION is "1".
[[nodiscard]] bool validationRequested();

// How to create a Context. Extension lists are for later users (a window adds the surface and
// swapchain extensions); headless compute needs none.
struct ContextOptions {
    const char* appName = "onelight";
    uint32_t apiVersion = VK_API_VERSION_1_1;     // matches glslang --target-env vulkan1.1
    bool validation = validationRequested();      // ONELIGHT_VALIDATION=1
    std::vector<const char*> instanceExtensions;  // in addition to debug utils
    std::vector<const char*> deviceExtensions;
    VkPhysicalDeviceFeatures features{};  // core features to enable (the device must have them)
    const void* featureChain = nullptr;   // borrowed: VkPhysicalDevice*Features structs, chained
                                          // into VkDeviceCreateInfo::pNext (e.g. Vulkan 1.3's)
};

// One device and one queue. Create with createContext(), destroy with destroyContext() after
// every object made from it. Not copyable, not movable: the messenger points into it.
struct Context {
    VkInstance instance = VK_NULL_HANDLE;                 // owned
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;  // owned, only with validation
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;     // borrowed from instance
    VkDevice device = VK_NULL_HANDLE;                     // owned
    VkQueue queue = VK_NULL_HANDLE;                       // borrowed from device
    VkCommandPool commandPool = VK_NULL_HANDLE;           // owned, on queueFamily
    // Owned when made (vk/pipeline_cache.hpp), else null; every pipeline is created through it.
    VkPipelineCache pipelineCache = VK_NULL_HANDLE;

    uint32_t queueFamily = 0;                             // supports graphics and compute
    VkPhysicalDeviceProperties properties{};              // of physicalDevice: name, limits
    VkPhysicalDeviceMemoryProperties memoryProperties{};  // of physicalDevice: memory types
    bool validation = false;            // VK_LAYER_KHRONOS_validation and the messenger are on
    ValidationCounts validationCounts;  // what the messenger counted (zero without validation)

    Context() = default;
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
};

// Creates everything in ctx, in the order of its fields. Picks a device with a graphics+compute
// queue, options.apiVersion and the device extensions, preferring by type: discrete, integrated,
// virtual, then CPU (lavapipe). With options.validation, enables VK_LAYER_KHRONOS_validation and a
// messenger that counts and prints warnings and errors to stderr; throws if the layer is missing.
// On failure throws std::runtime_error, leaving ctx destroyed.
void createContext(Context& ctx, const ContextOptions& options);

// Destroys what createContext() made, in reverse order. Safe on a partly created context.
void destroyContext(Context& ctx);

}  // namespace onelight::vk
