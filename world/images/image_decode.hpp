// Encoded images (PNG, JPEG, TGA for Quake 3 textures; Radiance HDR for skies) decoded to pixels
// with stb_image: the one decoder of the runtime (its material textures) and the baker (the same
// textures at ray hits).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "world/images/image_budget.hpp"

namespace onelight::world {

/// An image decoded to 8-bit RGBA, rows top to bottom.
struct DecodedImage {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;  // width * height * 4 bytes
};

/// An image decoded to linear float RGB, rows top to bottom (an HDR sky).
struct HdrImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgb;  // width * height * 3
};

/// The largest encoded image (file or embedded bytes) decoded.
inline constexpr size_t kMaxEncodedImageBytes = size_t(1) << 30;

/// The largest width or height a decoded image may have (texels).
inline constexpr uint32_t kMaxImageExtent = 16384;

/// Decodes PNG, JPEG or TGA bytes. Throws world::Error, its message starting with `where` (the
/// file). With a `budget`, the image is charged to it from its header before it is decoded.
[[nodiscard]] DecodedImage decodeImage(const uint8_t* bytes, size_t size, const std::string& where,
                                       ImageMemoryBudget* budget = nullptr);

/// Reads and decodes the image file at `path` (PNG/JPEG). Throws world::Error naming it.
[[nodiscard]] DecodedImage readImageFile(const std::string& path,
                                         ImageMemoryBudget* budget = nullptr);

/// Decodes Radiance .hdr bytes as linear RGB (NaN, Inf and negatives to 0). Throws world::Error,
/// its message starting with `where`. A `budget` is charged as decodeImage's is.
[[nodiscard]] HdrImage decodeHdrImage(const uint8_t* bytes, size_t size, const std::string& where,
                                      ImageMemoryBudget* budget = nullptr);

/// Reads a Radiance .hdr file as linear RGB. Throws world::Error naming it.
[[nodiscard]] HdrImage readHdrFile(const std::string& path, ImageMemoryBudget* budget = nullptr);

}  // namespace onelight::world
