#include "world/images/image_decode.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "world/error.hpp"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_HDR
#define STBI_ONLY_TGA  // Quake 3 textures
#define STBI_FAILURE_USERMSG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_image.h>
#pragma GCC diagnostic pop

#include "world/file_read.hpp"

namespace onelight::world {

namespace {

void checkExtent(int width, int height, const std::string& where) {
    if (width <= 0 || height <= 0 || uint32_t(width) > kMaxImageExtent ||
        uint32_t(height) > kMaxImageExtent)
        throw Error(where + ": image of " + std::to_string(width) + "x" + std::to_string(height) +
                    "; expected 1.." + std::to_string(kMaxImageExtent) + " texels a side");
}

}  // namespace

DecodedImage decodeImage(const uint8_t* bytes, size_t size, const std::string& where,
                         ImageMemoryBudget* budget) {
    if (size == 0 || size > kMaxEncodedImageBytes)
        throw Error(where + ": " + std::to_string(size) + " bytes of image data; expected 1.." +
                    std::to_string(kMaxEncodedImageBytes));
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, int(size), &width, &height, &channels))
        throw Error(where + ": not a decodable PNG, JPEG or TGA image (" + stbi_failure_reason() +
                    ")");
    checkExtent(width, height, where);
    if (budget) chargeImage(*budget, uint32_t(width), uint32_t(height), where);
    stbi_uc* pixels = stbi_load_from_memory(bytes, int(size), &width, &height, &channels, 4);
    if (!pixels)
        throw Error(where + ": not a decodable PNG, JPEG or TGA image (" + stbi_failure_reason() +
                    ")");
    DecodedImage out;
    out.width = uint32_t(width);
    out.height = uint32_t(height);
    out.rgba.assign(pixels, pixels + size_t(width) * size_t(height) * 4);
    stbi_image_free(pixels);
    return out;
}

DecodedImage readImageFile(const std::string& path, ImageMemoryBudget* budget) {
    const std::vector<uint8_t> bytes =
        readRegularFile(path, "a PNG or JPEG file", kMaxEncodedImageBytes);
    return decodeImage(bytes.data(), bytes.size(), path, budget);
}

HdrImage readHdrFile(const std::string& path, ImageMemoryBudget* budget) {
    const std::vector<uint8_t> bytes =
        readRegularFile(path, "a Radiance .hdr image", kMaxEncodedImageBytes);
    return decodeHdrImage(bytes.data(), bytes.size(), path, budget);
}

HdrImage decodeHdrImage(const uint8_t* bytes, size_t size, const std::string& where,
                        ImageMemoryBudget* budget) {
    int width = 0, height = 0, channels = 0;
    if (size == 0 || size > kMaxEncodedImageBytes ||
        !stbi_info_from_memory(bytes, int(size), &width, &height, &channels))
        throw Error(where + ": not a decodable .hdr image (" + stbi_failure_reason() + ")");
    checkExtent(width, height, where);
    if (budget) chargeImage(*budget, uint32_t(width), uint32_t(height), where);
    float* pixels = stbi_loadf_from_memory(bytes, int(size), &width, &height, &channels, 3);
    if (!pixels)
        throw Error(where + ": not a decodable .hdr image (" + stbi_failure_reason() + ")");
    HdrImage out;
    out.width = uint32_t(width);
    out.height = uint32_t(height);
    out.rgb.assign(pixels, pixels + size_t(width) * size_t(height) * 3);
    stbi_image_free(pixels);
    for (float& v : out.rgb)
        if (!(v >= 0.0f) || !std::isfinite(v)) v = 0.0f;  // no NaN or Inf reaches a texel
    return out;
}

}  // namespace onelight::world
