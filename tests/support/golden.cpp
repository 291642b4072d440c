#include "golden.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "world/images/image_decode.hpp"
#include "world/images/image_files.hpp"

namespace onelight::test {

namespace {
constexpr int kPixelTolerance = 8;  // codes of 255
constexpr double kMaxDifferingFraction = 0.005;
constexpr double kMaxMeanDifference = 0.5;  // codes of 255
}  // namespace

GoldenResult compareWithGolden(const std::vector<uint8_t>& rgba8, uint32_t width, uint32_t height,
                               const std::string& goldenPath, const std::string& diffPath) {
    const char* update = std::getenv("ONELIGHT_UPDATE_GOLDENS");
    if (update && std::strcmp(update, "1") == 0) {
        std::filesystem::create_directories(std::filesystem::path(goldenPath).parent_path());
        world::writePngFile(goldenPath, width, height, rgba8);
        std::printf("[ golden ] updated %s\n", goldenPath.c_str());
        return {true, "updated"};
    }
    if (!std::filesystem::exists(goldenPath))
        return {false,
                goldenPath + ": no golden (run with ONELIGHT_UPDATE_GOLDENS=1 to create it)"};
    const world::DecodedImage golden = world::readImageFile(goldenPath);
    const uint32_t w = golden.width, h = golden.height;
    const std::vector<uint8_t>& expected = golden.rgba;
    if (w != width || h != height)
        return {false, goldenPath + ": golden is " + std::to_string(w) + "x" + std::to_string(h) +
                           ", frame is " + std::to_string(width) + "x" + std::to_string(height)};
    std::vector<uint8_t> diff(expected.size(), 255);
    uint64_t differing = 0;
    double sum = 0.0;
    int worst = 0;
    const size_t pixels = size_t(w) * h;
    for (size_t p = 0; p < pixels; ++p) {
        int pixelWorst = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(rgba8[4 * p + c]) - int(expected[4 * p + c]));
            sum += d;
            pixelWorst = std::max(pixelWorst, d);
            diff[4 * p + c] = uint8_t(std::min(d * 8, 255));
        }
        worst = std::max(worst, pixelWorst);
        if (pixelWorst > kPixelTolerance) ++differing;
    }
    const double fraction = double(differing) / double(pixels);
    const double mean = sum / double(pixels * 3);
    char buffer[512];
    std::snprintf(buffer, sizeof buffer,
                  "%s: %.3f%% pixels over %d/255 (max %.1f%%), mean |diff| %.3f/255 (max %.1f), "
                  "worst %d",
                  goldenPath.c_str(), 100.0 * fraction, kPixelTolerance,
                  100.0 * kMaxDifferingFraction, mean, kMaxMeanDifference, worst);
    std::printf("[ golden ] %s\n", buffer);
    const bool ok = fraction <= kMaxDifferingFraction && mean <= kMaxMeanDifference;
    if (!ok) {
        world::writePngFile(diffPath, w, h, diff);
        return {false, std::string(buffer) + "; see " + diffPath};
    }
    return {true, buffer};
}

}  // namespace onelight::test
