// A linear EXR (cd/m^2) as the player sees it: the renderer's exposure at one EV100 and its
// filmic curve (shaders/tonemap.glsl), as 8-bit RGBA; for contact sheets.
#pragma once

#include <cstdint>
#include <vector>

#include "world/images/image_files.hpp"

namespace onelight::lab {

[[nodiscard]] std::vector<uint8_t> displayRgba8(const world::FloatImage& image, float ev100);

// Copies `tile` (tileWidth wide) into `sheet` (sheetWidth wide, RGBA8) at (x, y).
void placeTile(std::vector<uint8_t>& sheet, uint32_t sheetWidth, const std::vector<uint8_t>& tile,
               uint32_t tileWidth, uint32_t x, uint32_t y);

}  // namespace onelight::lab
