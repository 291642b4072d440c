// The split-sum table of shaders/lighting.glsl ("The split-sum table") for C++: the numbers the
// runtime uploads as its texture, and the bilinear, clamp-to-edge lookup its sampler performs,
// so that the baker, the reference and the lab weight the diffuse exactly as a pixel does.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

namespace onelight::glsl {

inline constexpr uint32_t kEnvBrdfTableSize = 32;  // ENV_BRDF_TABLE_SIZE of lighting.glsl

/// (scale, bias) pairs, row j (gloss = j / 31) after row, column i at sqrt(NoV) = i / 31.
inline constexpr float kEnvBrdfTable[2 * kEnvBrdfTableSize * kEnvBrdfTableSize] = {
#include "env_brdf_table.inc"
};

/// The table at texture coordinates `uv` (envBrdfTableCoord), as a bilinear sampler with clamp
/// to edge reads it.
[[nodiscard]] inline glm::vec2 sampleEnvBrdfTable(glm::vec2 uv) {
    const float n = float(kEnvBrdfTableSize);
    const float fx = std::clamp(uv.x * n - 0.5f, 0.0f, n - 1.0f);
    const float fy = std::clamp(uv.y * n - 0.5f, 0.0f, n - 1.0f);
    const uint32_t x0 = std::min(uint32_t(fx), kEnvBrdfTableSize - 2);
    const uint32_t y0 = std::min(uint32_t(fy), kEnvBrdfTableSize - 2);
    const float tx = fx - float(x0), ty = fy - float(y0);
    const auto at = [](uint32_t x, uint32_t y) {
        const uint32_t i = 2 * (y * kEnvBrdfTableSize + x);
        return glm::vec2(kEnvBrdfTable[i], kEnvBrdfTable[i + 1]);
    };
    const glm::vec2 top = at(x0, y0) * (1.0f - tx) + at(x0 + 1, y0) * tx;
    const glm::vec2 bottom = at(x0, y0 + 1) * (1.0f - tx) + at(x0 + 1, y0 + 1) * tx;
    return top * (1.0f - ty) + bottom * ty;
}

}  // namespace onelight::glsl
