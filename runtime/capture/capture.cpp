#include "capture/capture.hpp"

#include <algorithm>
#include <cmath>

#include "world/file_write.hpp"
#include "world/images/image_files.hpp"

namespace onelight::capture {

nlohmann::json frameRadiance(const render::CapturedFrame& frame) {
    double sum[3] = {0.0, 0.0, 0.0};
    const size_t pixels = frame.linearRgba.size() / 4;
    for (size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c) {
            const double v = frame.linearRgba[i * 4 + c];
            if (std::isfinite(v)) sum[c] += v;
        }
    const double n = double(std::max<size_t>(pixels, 1));
    const double r = sum[0] / n, g = sum[1] / n, b = sum[2] / n;
    return {{"mean_rgb", {r, g, b}}, {"mean_luminance", 0.2126 * r + 0.7152 * g + 0.0722 * b}};
}

void writeCaptureFiles(const std::string& base, const render::CapturedFrame& frame,
                       const nlohmann::json& sidecar) {
    world::writePngFile(base + ".png", frame.width, frame.height, frame.rgba8);
    world::writeExrFile(base + ".exr", frame.width, frame.height, frame.linearRgba);
    nlohmann::json withRadiance = sidecar;
    withRadiance["radiance"] = frameRadiance(frame);
    world::writeFileAtomically(base + ".json", withRadiance.dump(2) + "\n");
}

}  // namespace onelight::capture
