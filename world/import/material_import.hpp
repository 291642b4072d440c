// glTF metallic-roughness materials into the engine's albedo, specular colour and gloss
// (formula on world::Material), and the material class that picks the shader permutation.
#pragma once

#include <cstdint>
#include <functional>

#include "world/compiled_level.hpp"

namespace tinygltf {
struct Material;
}

namespace onelight::world {

/// Engine gloss for glTF perceptual roughness r: GGX alpha = r^2 and
/// alpha = sqrt(2 / (1 + 2^(18 g)))  =>  g = log2(2 / r^4 - 1) / 18, clamped to [0, 1].
/// r = 1 gives 0; r <= 0.0935 gives 1.
[[nodiscard]] float glossFromRoughness(float roughness);

/// metal: metallic == 1 without a metallic-roughness texture (no diffuse);
/// lambert: metallic == 0 and roughness == 1 without that texture (diffuse only);
/// dielectric: metallic == 0 (scalar specular 0.04); full: anything else.
[[nodiscard]] MaterialClass classifyMaterial(const Material& material);

/// Converts a glTF material; `useTexture` maps a glTF texture index to the level's index.
[[nodiscard]] Material convertMaterial(const tinygltf::Material& source,
                                       const std::function<uint32_t(int)>& useTexture);

/// The material given to primitives that have none (glTF's default: white, metallic 1,
/// roughness 1).
[[nodiscard]] Material defaultMaterial();

}  // namespace onelight::world
