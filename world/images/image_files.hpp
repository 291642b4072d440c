// Image files written and read whole: PNG (8-bit RGBA, stb_image_write), Radiance .hdr (linear
// RGB, stb_image_write) and OpenEXR (32-bit float, ZIP-compressed, tinyexr), each written through
// world::writeFileAtomically. The game's frame captures, the baker's references, the lab's
// pictures and the tests' fixtures all write here; PNG, JPEG and .hdr files are read by
// image_decode.hpp (readImageFile, readHdrFile), EXRs by readExrFile.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace onelight::world {

/// A float RGBA image, rows top to bottom (an EXR: a frame's or a reference's radiance).
struct FloatImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;  // width * height * 4
};

// Every function throws world::Error naming the file; a writer leaves no file behind on failure.

/// 8-bit RGBA, rows top to bottom (width * height * 4 bytes).
void writePngFile(const std::string& path, uint32_t width, uint32_t height,
                  std::span<const uint8_t> rgba8);

/// Linear float RGB, rows top to bottom, as a Radiance .hdr (RGBE, run-length encoded).
void writeHdrFile(const std::string& path, uint32_t width, uint32_t height,
                  std::span<const float> rgb);

/// 32-bit float RGBA, rows top to bottom, ZIP-compressed.
void writeExrFile(const std::string& path, uint32_t width, uint32_t height,
                  std::span<const float> rgba);

/// 32-bit float RGB (no alpha channel), rows top to bottom, ZIP-compressed.
void writeRgbExrFile(const std::string& path, uint32_t width, uint32_t height,
                     std::span<const float> rgb);

/// Reads an EXR (a regular file of at most kMaxEncodedImageBytes) as float RGBA; a file
/// without alpha reads with alpha 1.
[[nodiscard]] FloatImage readExrFile(const std::string& path);

}  // namespace onelight::world
