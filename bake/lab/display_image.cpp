#include "display_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "shading.hpp"

namespace onelight::lab {

std::vector<uint8_t> displayRgba8(const world::FloatImage& image, float ev100) {
    const float exposure = glsl::exposure_fromEV100(ev100);
    std::vector<uint8_t> rgba(size_t(image.width) * image.height * 4, 255);
    for (size_t p = 0; p < size_t(image.width) * image.height; ++p)
        for (size_t c = 0; c < 3; ++c) {
            const float v = image.rgba[p * 4 + c];
            const float d = glsl::displayValue(std::isfinite(v) ? v * exposure : 0.0f);
            rgba[p * 4 + c] = uint8_t(std::clamp(d * 255.0f + 0.5f, 0.0f, 255.0f));
        }
    return rgba;
}

void placeTile(std::vector<uint8_t>& sheet, uint32_t sheetWidth, const std::vector<uint8_t>& tile,
               uint32_t tileWidth, uint32_t x, uint32_t y) {
    const size_t rows = tile.size() / (size_t(tileWidth) * 4);
    for (size_t row = 0; row < rows; ++row)
        std::memcpy(&sheet[((y + row) * sheetWidth + x) * 4], &tile[row * tileWidth * 4],
                    size_t(tileWidth) * 4);
}

}  // namespace onelight::lab
