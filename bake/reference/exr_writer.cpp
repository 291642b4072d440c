// EXR output through tinyexr (linear float32 RGB), written atomically.
#include <cstdio>
#include <filesystem>

#include <tinyexr.h>

#include "bake/reference/path_tracer.hpp"
#include "world/error.hpp"

namespace onelight::bake {

void writeExr(const std::string& path, const ReferenceImage& image) {
    const std::string temporary = path + ".tmp";
    const char* error = nullptr;
    const int status = SaveEXR(image.rgb.data(), static_cast<int>(image.width),
                               static_cast<int>(image.height), 3, 0, temporary.c_str(), &error);
    if (status != TINYEXR_SUCCESS) {
        const std::string message =
            path + ": cannot write EXR (" + (error ? error : "unknown") + ")";
        if (error) FreeEXRErrorMessage(error);
        std::remove(temporary.c_str());
        throw world::Error(message);
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) throw world::Error(path + ": cannot rename " + temporary + " (" + ec.message() + ")");
}

}  // namespace onelight::bake
