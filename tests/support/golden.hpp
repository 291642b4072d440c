// Golden-image comparison for frame-capture tests, with one stated tolerance.
//
// Per 8-bit channel, a pixel "differs" when some channel is off by more than 8/255; at most 0.5%
// of pixels may differ, and the mean absolute difference over all channels must stay within
// 0.5/255. Why: a new LLVM (llvmpipe compiles the shaders) or another conformant GPU changes
// float rounding (FMA contraction, transcendental approximations), which moves smooth regions by
// 1-2 codes: far inside 8/255 and far inside the mean bound. Rasterisation and filtering rules
// may flip the coverage of edge pixels and texels: those can differ by much more than 8 codes but
// are few (0.5% of a 320x180 frame is 288 pixels, about the length of the longest silhouettes).
// A real regression (a wrong term, a lost shadow, exposure off by a tenth of a stop) moves most
// pixels by more than a code, which the mean bound catches.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace onelight::test {

struct GoldenResult {
    bool ok = false;
    std::string message;  // what differed, or why it could not compare; names the diff image
};

// Compares an RGBA8 image (top row first) with the PNG at goldenPath. On failure writes
// diffPath (|difference| x 8). With ONELIGHT_UPDATE_GOLDENS=1 it rewrites the golden instead.
GoldenResult compareWithGolden(const std::vector<uint8_t>& rgba8, uint32_t width, uint32_t height,
                               const std::string& goldenPath, const std::string& diffPath);

}  // namespace onelight::test
