// A glossy (roughness 0.2), egg-crate bump-mapped floor to the horizon under a sun 8 degrees up,
// ahead of a camera "view" 1.7 m above it: the level of the whole-frame test of normal and gloss
// mips (material_mips_frame_test) and of the material pipeline's frame cost in
// onelight-bench-render.
#pragma once

#include <cstdint>
#include <string>

namespace onelight::test {

inline constexpr uint32_t kBumpTexels = 64;   // the normal map's size
inline constexpr float kTileMetres = 0.5f;    // one repeat of the normal map
inline constexpr float kCameraHeight = 1.7f;  // metres above the floor

/// Writes FOLDER/bumps.png and FOLDER/floor_GLOSSMIPS.gltf (its mips made by `glossMips`: blit,
/// black_ops or wwii) with a camera of aspect `aspect`; returns the glTF's path.
[[nodiscard]] std::string writeBumpyGlossyFloor(const std::string& folder, const char* glossMips,
                                                float aspect);

}  // namespace onelight::test
