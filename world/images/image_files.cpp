#include "world/images/image_files.hpp"

#include <cstdlib>

#include <tinyexr.h>

// Internal to this file (static): the project's one user of stb_image_write.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/file_write.hpp"
#include "world/images/image_decode.hpp"

namespace onelight::world {

namespace {

// The widest or tallest image written: far past any frame or sheet, well within stb's int sizes.
constexpr uint32_t kMaxWrittenExtent = 65536;

void checkSize(const std::string& path, uint32_t width, uint32_t height, size_t size,
               uint32_t channels, const char* unit) {
    if (width == 0 || height == 0 || width > kMaxWrittenExtent || height > kMaxWrittenExtent)
        throw Error(path + ": an image of " + std::to_string(width) + "x" + std::to_string(height) +
                    "; expected 1.." + std::to_string(kMaxWrittenExtent) + " pixels a side");
    const size_t expected = size_t(width) * height * channels;
    if (size != expected)
        throw Error(path + ": the image has " + std::to_string(size) + " " + unit + ", expected " +
                    std::to_string(expected));
}

void appendTo(void* context, void* data, int size) {
    auto* bytes = static_cast<std::vector<uint8_t>*>(context);
    const auto* begin = static_cast<const uint8_t*>(data);
    bytes->insert(bytes->end(), begin, begin + size);
}

void writeExr(const std::string& path, uint32_t width, uint32_t height,
              std::span<const float> pixels, uint32_t channels) {
    checkSize(path, width, height, pixels.size(), channels, "floats");
    writeFileAtomicallyWith(path, [&](const std::string& temporary) {
        const char* message = nullptr;
        if (SaveEXR(pixels.data(), int(width), int(height), int(channels), 0, temporary.c_str(),
                    &message) != TINYEXR_SUCCESS) {
            const std::string why = message ? message : "unknown error";
            if (message) FreeEXRErrorMessage(message);
            throw Error(path + ": cannot write the EXR (" + why + ")");
        }
    });
}

}  // namespace

void writePngFile(const std::string& path, uint32_t width, uint32_t height,
                  std::span<const uint8_t> rgba8) {
    checkSize(path, width, height, rgba8.size(), 4, "bytes");
    std::vector<uint8_t> png;
    if (!stbi_write_png_to_func(appendTo, &png, int(width), int(height), 4, rgba8.data(),
                                int(width * 4)))
        throw Error(path + ": cannot encode the PNG");
    writeFileAtomically(path, png);
}

void writeHdrFile(const std::string& path, uint32_t width, uint32_t height,
                  std::span<const float> rgb) {
    checkSize(path, width, height, rgb.size(), 3, "floats");
    std::vector<uint8_t> hdr;
    if (!stbi_write_hdr_to_func(appendTo, &hdr, int(width), int(height), 3, rgb.data()))
        throw Error(path + ": cannot encode the .hdr");
    writeFileAtomically(path, hdr);
}

void writeExrFile(const std::string& path, uint32_t width, uint32_t height,
                  std::span<const float> rgba) {
    writeExr(path, width, height, rgba, 4);
}

void writeRgbExrFile(const std::string& path, uint32_t width, uint32_t height,
                     std::span<const float> rgb) {
    writeExr(path, width, height, rgb, 3);
}

FloatImage readExrFile(const std::string& path) {
    const std::vector<uint8_t> bytes =
        readRegularFile(path, "an OpenEXR image", kMaxEncodedImageBytes);
    float* data = nullptr;
    int w = 0, h = 0;
    const char* message = nullptr;
    if (LoadEXRFromMemory(&data, &w, &h, bytes.data(), bytes.size(), &message) != TINYEXR_SUCCESS) {
        const std::string why = message ? message : "unknown error";
        if (message) FreeEXRErrorMessage(message);
        throw Error(path + ": cannot read the EXR (" + why + ")");
    }
    FloatImage image;
    image.width = uint32_t(w);
    image.height = uint32_t(h);
    image.rgba.assign(data, data + size_t(w) * size_t(h) * 4);
    std::free(data);
    return image;
}

}  // namespace onelight::world
