#include "block_error.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace onelight::lab {

namespace {

// Rec. 709 luminance (shaders/common.glsl luminance), in double precision for the sums.
double luminanceAt(const world::FloatImage& f, size_t pixel) {
    double rgb[3];
    for (int c = 0; c < 3; ++c) {
        const float v = f.rgba[pixel * 4 + size_t(c)];
        rgb[c] = std::isfinite(v) ? double(v) : 0.0;
    }
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

}  // namespace

BlockErrors blockErrors(const world::FloatImage& frame, const world::FloatImage& reference) {
    if (frame.width != reference.width || frame.height != reference.height)
        throw std::invalid_argument("frame " + std::to_string(frame.width) + "x" +
                                    std::to_string(frame.height) + "; expected the reference's " +
                                    std::to_string(reference.width) + "x" +
                                    std::to_string(reference.height));
    BlockErrors e;
    e.columns = frame.width / kErrorBlock;
    e.rows = frame.height / kErrorBlock;
    if (e.columns == 0 || e.rows == 0)
        throw std::invalid_argument("a frame of " + std::to_string(frame.width) + "x" +
                                    std::to_string(frame.height) + " holds no 8x8 block");
    std::vector<double> mine(size_t(e.columns) * e.rows), theirs(mine.size());
    double sumRef = 0.0, sumMine = 0.0;
    for (uint32_t by = 0; by < e.rows; ++by)
        for (uint32_t bx = 0; bx < e.columns; ++bx) {
            double a = 0.0, b = 0.0;
            for (uint32_t y = by * kErrorBlock; y < (by + 1) * kErrorBlock; ++y)
                for (uint32_t x = bx * kErrorBlock; x < (bx + 1) * kErrorBlock; ++x) {
                    const size_t p = size_t(y) * frame.width + x;
                    a += luminanceAt(frame, p);
                    b += luminanceAt(reference, p);
                }
            const size_t i = size_t(by) * e.columns + bx;
            mine[i] = a / double(kErrorBlock * kErrorBlock);
            theirs[i] = b / double(kErrorBlock * kErrorBlock);
            sumRef += theirs[i];
            sumMine += mine[i];
        }
    const double floor = std::max(kErrorFloor * sumRef / double(mine.size()), 1e-6);
    double sum = 0.0;
    for (size_t i = 0; i < mine.size(); ++i) {
        e.relative.push_back(std::fabs(mine[i] - theirs[i]) / std::max(theirs[i], floor));
        sum += e.relative.back();
    }
    e.mean = sum / double(e.relative.size());
    std::vector<double> ratios;
    for (size_t i = 0; i < mine.size(); ++i)
        ratios.push_back(std::max(mine[i], floor) / std::max(theirs[i], floor));
    const size_t half = ratios.size() / 2;
    std::nth_element(ratios.begin(), ratios.begin() + long(half), ratios.end());
    e.medianLevel = ratios[half];
    if (ratios.size() % 2 == 0)  // the mean of the two middle values
        e.medianLevel =
            0.5 * (e.medianLevel + *std::max_element(ratios.begin(), ratios.begin() + long(half)));
    // A black reference: the level against the error floor's least value, finite.
    e.level = sumMine == sumRef ? 1.0 : sumMine / std::max(sumRef, 1e-6 * double(mine.size()));
    return e;
}

std::vector<uint8_t> heatMap(const BlockErrors& e, uint32_t width, uint32_t height,
                             double fullScale) {
    std::vector<uint8_t> rgba(size_t(width) * height * 4, 0);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const uint32_t bx = std::min(x / kErrorBlock, e.columns - 1);
            const uint32_t by = std::min(y / kErrorBlock, e.rows - 1);
            const double t =
                std::clamp(e.relative[size_t(by) * e.columns + bx] / fullScale, 0.0, 1.0);
            // black -> red (1/3) -> yellow (2/3) -> white (1)
            const double r = std::clamp(3.0 * t, 0.0, 1.0);
            const double g = std::clamp(3.0 * t - 1.0, 0.0, 1.0);
            const double b = std::clamp(3.0 * t - 2.0, 0.0, 1.0);
            uint8_t* px = &rgba[(size_t(y) * width + x) * 4];
            px[0] = uint8_t(r * 255.0 + 0.5);
            px[1] = uint8_t(g * 255.0 + 0.5);
            px[2] = uint8_t(b * 255.0 + 0.5);
            px[3] = 255;
        }
    return rgba;
}

}  // namespace onelight::lab
