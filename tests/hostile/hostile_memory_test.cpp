// Memory bounds: a level's decoded images are charged against a budget from their headers, so
// the refusal comes before the allocation and names the image, the total and the limit.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "world/error.hpp"
#include "world/images/image_budget.hpp"
#include "world/images/image_decode.hpp"

namespace onelight::test {
namespace {

// A 64x64 RGBA PNG, every texel (128, 64, 32, 255).
const std::vector<uint8_t> kPng64 = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x40, 0x00, 0x00, 0x00, 0x40, 0x08, 0x06, 0x00, 0x00, 0x00, 0xaa, 0x69, 0x71,
    0xde, 0x00, 0x00, 0x00, 0x65, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0xed, 0xd0, 0x41, 0x11, 0x00,
    0x00, 0x04, 0x00, 0x30, 0x51, 0x44, 0x11, 0x4d, 0x73, 0x72, 0x38, 0x7b, 0xac, 0xc0, 0xa2, 0x2b,
    0xe7, 0xb3, 0x10, 0x20, 0x40, 0x80, 0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x20, 0x40, 0x80, 0x00,
    0x01, 0x02, 0x04, 0x08, 0x10, 0x20, 0x40, 0x80, 0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x20, 0x40,
    0x80, 0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x20, 0x40, 0x80, 0x00, 0x01, 0x02, 0x04, 0x08, 0x10,
    0x20, 0x40, 0x80, 0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x20, 0x40, 0x80, 0x00, 0x01, 0x02, 0x04,
    0x08, 0x10, 0x20, 0x40, 0x80, 0x00, 0x01, 0x02, 0xee, 0x5b, 0xb5, 0x05, 0xf1, 0xb4, 0x75, 0x2d,
    0x21, 0xf0, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

TEST(HostileMemory, DecodedImagesPastTheBudgetAreRefusedBeforeDecoding) {
    // Room for two 64x64 RGBA8 images (16384 bytes each), not three.
    world::ImageMemoryBudget budget{4.0, 40000, 0};
    for (int i = 0; i < 2; ++i) {
        const world::DecodedImage image =
            world::decodeImage(kPng64.data(), kPng64.size(), "level.gltf: image 0", &budget);
        ASSERT_EQ(image.width, 64u);
        EXPECT_EQ(image.rgba[0], 128);
    }
    EXPECT_EQ(budget.usedBytes, 32768u);
    try {
        (void)world::decodeImage(kPng64.data(), kPng64.size(), "level.gltf: image 2 'big'",
                                 &budget);
        FAIL() << "the third image fits a budget of two";
    } catch (const world::Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("level.gltf: image 2 'big'"), std::string::npos) << message;
        EXPECT_NE(message.find("64x64"), std::string::npos) << message;
        EXPECT_NE(message.find("0.04915 MB"), std::string::npos) << message;  // the total
        EXPECT_NE(message.find("at most 0.04 MB"), std::string::npos) << message;
    }
    EXPECT_EQ(budget.usedBytes, 32768u);  // nothing charged for the refused image
}

TEST(HostileMemory, TheBudgetCountsWhatATexelCostsItsHolder) {
    // The baker's float texels with mips cost 16 * 4 / 3 bytes: one 64x64 image is 87381 bytes.
    world::ImageMemoryBudget baker{16.0 * 4.0 / 3.0, 80000, 0};
    EXPECT_THROW(world::chargeImage(baker, 64, 64, "image"), world::Error);
    world::ImageMemoryBudget runtime{4.0, 80000, 0};
    EXPECT_NO_THROW(world::chargeImage(runtime, 64, 64, "image"));
    // The default limit holds eight 16384^2 RGBA8 images and refuses a ninth.
    world::ImageMemoryBudget full{};
    for (int i = 0; i < 8; ++i) world::chargeImage(full, 16384, 16384, "image");
    EXPECT_THROW(world::chargeImage(full, 16384, 16384, "image 8"), world::Error);
}

}  // namespace
}  // namespace onelight::test
