#include "vk/pipeline_cache.hpp"

#include <cstring>

#include "vk/vk_check.hpp"

namespace onelight::vk {

namespace {

uint32_t readU32(std::span<const uint8_t> bytes, size_t offset) {
    uint32_t v = 0;
    std::memcpy(&v, bytes.data() + offset, sizeof(v));
    return v;
}

}  // namespace

bool pipelineCacheFits(const Context& ctx, std::span<const uint8_t> bytes, std::string* why) {
    // VkPipelineCacheHeaderVersionOne: length, version, vendorID, deviceID, UUID (32 bytes).
    constexpr size_t kHeaderBytes = 16 + VK_UUID_SIZE;
    const auto fail = [why](const std::string& reason) {
        if (why) *why = reason;
        return false;
    };
    if (bytes.size() < kHeaderBytes) return fail("shorter than the cache header");
    if (readU32(bytes, 0) < kHeaderBytes || readU32(bytes, 0) > bytes.size())
        return fail("header length out of range");
    if (readU32(bytes, 4) != uint32_t(VK_PIPELINE_CACHE_HEADER_VERSION_ONE))
        return fail("header version");
    if (readU32(bytes, 8) != ctx.properties.vendorID) return fail("vendor ID");
    if (readU32(bytes, 12) != ctx.properties.deviceID) return fail("device ID");
    if (std::memcmp(bytes.data() + 16, ctx.properties.pipelineCacheUUID, VK_UUID_SIZE) != 0)
        return fail("pipeline cache UUID (another driver version)");
    return true;
}

bool createPipelineCache(Context& ctx, std::span<const uint8_t> bytes) {
    const bool fits = pipelineCacheFits(ctx, bytes);
    VkPipelineCacheCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO;
    info.initialDataSize = fits ? bytes.size() : 0;
    info.pInitialData = fits ? bytes.data() : nullptr;
    VK_CHECK(vkCreatePipelineCache(ctx.device, &info, nullptr, &ctx.pipelineCache));
    return fits;
}

std::vector<uint8_t> pipelineCacheData(const Context& ctx) {
    if (!ctx.pipelineCache) return {};
    size_t size = 0;
    VK_CHECK(vkGetPipelineCacheData(ctx.device, ctx.pipelineCache, &size, nullptr));
    std::vector<uint8_t> bytes(size);
    if (size) VK_CHECK(vkGetPipelineCacheData(ctx.device, ctx.pipelineCache, &size, bytes.data()));
    bytes.resize(size);
    return bytes;
}

void destroyPipelineCache(Context& ctx) {
    if (ctx.pipelineCache) vkDestroyPipelineCache(ctx.device, ctx.pipelineCache, nullptr);
    ctx.pipelineCache = VK_NULL_HANDLE;
}

}  // namespace onelight::vk
