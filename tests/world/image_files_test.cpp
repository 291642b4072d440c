// world's image files: PNG, EXR (RGBA and RGB) and .hdr written and read back; a wrong size or
// an unreadable file is a world::Error naming the file, and a refused write leaves no file.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/error_message.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/error.hpp"
#include "world/images/image_decode.hpp"
#include "world/images/image_files.hpp"

namespace onelight::test {
namespace {

namespace fs = std::filesystem;

TEST(ImageFiles, PngRoundTrip) {
    const fs::path folder = freshFolder("image_files_png");
    const uint32_t w = 5, h = 3;
    std::vector<uint8_t> rgba(size_t(w) * h * 4);
    for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = uint8_t(i * 37 + 11);
    const std::string path = (folder / "a.png").string();
    world::writePngFile(path, w, h, rgba);
    const world::DecodedImage read = world::readImageFile(path);
    EXPECT_EQ(read.width, w);
    EXPECT_EQ(read.height, h);
    EXPECT_EQ(read.rgba, rgba);
}

TEST(ImageFiles, ExrRoundTripIsExact) {
    const fs::path folder = freshFolder("image_files_exr");
    const uint32_t w = 7, h = 4;
    std::vector<float> rgba(size_t(w) * h * 4);
    for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = std::pow(1.7f, float(i % 40) - 20.0f);
    rgba[5] = 0.0f;
    rgba[9] = 65504.0f * 3.0f;  // past half float: the file is 32-bit
    const std::string path = (folder / "a.exr").string();
    world::writeExrFile(path, w, h, rgba);
    const world::FloatImage read = world::readExrFile(path);
    EXPECT_EQ(read.width, w);
    EXPECT_EQ(read.height, h);
    EXPECT_EQ(read.rgba, rgba);
}

TEST(ImageFiles, RgbExrReadsWithAlphaOne) {
    const fs::path folder = freshFolder("image_files_rgb_exr");
    const uint32_t w = 3, h = 2;
    std::vector<float> rgb(size_t(w) * h * 3);
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = 0.25f * float(i) + 0.5f;
    const std::string path = (folder / "rgb.exr").string();
    world::writeRgbExrFile(path, w, h, rgb);
    const world::FloatImage read = world::readExrFile(path);
    ASSERT_EQ(read.rgba.size(), size_t(w) * h * 4);
    for (size_t p = 0; p < size_t(w) * h; ++p) {
        for (size_t c = 0; c < 3; ++c) EXPECT_EQ(read.rgba[p * 4 + c], rgb[p * 3 + c]) << p;
        EXPECT_EQ(read.rgba[p * 4 + 3], 1.0f) << p;
    }
}

TEST(ImageFiles, HdrRoundTripWithinRgbePrecision) {
    const fs::path folder = freshFolder("image_files_hdr");
    const uint32_t w = 4, h = 2;
    std::vector<float> rgb(size_t(w) * h * 3);
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = 0.1f + 3.0f * float(i);
    const std::string path = (folder / "sky.hdr").string();
    world::writeHdrFile(path, w, h, rgb);
    const world::HdrImage read = world::readHdrFile(path);
    EXPECT_EQ(read.width, w);
    EXPECT_EQ(read.height, h);
    ASSERT_EQ(read.rgb.size(), rgb.size());
    // RGBE keeps 8 bits of mantissa against the pixel's largest channel.
    for (size_t i = 0; i < rgb.size(); ++i) {
        const size_t p = i / 3 * 3;
        const float largest = std::max({rgb[p], rgb[p + 1], rgb[p + 2]});
        EXPECT_NEAR(read.rgb[i], rgb[i], largest / 128.0f) << i;
    }
}

TEST(ImageFiles, AWrongSizeIsANamedErrorAndWritesNothing) {
    const fs::path folder = freshFolder("image_files_wrong_size");
    const std::string png = (folder / "a.png").string(), exr = (folder / "a.exr").string();
    std::string error =
        errorMessage([&] { world::writePngFile(png, 2, 2, std::vector<uint8_t>(15)); });
    EXPECT_EQ(error, png + ": the image has 15 bytes, expected 16");
    error = errorMessage([&] { world::writeExrFile(exr, 0, 2, std::vector<float>()); });
    EXPECT_EQ(error.rfind(exr + ": an image of 0x2", 0), 0u) << error;
    EXPECT_THROW(world::writeExrFile(exr, 2, 2, std::vector<float>(12)), world::Error);
    EXPECT_TRUE(fs::is_empty(folder));
}

TEST(ImageFiles, AFileThatIsNoExrIsANamedError) {
    const fs::path folder = freshFolder("image_files_not_exr");
    const std::string path = (folder / "not.exr").string();
    world::writePngFile(path, 1, 1, std::vector<uint8_t>{1, 2, 3, 4});
    const std::string error = errorMessage([&] { (void)world::readExrFile(path); });
    EXPECT_EQ(error.rfind(path + ": cannot read the EXR (", 0), 0u) << error;
    EXPECT_THROW((void)world::readExrFile((folder / "absent.exr").string()), world::Error);
    EXPECT_THROW((void)world::readExrFile(folder.string()), world::Error);  // a folder
}

}  // namespace
}  // namespace onelight::test
