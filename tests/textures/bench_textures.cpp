// onelight-bench-textures [LEVEL ...]: the texture stage (bake/textures/texture_stage.hpp) on real
// levels, by each normal-and-gloss mip method: wall time per megatexel of level-0 output, and the
// memory of every texture with its mips by kind. Default levels: the NormalTangentTest glTF sample
// (a normal map with occlusion-roughness-metallic) when ../shared/assets is beside the checkout,
// and the OpenArena maps aggressor and kaos when their package is installed. One run per level and
// method after a warm-up run on the same level (the decode of the images is part of each run, as in
// a bake); compare the methods' times within one run only (docs/toolchain.md, "Timing things").
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "bake/textures/texture_stage.hpp"
#include "world/import/level_import.hpp"

namespace {

using namespace onelight;

struct Method {
    const char* name;
    world::GlossMipMethod method;
};
constexpr Method kMethods[] = {{"blit", world::GlossMipMethod::kBlit},
                               {"black_ops", world::GlossMipMethod::kBlackOps},
                               {"wwii", world::GlossMipMethod::kWwii},
                               {"clean", world::GlossMipMethod::kClean}};

double megatexels(const world::ProcessedTextures& textures) {
    double texels = 0.0;
    for (const world::ProcessedTexture& t : textures.textures)
        texels += double(t.width) * double(t.height);
    return texels * 1e-6;
}

// Memory by kind (format and role from the texture's name), with its mips.
void printMemory(const world::ProcessedTextures& textures) {
    const bake::TextureStageReport report = bake::textureStageReport(textures);
    struct Kind {
        size_t count = 0;
        uint64_t bytes = 0;
        double texels = 0.0;
    };
    std::map<std::string, Kind> kinds;
    for (const bake::ProcessedTextureRow& row : report.textures) {
        Kind& k = kinds[bake::texelFormatName(row.format)];
        ++k.count;
        k.bytes += row.bytes;
        k.texels += double(row.width) * double(row.height);
    }
    for (const auto& [format, k] : kinds)
        std::printf(
            "    %-11s %4zu textures, %8.2f MiB with every mip, %.3f bytes per level-0 texel\n",
            format.c_str(), k.count, double(k.bytes) / 1048576.0,
            k.texels > 0.0 ? double(k.bytes) / k.texels : 0.0);
    const bake::ProcessedTextureRow* largest = nullptr;
    for (const bake::ProcessedTextureRow& row : report.textures)
        if (!largest || row.bytes > largest->bytes) largest = &row;
    if (largest)
        std::printf("    largest: %s, %s %ux%u, %u mips, %.2f MiB\n", largest->name.c_str(),
                    bake::texelFormatName(largest->format), largest->width, largest->height,
                    largest->mipCount, double(largest->bytes) / 1048576.0);
    std::printf("    total: %.2f MiB\n", double(report.totalBytes) / 1048576.0);
}

void benchLevel(const std::string& spec) {
    const world::SourceLevel level = world::importLevel(spec);
    std::printf("\n%s: %zu images, %zu materials\n", spec.c_str(), level.images.size(),
                level.materials.size());
    world::ProcessedTextures last = bake::processLevelTextures(level, level.glossMips);  // warm-up
    for (const Method& m : kMethods) {
        const auto start = std::chrono::steady_clock::now();
        const world::ProcessedTextures out = bake::processLevelTextures(level, m.method);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double mt = megatexels(out);
        std::printf(
            "  %-9s %7.3f s for %6.2f megatexels of level 0 (%zu textures): %7.1f ms per "
            "megatexel\n",
            m.name, seconds, mt, out.textures.size(), mt > 0.0 ? 1e3 * seconds / mt : 0.0);
        if (m.method == level.glossMips) last = out;
    }
    std::printf("  memory (the level's method, %s):\n", kMethods[size_t(level.glossMips)].name);
    printMemory(last);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> levels(argv + 1, argv + argc);
    if (levels.empty()) {
        const std::filesystem::path sample = std::filesystem::path(ONELIGHT_SHARED_ASSETS) /
                                             "NormalTangentTest/glTF/NormalTangentTest.gltf";
        if (std::filesystem::exists(sample)) levels.push_back(sample.lexically_normal());
        if (std::filesystem::exists("/usr/share/games/openarena/baseoa"))
            levels.insert(levels.end(), {"aggressor", "kaos"});
    }
    if (levels.empty()) {
        std::fprintf(stderr,
                     "onelight-bench-textures: no level given and none of the default ones "
                     "found (usage: onelight-bench-textures [LEVEL ...])\n");
        return 2;
    }
    std::printf("onelight-bench-textures: the texture stage per level and method, %u threads\n",
                std::max(1u, std::thread::hardware_concurrency()));
    try {
        for (const std::string& level : levels) benchLevel(level);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "onelight-bench-textures: %s\n", e.what());
        return 1;
    }
    return 0;
}
