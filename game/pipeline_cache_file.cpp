#include "pipeline_cache_file.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <vector>

#include "vk/pipeline_cache.hpp"
#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/file_write.hpp"

namespace onelight::game {

namespace {

// A pipeline cache larger than this is not one this game wrote.
constexpr uint64_t kMaxPipelineCacheBytes = uint64_t(256) << 20;

}  // namespace

std::string pipelineCachePath() {
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    if (xdg && *xdg) return std::string(xdg) + "/onelight/pipelines.bin";
    const char* home = std::getenv("HOME");
    if (home && *home) return std::string(home) + "/.cache/onelight/pipelines.bin";
    return {};
}

size_t openPipelineCache(vk::Context& ctx, const std::string& path) {
    std::vector<uint8_t> bytes;
    std::error_code ec;
    if (!path.empty() && std::filesystem::is_regular_file(path, ec)) {
        try {
            bytes = world::readRegularFile(path, "a pipeline cache", kMaxPipelineCacheBytes);
        } catch (const world::Error& e) {
            std::fprintf(stderr, "onelight: pipeline cache not used: %s\n", e.what());
            bytes.clear();
        }
    }
    return vk::createPipelineCache(ctx, bytes) ? bytes.size() : 0;
}

void keepPipelineCache(const vk::Context& ctx, const std::string& path, size_t loadedBytes) {
    if (path.empty() || !ctx.pipelineCache) return;
    const std::vector<uint8_t> bytes = vk::pipelineCacheData(ctx);
    if (bytes.empty() || bytes.size() == loadedBytes) return;
    try {
        world::makeFolder(std::filesystem::path(path).parent_path().string(),
                          "the pipeline cache's folder");
        world::writeFileAtomically(path, bytes);
    } catch (const world::Error& e) {
        std::fprintf(stderr, "onelight: pipeline cache not kept: %s\n", e.what());
    }
}

}  // namespace onelight::game
