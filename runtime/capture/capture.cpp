#include "capture/capture.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <tinyexr.h>

// Internal to this file (static), so a program may link another user of stb_image_write.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

#include "world/error.hpp"

namespace onelight::capture {

namespace {

std::string temporaryName(const std::string& path) {
    return path + ".tmp";
}

void commit(const std::string& path) {
    std::error_code ec;
    std::filesystem::rename(temporaryName(path), path, ec);
    if (ec) {
        const std::string why = ec.message();
        std::filesystem::remove(temporaryName(path), ec);
        throw world::Error(path + ": cannot rename the finished file into place (" + why + ")");
    }
}

}  // namespace

void writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba8) {
    if (rgba8.size() != size_t(width) * height * 4)
        throw world::Error(path + ": the image has " + std::to_string(rgba8.size()) +
                           " bytes, expected " + std::to_string(size_t(width) * height * 4));
    if (!stbi_write_png(temporaryName(path).c_str(), int(width), int(height), 4, rgba8.data(),
                        int(width * 4)))
        throw world::Error(path + ": cannot write the PNG");
    commit(path);
}

void writeHdr(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<float>& rgb) {
    if (rgb.size() != size_t(width) * height * 3)
        throw world::Error(path + ": the image has " + std::to_string(rgb.size()) +
                           " floats, expected " + std::to_string(size_t(width) * height * 3));
    if (!stbi_write_hdr(temporaryName(path).c_str(), int(width), int(height), 3, rgb.data()))
        throw world::Error(path + ": cannot write the .hdr");
    commit(path);
}

void writeExr(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<float>& rgba) {
    if (rgba.size() != size_t(width) * height * 4)
        throw world::Error(path + ": the image has " + std::to_string(rgba.size()) +
                           " floats, expected " + std::to_string(size_t(width) * height * 4));
    const char* message = nullptr;
    const std::string tmp = temporaryName(path);
    if (SaveEXR(rgba.data(), int(width), int(height), 4, 0, tmp.c_str(), &message) < 0) {
        const std::string why = message ? message : "unknown error";
        if (message) FreeEXRErrorMessage(message);
        throw world::Error(path + ": cannot write the EXR (" + why + ")");
    }
    commit(path);
}

FloatImage readExr(const std::string& path) {
    float* data = nullptr;
    int w = 0, h = 0;
    const char* message = nullptr;
    if (LoadEXR(&data, &w, &h, path.c_str(), &message) < 0) {
        const std::string why = message ? message : "unknown error";
        if (message) FreeEXRErrorMessage(message);
        throw world::Error(path + ": cannot read the EXR (" + why + ")");
    }
    FloatImage image;
    image.width = uint32_t(w);
    image.height = uint32_t(h);
    image.rgba.assign(data, data + size_t(w) * size_t(h) * 4);
    std::free(data);
    return image;
}

world::DecodedImage readPng(const std::string& path) {
    return world::readImageFile(path);
}

void writeJson(const std::string& path, const nlohmann::json& value) {
    {
        std::ofstream out(temporaryName(path), std::ios::binary | std::ios::trunc);
        out << value.dump(2) << '\n';
        if (!out) throw world::Error(path + ": cannot write the JSON");
    }
    commit(path);
}

}  // namespace onelight::capture
