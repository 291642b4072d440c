// The game's pipeline cache between runs: $XDG_CACHE_HOME/onelight/pipelines.bin (else
// ~/.cache/onelight/pipelines.bin), read into the context's VkPipelineCache before the renderer
// creates its pipelines and written back, atomically, when the game closes it.
#pragma once

#include <string>

#include "vk/context.hpp"

namespace onelight::game {

/// Where the cache is kept; empty when neither XDG_CACHE_HOME nor HOME is set.
[[nodiscard]] std::string pipelineCachePath();

/// Creates ctx.pipelineCache from the file when it fits this device, else empty. A missing,
/// unreadable or foreign file is not an error (the pipelines are made afresh). Returns the bytes
/// taken from the file (0: none).
size_t openPipelineCache(vk::Context& ctx, const std::string& path);

/// Writes what ctx.pipelineCache holds to `path` when it changed since `loadedBytes` were read;
/// a failure is reported on stderr and is not an error (the next run makes the pipelines again).
void keepPipelineCache(const vk::Context& ctx, const std::string& path, size_t loadedBytes);

}  // namespace onelight::game
