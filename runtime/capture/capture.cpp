#include "capture/capture.hpp"

#include "world/file_write.hpp"
#include "world/images/image_files.hpp"

namespace onelight::capture {

void writeCaptureFiles(const std::string& base, const render::CapturedFrame& frame,
                       const nlohmann::json& sidecar) {
    world::writePngFile(base + ".png", frame.width, frame.height, frame.rgba8);
    world::writeExrFile(base + ".exr", frame.width, frame.height, frame.linearRgba);
    world::writeFileAtomically(base + ".json", sidecar.dump(2) + "\n");
}

}  // namespace onelight::capture
