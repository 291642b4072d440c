// Frame capture files: a tonemapped PNG, a linear HDR EXR (float, cd/m^2 before exposure) and a
// JSON sidecar. Each file is written to a temporary name and renamed when complete.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "world/images/image_decode.hpp"

namespace onelight::capture {

/// A float RGBA image, top row first.
struct FloatImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;  // width * height * 4
};

// Every function throws world::Error naming the file.

/// 8-bit RGBA, top row first.
void writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba8);

/// 32-bit float RGBA, top row first, ZIP-compressed.
void writeExr(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<float>& rgba);

/// Linear float RGB, top row first, as a Radiance .hdr (RGBE, run-length encoded).
void writeHdr(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<float>& rgb);

/// Reads an EXR back as float RGBA (tests).
[[nodiscard]] FloatImage readExr(const std::string& path);

/// Reads a PNG as 8-bit RGBA (tests).
[[nodiscard]] world::DecodedImage readPng(const std::string& path);

/// Pretty-printed JSON.
void writeJson(const std::string& path, const nlohmann::json& value);

}  // namespace onelight::capture
