// onelight-lab sheet: linear EXRs in cd/m^2 (a reference's, a capture's) side by side as one PNG,
// each through the renderer's exposure and filmic curve (shaders/tonemap.glsl) at one EV100, so
// a path-traced reference and a real-time frame are looked at alike. With --columns, a grid of
// rows, each at its own EV100 when one is given per row. With a rectangle, each
// image's mean radiance over it and its ratio to the first image's.
#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "shading.hpp"
#include "world/images/image_files.hpp"

namespace onelight::lab {

int sheet(const std::string& output, const std::vector<float>& ev100,
          const std::vector<std::string>& images, const std::vector<uint32_t>& rect,
          uint32_t columns) {
    if (images.empty()) throw std::invalid_argument("--images: expected one EXR or more");
    const uint32_t across = columns == 0 ? uint32_t(images.size()) : columns;
    const uint32_t rows = (uint32_t(images.size()) + across - 1) / across;
    if (ev100.size() != 1 && ev100.size() != rows)
        throw std::invalid_argument("--ev100: " + std::to_string(ev100.size()) +
                                    " values; expected one, or one per row (" +
                                    std::to_string(rows) + ")");
    if (!rect.empty() && rect.size() != 4)
        throw std::invalid_argument("--rect: expected x,y,width,height");
    std::vector<world::FloatImage> read;
    for (const std::string& path : images) {
        read.push_back(world::readExrFile(path));
        const world::FloatImage& f = read.back();
        if (f.width != read[0].width || f.height != read[0].height)
            throw std::invalid_argument(path + ": " + std::to_string(f.width) + "x" +
                                        std::to_string(f.height) + "; expected the first image's " +
                                        std::to_string(read[0].width) + "x" +
                                        std::to_string(read[0].height));
        if (!rect.empty() && (rect[2] == 0 || rect[3] == 0 || rect[0] + rect[2] > f.width ||
                              rect[1] + rect[3] > f.height))
            throw std::invalid_argument("--rect: outside the " + std::to_string(f.width) + "x" +
                                        std::to_string(f.height) + " images");
    }
    const uint32_t w = read[0].width, h = read[0].height, n = uint32_t(read.size());
    const size_t stride = size_t(w) * across;  // pixels per row of the sheet
    std::vector<uint8_t> rgba(stride * rows * h * 4, 255);
    double first = 0.0;
    for (uint32_t k = 0; k < n; ++k) {
        const std::vector<float>& px = read[k].rgba;
        const uint32_t row = k / across, column = k % across;
        const float exposure = glsl::exposure_fromEV100(ev100[ev100.size() == 1 ? 0 : row]);
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                for (uint32_t c = 0; c < 3; ++c) {
                    const float v = px[(size_t(y) * w + x) * 4 + c];
                    const float d = glsl::displayValue(std::isfinite(v) ? v * exposure : 0.0f);
                    rgba[((size_t(row) * h + y) * stride + size_t(column) * w + x) * 4 + c] =
                        uint8_t(std::clamp(d * 255.0f + 0.5f, 0.0f, 255.0f));
                }
        if (rect.empty()) continue;
        glm::dvec3 sum(0.0);
        for (uint32_t y = rect[1]; y < rect[1] + rect[3]; ++y)
            for (uint32_t x = rect[0]; x < rect[0] + rect[2]; ++x)
                for (int c = 0; c < 3; ++c) sum[c] += double(px[(size_t(y) * w + x) * 4 + c]);
        const glm::dvec3 mean = sum / double(rect[2] * rect[3]);
        const double y = double(glsl::luminance(glm::vec3(mean)));
        if (k == 0) first = y;
        std::printf(
            "%s: mean over the rectangle %.2f %.2f %.2f cd/m^2, luminance %.2f (%.4f of "
            "the first)\n",
            images[k].c_str(), mean.x, mean.y, mean.z, y, first > 0.0 ? y / first : 0.0);
    }
    world::writePngFile(output, uint32_t(stride), rows * h, rgba);
    std::printf("wrote %s: %u images of %ux%u, %u to a row, at EV100 %.2f%s\n", output.c_str(), n,
                w, h, across, double(ev100[0]), ev100.size() > 1 ? " (first row)" : "");
    return 0;
}

}  // namespace onelight::lab
