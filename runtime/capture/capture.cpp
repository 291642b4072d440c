#include "capture/capture.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <tinyexr.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

#include "assets/level_assets.hpp"

namespace onelight::capture {

namespace {

std::string temporaryName(const std::string& path) {
    return path + ".tmp";
}

bool commit(const std::string& path, std::string& error) {
    std::error_code ec;
    std::filesystem::rename(temporaryName(path), path, ec);
    if (ec) {
        error = path + ": cannot rename the finished file into place (" + ec.message() + ")";
        std::filesystem::remove(temporaryName(path), ec);
        return false;
    }
    return true;
}

}  // namespace

bool writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba8, std::string& error) {
    if (rgba8.size() != size_t(width) * height * 4) {
        error = path + ": the image has " + std::to_string(rgba8.size()) + " bytes, expected " +
                std::to_string(size_t(width) * height * 4);
        return false;
    }
    if (!stbi_write_png(temporaryName(path).c_str(), int(width), int(height), 4, rgba8.data(),
                        int(width * 4))) {
        error = path + ": cannot write the PNG";
        return false;
    }
    return commit(path, error);
}

bool writeExr(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<float>& rgba, std::string& error) {
    if (rgba.size() != size_t(width) * height * 4) {
        error = path + ": the image has " + std::to_string(rgba.size()) + " floats, expected " +
                std::to_string(size_t(width) * height * 4);
        return false;
    }
    const char* message = nullptr;
    const std::string tmp = temporaryName(path);
    if (SaveEXR(rgba.data(), int(width), int(height), 4, 0, tmp.c_str(), &message) < 0) {
        error = path + ": cannot write the EXR (" + (message ? message : "unknown error") + ")";
        if (message) FreeEXRErrorMessage(message);
        return false;
    }
    return commit(path, error);
}

bool readExr(const std::string& path, uint32_t& width, uint32_t& height, std::vector<float>& rgba,
             std::string& error) {
    float* data = nullptr;
    int w = 0, h = 0;
    const char* message = nullptr;
    if (LoadEXR(&data, &w, &h, path.c_str(), &message) < 0) {
        error = path + ": cannot read the EXR (" + (message ? message : "unknown error") + ")";
        if (message) FreeEXRErrorMessage(message);
        return false;
    }
    width = uint32_t(w);
    height = uint32_t(h);
    rgba.assign(data, data + size_t(w) * size_t(h) * 4);
    std::free(data);
    return true;
}

bool readPng(const std::string& path, uint32_t& width, uint32_t& height,
             std::vector<uint8_t>& rgba8, std::string& error) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = path + ": cannot open";
        return false;
    }
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    assets::DecodedImage image;
    if (!assets::decodeImage(bytes.data(), bytes.size(), image, error)) {
        error = path + ": " + error;
        return false;
    }
    width = image.width;
    height = image.height;
    rgba8 = std::move(image.rgba);
    return true;
}

bool writeJson(const std::string& path, const nlohmann::json& value, std::string& error) {
    {
        std::ofstream out(temporaryName(path), std::ios::binary | std::ios::trunc);
        out << value.dump(2) << '\n';
        if (!out) {
            error = path + ": cannot write the JSON";
            return false;
        }
    }
    return commit(path, error);
}

}  // namespace onelight::capture
