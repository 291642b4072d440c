// Memory bounds: a level's decoded images are charged against a budget from their headers, so
// the refusal comes before the allocation and names the image, the total and the limit; and an
// image whose header claims more texels than its bytes can hold (a TGA's RLE walked exactly, a
// PNG or JPEG by its format's best ratio) is refused before it is decoded.
#include <chrono>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/error_message.hpp"
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

// A TGA header: `type` 2 raw or 10 run-length coded, 24-bit, `width` x `height`, top-left.
std::vector<uint8_t> tgaHeader(uint8_t type, uint16_t width, uint16_t height) {
    return {0,
            0,
            type,
            0,
            0,
            0,
            0,
            0,
            0,
            0,
            0,
            0,
            uint8_t(width),
            uint8_t(width >> 8),
            uint8_t(height),
            uint8_t(height >> 8),
            24,
            0x20};
}

std::string decodeError(const std::vector<uint8_t>& bytes, double* seconds = nullptr) {
    const auto start = std::chrono::steady_clock::now();
    std::string message;
    try {
        (void)world::decodeImage(bytes.data(), bytes.size(), "maps.pk3:textures/x.tga");
    } catch (const world::Error& e) {
        message = e.what();
    }
    if (seconds)
        *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return message;
}

TEST(HostileMemory, ATgaIsRefusedWhenItsTexelDataCannotHoldItsHeader) {
    // 16384^2 claimed in 1 KB of RLE: 8 texels a packet of 4 bytes at most covers 2048 texels.
    std::vector<uint8_t> big = tgaHeader(10, 16384, 16384);
    for (int i = 0; i < 256; ++i) big.insert(big.end(), {0x87, 1, 2, 3});
    double seconds = 0.0;
    std::string message = decodeError(big, &seconds);
    EXPECT_EQ(message,
              "maps.pk3:textures/x.tga: a run-length coded TGA ends after 2048 of its "
              "268435456 texels (byte 1042); expected the rest");
    EXPECT_LT(seconds, 1.0) << "refused before 1 GiB is allocated";
    // A 4x4 RLE image whose packets cover 10 texels: truncated, not padded with zeros.
    std::vector<uint8_t> cut = tgaHeader(10, 4, 4);
    cut.insert(cut.end(), {0x89, 9, 9, 9});
    EXPECT_NE(decodeError(cut).find("ends after 10 of its 16 texels"), std::string::npos)
        << decodeError(cut);
    // The same image whole decodes: one run of 16 texels.
    std::vector<uint8_t> whole = tgaHeader(10, 4, 4);
    whole.insert(whole.end(), {0x8F, 10, 20, 30});
    const world::DecodedImage image =
        world::decodeImage(whole.data(), whole.size(), "maps.pk3:textures/x.tga");
    ASSERT_EQ(image.width, 4u);
    EXPECT_EQ(image.rgba[0], 30);  // TGA stores BGR
    EXPECT_EQ(image.rgba[4 * 15 + 2], 10);
    // A raw image one byte short.
    std::vector<uint8_t> raw = tgaHeader(2, 2, 2);
    raw.resize(raw.size() + 11, 7);
    EXPECT_EQ(decodeError(raw),
              "maps.pk3:textures/x.tga: a TGA of 4 texels in 11 bytes of texel "
              "data; expected 12");
}

TEST(HostileMemory, NoBytesAtAllAreAnErrorNotACrash) {
    // Found by fuzz_image: an empty .hdr read stb_image's failure reason before stb had one.
    const uint8_t none[1] = {0};
    EXPECT_NE(errorMessage([&] {
                  (void)world::decodeHdrImage(none, 0, "sky.hdr");
              }).find("sky.hdr: not a Radiance .hdr image"),
              std::string::npos);
    // Found by fuzz_image as well: a JPEG given as a sky went through stb's JPEG decoder.
    EXPECT_NE(errorMessage([&] {
                  (void)world::decodeHdrImage(kPng64.data(), kPng64.size(), "sky.hdr");
              }).find("sky.hdr: not a Radiance .hdr image"),
              std::string::npos);
    EXPECT_NE(
        errorMessage([&] { (void)world::decodeImage(none, 0, "x.png"); }).find("x.png: 0 bytes"),
        std::string::npos);
}

TEST(HostileMemory, AJpegHuffmanTablePast256CodesIsRefusedBeforeStbReadsIt) {
    // Found by fuzz_image: stb_image writes past its 257-entry table for such a DHT segment.
    std::vector<uint8_t> jpeg = {0xFF, 0xD8, 0xFF, 0xC4};
    const size_t length = 2 + 17 + 300;
    jpeg.insert(jpeg.end(), {uint8_t(length >> 8), uint8_t(length & 255), 0x00});
    for (int i = 0; i < 16; ++i) jpeg.push_back(i == 14 ? 45 : i == 15 ? 255 : 0);
    jpeg.resize(jpeg.size() + 300, 7);
    jpeg.insert(jpeg.end(), {0xFF, 0xD9});
    EXPECT_EQ(decodeError(jpeg),
              "maps.pk3:textures/x.tga: a JPEG Huffman table of 300 codes "
              "(byte 6); expected at most 256");
    // Within a scan's entropy-coded bytes a 0xFF 0x00 is data, not a marker: walked past.
    std::vector<uint8_t> scan;
    scan.reserve(jpeg.size() + 8);
    for (const uint8_t b : {0xFF, 0xD8, 0xFF, 0xDA, 0x00, 0x02, 0x12, 0xFF, 0x00, 0x34})
        scan.push_back(b);
    for (size_t i = 2; i < jpeg.size(); ++i) scan.push_back(jpeg[i]);
    EXPECT_NE(decodeError(scan).find("a JPEG Huffman table of 300 codes (byte 14)"),
              std::string::npos)
        << decodeError(scan);
}

TEST(HostileMemory, AJpegHuffmanTableAfterAScanIsCheckedWhereverADecoderMightTakeIt) {
    // Found by fuzz_image: after a scan, stb reads its Huffman-coded bytes as far as its decoding
    // goes, and a fill byte before a stuffed zero (FF FF 00) is data to it, so where it takes the
    // next marker is not where a walk of the segments ends. A DHT of 300 codes after such bytes
    // reached stb's 257-entry table. Every FF C4 after the first scan is now checked.
    std::vector<uint8_t> jpeg = {0xFF, 0xD8,                                      // SOI
                                 0xFF, 0xC0, 0x00, 0x0B, 0x08, 0x00, 0x08, 0x00,  // SOF0 8x8
                                 0x08, 0x01, 0x01, 0x11, 0x00,                    // 1 component
                                 0xFF, 0xC4, 0x00, 0x14, 0x00};                   // DHT DC 0
    for (int i = 0; i < 16; ++i) jpeg.push_back(i == 0 ? 1 : 0);                  // one code
    jpeg.push_back(0x00);
    jpeg.insert(jpeg.end(), {0xFF, 0xC4, 0x00, 0x14, 0x10});  // DHT AC 0, one code
    for (int i = 0; i < 16; ++i) jpeg.push_back(i == 0 ? 1 : 0);
    jpeg.push_back(0x00);
    jpeg.insert(jpeg.end(), {0xFF, 0xDA, 0x00, 0x08, 0x01, 0x01, 0x00, 0x00, 0x3F, 0x00,  // SOS
                             0x12, 0x34, 0xFF, 0xFF, 0x00, 0x56});  // coded bytes, FF FF 00
    const size_t table = jpeg.size() + 4;
    jpeg.insert(jpeg.end(), {0xFF, 0xC4, 0x01, 0x3F, 0x00});  // DHT: 300 codes
    for (int i = 0; i < 16; ++i) jpeg.push_back(i == 14 ? 45 : i == 15 ? 255 : 0);
    jpeg.resize(jpeg.size() + 300, 7);
    jpeg.insert(jpeg.end(), {0xFF, 0xD9});
    EXPECT_EQ(decodeError(jpeg),
              "maps.pk3:textures/x.tga: a JPEG Huffman table of 300 codes "
              "(byte " +
                  std::to_string(table) + "); expected at most 256");
}

TEST(HostileMemory, AJpegScanWithAnUndefinedHuffmanTableIsRefused) {
    // Found by fuzz_image: stb decodes with an unbuilt table and reads past its end. A baseline
    // frame, then a scan of one component using DC table 0 and AC table 0, none defined.
    const std::vector<uint8_t> jpeg = {0xFF, 0xD8, 0xFF, 0xC0, 0x00, 0x0B, 0x08, 0x00, 0x08, 0x00,
                                       0x08, 0x01, 0x01, 0x11, 0x00, 0xFF, 0xDA, 0x00, 0x08, 0x01,
                                       0x01, 0x00, 0x00, 0x3F, 0x00, 0x12, 0x34, 0xFF, 0xD9};
    EXPECT_EQ(decodeError(jpeg),
              "maps.pk3:textures/x.tga: a JPEG scan (byte 15) decodes with a "
              "Huffman table never defined; expected a DHT segment before it");
}

TEST(HostileMemory, AJpegWhoseCoefficientsOverflowDecodesToDefinedTexels) {
    // Found by fuzz_image: a damaged 128x128 baseline JPEG whose DC differences accumulate past
    // what stb's int product with the quantiser holds (stbi__jpeg_decode_block), and whose scan
    // names component 2 twice and component 3 never, so stb reads a plane it never wrote. stb is
    // built with -fwrapv and zeroed allocations (world/images/stb_image_build.cpp): the product
    // wraps and the unwritten plane reads 0, so the file decodes to the same wrong texels every
    // time, and the sanitizer build (scripts/sanitize.sh) sees no undefined behaviour.
    const std::vector<uint8_t> jpeg = {
        0xff, 0xd8, 0xff, 0xe0, 0x00, 0x15, 0x16, 0x17, 0x17, 0x17, 0x0e, 0x11, 0x19, 0x1b, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x16, 0x16, 0x16,
        0x16, 0x16, 0x16, 0x16, 0x16, 0x16, 0x16, 0xff, 0xc0, 0x00, 0x11, 0x08, 0x00, 0x80, 0x00,
        0x80, 0x03, 0x01, 0x22, 0x00, 0x02, 0x11, 0x01, 0x03, 0x11, 0x01, 0xff, 0xc4, 0x00, 0x1c,
        0x00, 0x01, 0x00, 0x01, 0x05, 0x01, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x08, 0x09, 0x07, 0x02, 0x03, 0x04, 0x05, 0x07, 0x06, 0xff, 0xc4, 0x00, 0x2c,
        0x10, 0x00, 0x02, 0x01, 0x04, 0x00, 0x04, 0x05, 0x03, 0x05, 0x01, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x01, 0x02, 0x03, 0x04, 0x05, 0x11, 0x06, 0x07, 0x12, 0x21, 0x08, 0x13,
        0x31, 0x41, 0x61, 0x14, 0x32, 0x51, 0x09, 0x22, 0x71, 0x81, 0xa1, 0xb1, 0xff, 0xc4, 0x00,
        0x14, 0x01, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0xff, 0xc4, 0x00, 0x14, 0x11, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xff, 0xda, 0x00, 0x0c,
        0x03, 0x01, 0x00, 0x02, 0x11, 0x02, 0x11, 0x00, 0x4a, 0x00, 0xde, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x3f, 0xff, 0xd9,
    };
    const world::DecodedImage first = world::decodeImage(jpeg.data(), jpeg.size(), "x.jpg");
    const world::DecodedImage second = world::decodeImage(jpeg.data(), jpeg.size(), "x.jpg");
    EXPECT_EQ(first.width, 128u);
    EXPECT_EQ(first.height, 128u);
    EXPECT_EQ(first.rgba, second.rgba);
}

// A chunk whose length claims more than the file holds (fuzz_image's 1.3 KB PNG whose IDAT
// declared 1.5 GB, which stb allocated before reading) is refused by the chunk walk, at once.
TEST(HostileMemory, APngChunkLongerThanItsFileIsRefusedBeforeDecoding) {
    std::vector<uint8_t> png = kPng64;
    size_t idat = 8;
    while (idat + 8 <= png.size() &&
           std::string(png.begin() + long(idat) + 4, png.begin() + long(idat) + 8) != "IDAT")
        idat += 12 + (size_t(png[idat]) << 24 | size_t(png[idat + 1]) << 16 |
                      size_t(png[idat + 2]) << 8 | size_t(png[idat + 3]));
    ASSERT_LT(idat + 8, png.size());
    for (int i = 0; i < 4; ++i) png[idat + size_t(i)] = uint8_t(0x5C000000u >> (24 - 8 * i));
    double seconds = 0.0;
    const std::string message = decodeError(png, &seconds);
    EXPECT_NE(message.find("maps.pk3:textures/x.tga: a PNG chunk 'IDAT' at byte " +
                           std::to_string(idat) + " declares 1543503872 bytes; expected at most"),
              std::string::npos)
        << message;
    EXPECT_LT(seconds, 1.0);
    // The real file still decodes.
    EXPECT_EQ(world::decodeImage(kPng64.data(), kPng64.size(), "x.png").width, 64u);
}

TEST(HostileMemory, APngClaimingMoreThanDeflateCanHoldIsRefusedBeforeDecoding) {
    // kPng64 with its IHDR saying 16384 x 16384 (the CRC is not what stb checks first).
    std::vector<uint8_t> png = kPng64;
    for (int at : {16, 20}) {
        png[size_t(at)] = 0, png[size_t(at) + 1] = 0, png[size_t(at) + 2] = 0x40,
        png[size_t(at) + 3] = 0;
    }
    double seconds = 0.0;
    const std::string message = decodeError(png, &seconds);
    EXPECT_NE(message.find("a PNG of 158 bytes claims 16384x16384 texels; expected at most 8256 "
                           "texels a byte of it"),
              std::string::npos)
        << message;
    EXPECT_LT(seconds, 1.0);
}

}  // namespace
}  // namespace onelight::test
