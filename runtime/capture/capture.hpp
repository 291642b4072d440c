// A frame's capture files, written from what the renderer read back (render::CapturedFrame):
// BASE.png (tonemapped, sRGB), BASE.exr (linear RGBA float, cd/m^2 before exposure) and BASE.json
// (the sidecar). The image files themselves are world's (world/images/image_files.hpp).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "render/renderer.hpp"

namespace onelight::capture {

/// Writes BASE.png, BASE.exr and BASE.json (pretty-printed `sidecar` with "radiance" added:
/// frameRadiance), each whole (world::writeFileAtomically), making BASE's folder when it is
/// missing. Throws world::Error naming the file.
/// The frame's mean linear radiance before exposure: {"mean_rgb": [r, g, b] cd/m^2,
/// "mean_luminance": Rec. 709 Y cd/m^2} over every pixel, non-finite pixels counted as 0 (the
/// measure of a frame's light level that a tonemapped PNG's mean is not: the tonemap compresses).
[[nodiscard]] nlohmann::json frameRadiance(const render::CapturedFrame& frame);

void writeCaptureFiles(const std::string& base, const render::CapturedFrame& frame,
                       const nlohmann::json& sidecar);

}  // namespace onelight::capture
