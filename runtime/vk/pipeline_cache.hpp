// The context's VkPipelineCache and its bytes between runs: what a file gives back is checked
// against this device before the driver sees it, and what the cache holds is read out for the
// caller to keep (the game keeps it in the user's cache folder, game/render_target.cpp).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "vk/context.hpp"

namespace onelight::vk {

/// Whether `bytes` start with the Vulkan pipeline cache header (version one) of this device:
/// header length, version, vendor and device IDs and the pipeline cache UUID. Bytes from another
/// device, driver version or file are not handed to the driver; `why` says which field differed.
[[nodiscard]] bool pipelineCacheFits(const Context& ctx, std::span<const uint8_t> bytes,
                                     std::string* why = nullptr);

/// Creates ctx.pipelineCache, seeded with `bytes` when they fit this device (else empty).
/// Returns whether they were used.
bool createPipelineCache(Context& ctx, std::span<const uint8_t> bytes);

/// What ctx.pipelineCache holds now (empty without one).
[[nodiscard]] std::vector<uint8_t> pipelineCacheData(const Context& ctx);

void destroyPipelineCache(Context& ctx);

}  // namespace onelight::vk
