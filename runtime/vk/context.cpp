#include "vk/context.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include "vk/vk_check.hpp"

namespace onelight::vk {

namespace {

const char* const kValidationLayer = "VK_LAYER_KHRONOS_validation";

// Counts and prints warnings and errors; the counters come through pUserData.
VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data,
                                              void* userData) {
    auto* counts = static_cast<ValidationCounts*>(userData);
    const char* label = nullptr;
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
        counts->errors.fetch_add(1);
        label = "error";
    } else if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
        counts->warnings.fetch_add(1);
        label = "warning";
    } else {
        return VK_FALSE;
    }
    std::fprintf(stderr, "vulkan %s: %s\n", label, data->pMessage ? data->pMessage : "");
    return VK_FALSE;  // never abort the call
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(ValidationCounts* counts) {
    VkDebugUtilsMessengerCreateInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = onDebugMessage;
    info.pUserData = counts;
    return info;
}

bool hasInstanceLayer(const char* name) {
    uint32_t count = 0;
    VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
    std::vector<VkLayerProperties> layers(count);
    VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
    for (const VkLayerProperties& layer : layers)
        if (std::strcmp(layer.layerName, name) == 0) return true;
    return false;
}

bool hasDeviceExtensions(VkPhysicalDevice gpu, const std::vector<const char*>& wanted) {
    uint32_t count = 0;
    VK_CHECK(vkEnumerateDeviceExtensionProperties(gpu, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> available(count);
    VK_CHECK(vkEnumerateDeviceExtensionProperties(gpu, nullptr, &count, available.data()));
    for (const char* name : wanted) {
        bool found = false;
        for (const VkExtensionProperties& ext : available)
            found = found || std::strcmp(ext.extensionName, name) == 0;
        if (!found) return false;
    }
    return true;
}

// The first queue family that does graphics and compute, or -1.
int graphicsComputeFamily(VkPhysicalDevice gpu) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(gpu, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(gpu, &count, families.data());
    const VkQueueFlags wanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    for (uint32_t i = 0; i < count; ++i)
        if ((families[i].queueFlags & wanted) == wanted && families[i].queueCount > 0)
            return int(i);
    return -1;
}

// Lower is preferred: a real GPU first, a software rasterizer (lavapipe) last.
int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return 0;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return 1;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return 3;
        default:
            return 4;
    }
}

std::string versionString(uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
           std::to_string(VK_API_VERSION_MINOR(version));
}

void createInstance(Context& ctx, const ContextOptions& options) {
    std::vector<const char*> layers;
    std::vector<const char*> extensions = options.instanceExtensions;
    if (ctx.validation) {
        if (!hasInstanceLayer(kValidationLayer))
            throw std::runtime_error(std::string("validation requested but ") + kValidationLayer +
                                     " is not installed (Debian: vulkan-validationlayers)");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }

    VkApplicationInfo app{};

    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = options.appName;
    app.pEngineName = "onelight";
    app.apiVersion = options.apiVersion;

    // Chained so that messages from vkCreateInstance and vkDestroyInstance are counted too.
    VkDebugUtilsMessengerCreateInfoEXT debugInfo = messengerInfo(&ctx.validationCounts);

    VkInstanceCreateInfo info{};

    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    info.pNext = ctx.validation ? &debugInfo : nullptr;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VK_CHECK(vkCreateInstance(&info, nullptr, &ctx.instance));

    if (ctx.validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(ctx.instance, "vkCreateDebugUtilsMessengerEXT"));
        if (!create) throw std::runtime_error("vkCreateDebugUtilsMessengerEXT is not available");
        VK_CHECK(create(ctx.instance, &debugInfo, nullptr, &ctx.messenger));
    }
}

void pickPhysicalDevice(Context& ctx, const ContextOptions& options) {
    uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(ctx.instance, &count, nullptr));
    std::vector<VkPhysicalDevice> gpus(count);
    VK_CHECK(vkEnumeratePhysicalDevices(ctx.instance, &count, gpus.data()));

    std::string seen;
    int bestRank = 1 << 30;
    for (VkPhysicalDevice gpu : gpus) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(gpu, &props);
        seen += std::string(seen.empty() ? "" : ", ") + props.deviceName + " (Vulkan " +
                versionString(props.apiVersion) + ")";
        int family = graphicsComputeFamily(gpu);
        if (props.apiVersion < options.apiVersion || family < 0 ||
            !hasDeviceExtensions(gpu, options.deviceExtensions))
            continue;
        if (typeRank(props.deviceType) < bestRank) {
            bestRank = typeRank(props.deviceType);
            ctx.physicalDevice = gpu;
            ctx.queueFamily = uint32_t(family);
            ctx.properties = props;
        }
    }
    if (ctx.physicalDevice == VK_NULL_HANDLE)
        throw std::runtime_error("no Vulkan " + versionString(options.apiVersion) +
                                 " device with a graphics+compute queue and the requested "
                                 "extensions; devices found: " +
                                 (seen.empty() ? std::string("none") : seen));
    vkGetPhysicalDeviceMemoryProperties(ctx.physicalDevice, &ctx.memoryProperties);
}

void createDevice(Context& ctx, const ContextOptions& options) {
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{};
    queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queueInfo.queueFamilyIndex = ctx.queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    VkDeviceCreateInfo info{};

    info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    info.pNext = options.featureChain;
    info.pEnabledFeatures = &options.features;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = uint32_t(options.deviceExtensions.size());
    info.ppEnabledExtensionNames = options.deviceExtensions.data();
    VK_CHECK(vkCreateDevice(ctx.physicalDevice, &info, nullptr, &ctx.device));
    vkGetDeviceQueue(ctx.device, ctx.queueFamily, 0, &ctx.queue);

    VkCommandPoolCreateInfo poolInfo{};

    poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = ctx.queueFamily;
    VK_CHECK(vkCreateCommandPool(ctx.device, &poolInfo, nullptr, &ctx.commandPool));
}

}  // namespace

bool validationRequested() {
    const char* value = std::getenv("ONELIGHT_VALIDATION");
    return value && std::strcmp(value, "1") == 0;
}

void createContext(Context& ctx, const ContextOptions& options) {
    ctx.validation = options.validation;
    try {
        createInstance(ctx, options);
        pickPhysicalDevice(ctx, options);
        createDevice(ctx, options);
    } catch (...) {
        destroyContext(ctx);
        throw;
    }
}

void destroyContext(Context& ctx) {
    if (ctx.pipelineCache) vkDestroyPipelineCache(ctx.device, ctx.pipelineCache, nullptr);
    ctx.pipelineCache = VK_NULL_HANDLE;
    if (ctx.commandPool) vkDestroyCommandPool(ctx.device, ctx.commandPool, nullptr);
    ctx.commandPool = VK_NULL_HANDLE;
    ctx.queue = VK_NULL_HANDLE;
    if (ctx.device) vkDestroyDevice(ctx.device, nullptr);
    ctx.device = VK_NULL_HANDLE;
    ctx.physicalDevice = VK_NULL_HANDLE;
    if (ctx.messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(ctx.instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(ctx.instance, ctx.messenger, nullptr);
    }
    ctx.messenger = VK_NULL_HANDLE;
    if (ctx.instance) vkDestroyInstance(ctx.instance, nullptr);
    ctx.instance = VK_NULL_HANDLE;
}

}  // namespace onelight::vk
