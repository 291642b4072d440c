// Whole-frame error of a real-time frame against a path-traced reference, both linear radiance
// in cd/m^2 before exposure (the capture's EXR and onelight-bake reference's), so no exposure
// enters the comparison.
#pragma once

#include <cstdint>
#include <vector>

#include "world/images/image_files.hpp"

namespace onelight::lab {

constexpr uint32_t kErrorBlock = 8;  // pixels per side of an error block
// A block's error is |L - L_ref| / max(L_ref, kErrorFloor x the reference's mean luminance):
// the floor keeps near-black blocks from dividing by almost nothing.
constexpr double kErrorFloor = 0.05;

struct BlockErrors {
    uint32_t columns = 0, rows = 0;  // blocks across and down (partial edge blocks dropped)
    std::vector<double> relative;    // per block, row by row
    double mean = 0.0;               // the mean of `relative`
    double level = 1.0;  // the frame's mean luminance over the reference's (1 when both are 0)
    // The median over blocks of a block's luminance over the reference's, each at least the
    // floor of `relative` (two dark blocks are level): the level of a typical surface, which a
    // few very bright blocks (a lamp's own pixels) do not move.
    double medianLevel = 1.0;
};

// The relative error of each 8x8 block's mean luminance. Throws std::invalid_argument when the
// sizes differ or the image is smaller than one block; non-finite pixels count as 0.
[[nodiscard]] BlockErrors blockErrors(const world::FloatImage& frame,
                                      const world::FloatImage& reference);

constexpr double kHeatFullScale = 0.5;  // the heat maps' white: a block 50% off

// The block errors as an RGBA8 heat map of the frame's size: 0 black, through red and yellow,
// to white at `fullScale` and above.
[[nodiscard]] std::vector<uint8_t> heatMap(const BlockErrors& e, uint32_t width, uint32_t height,
                                           double fullScale);

}  // namespace onelight::lab
