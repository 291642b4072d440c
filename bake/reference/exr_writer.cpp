// EXR output through tinyexr (linear float32 RGB), written atomically.
#include <cstdio>
#include <filesystem>

#include <tinyexr.h>

#include "bake/reference/path_tracer.hpp"

namespace onelight::bake {

std::string write_exr(const std::string& path, const ReferenceImage& image) {
    const std::string temporary = path + ".tmp";
    const char* error = nullptr;
    const int status = SaveEXR(image.rgb.data(), static_cast<int>(image.width),
                               static_cast<int>(image.height), 3, 0, temporary.c_str(), &error);
    if (status != TINYEXR_SUCCESS) {
        std::string message = path + ": cannot write EXR (" + (error ? error : "unknown") + ")";
        if (error) FreeEXRErrorMessage(error);
        std::remove(temporary.c_str());
        return message;
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) return path + ": cannot rename " + temporary + " (" + ec.message() + ")";
    return "";
}

}  // namespace onelight::bake
