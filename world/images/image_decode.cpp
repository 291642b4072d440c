#include "world/images/image_decode.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "world/error.hpp"

#include <stb_image.h>  // built in stb_image_build.cpp

#include "world/file_read.hpp"

namespace onelight::world {

namespace {

// stb_image's reason for the last failure; null when it has none (no stb call failed, as when a
// check of ours refused the bytes first).
std::string failureReason() {
    const char* reason = stbi_failure_reason();
    return reason ? reason : "no image data";
}

void checkExtent(int width, int height, const std::string& where) {
    if (width <= 0 || height <= 0 || uint32_t(width) > kMaxImageExtent ||
        uint32_t(height) > kMaxImageExtent)
        throw Error(where + ": image of " + std::to_string(width) + "x" + std::to_string(height) +
                    "; expected 1.." + std::to_string(kMaxImageExtent) + " texels a side");
}

// TGA's header fields (little-endian) that say how many bytes its texels take.
struct TgaHeader {
    uint32_t idLength, colourMapType, imageType, colourMapLength, colourMapEntryBits, bitsPerPixel;
};

TgaHeader tgaHeader(const uint8_t* b) {
    return {b[0], b[1], b[2], uint32_t(b[5] | b[6] << 8), b[7], b[16]};
}

// Whether the texel data of a TGA (types 1-3 raw, 9-11 run-length coded) holds `texels`
// texels: raw data must be whole; RLE packets are walked (no allocation) until they cover every
// texel. stb_image pads a short image with zeros, which would hide a truncated file.
void checkTgaHolds(const uint8_t* bytes, size_t size, uint64_t texels, const std::string& where) {
    if (size < 18)
        throw Error(where + ": a TGA of " + std::to_string(size) +
                    " bytes; expected a "
                    "header of 18");
    const TgaHeader h = tgaHeader(bytes);
    const uint64_t pixelBytes = (uint64_t(h.bitsPerPixel) + 7) / 8;
    const uint64_t start =
        18 + uint64_t(h.idLength) +
        (h.colourMapType ? uint64_t(h.colourMapLength) * ((uint64_t(h.colourMapEntryBits) + 7) / 8)
                         : 0);
    if (pixelBytes == 0 || start > size)
        throw Error(where + ": a TGA whose header and colour map pass its " + std::to_string(size) +
                    " bytes, or " + std::to_string(h.bitsPerPixel) + " bits a texel");
    const uint64_t available = size - start;
    if (h.imageType < 9) {
        if (texels * pixelBytes > available)
            throw Error(where + ": a TGA of " + std::to_string(texels) + " texels in " +
                        std::to_string(available) + " bytes of texel data; expected " +
                        std::to_string(texels * pixelBytes));
        return;
    }
    uint64_t covered = 0, at = start;
    while (covered < texels) {
        if (at >= size)
            throw Error(where + ": a run-length coded TGA ends after " + std::to_string(covered) +
                        " of its " + std::to_string(texels) + " texels (byte " +
                        std::to_string(size) + "); expected the rest");
        const uint8_t packet = bytes[at++];
        const uint64_t count = uint64_t(packet & 0x7F) + 1;
        at += (packet & 0x80) ? pixelBytes : count * pixelBytes;
        covered += count;
        if (at > size) covered = std::min(covered, texels - 1), at = size;  // cut mid-packet
    }
}

// JPEG's Huffman tables (DHT segments, wherever they appear: before the first scan or between
// scans) each define at most 256 codes. stb_image (Debian's 2022 copy) fills a 257-entry table
// with as many codes as the counts say, so a table claiming more writes past it: refused here
// first. Walks the segments and skips each scan's entropy-coded bytes (0xFF 0x00 is a stuffed
// byte, 0xFF 0xD0..0xD7 a restart marker).
// The Huffman tables a DHT segment at `at` (its FF C4) defines, read as stb reads them: tables
// while the segment's length lasts, each read whole even past the segment (bytes past the file
// read as 0). Throws naming a table of more than 256 codes (stb writes past its 257-entry
// array); returns the tables defined, a bit per id in [0] (DC) and [1] (AC).
std::array<uint8_t, 2> checkDhtSegment(const uint8_t* bytes, size_t size, size_t at,
                                       const std::string& where) {
    std::array<uint8_t, 2> defined = {0, 0};
    if (at + 4 > size) return defined;
    const size_t length = size_t(bytes[at + 2]) << 8 | bytes[at + 3];
    int64_t remaining = int64_t(length) - 2;
    for (size_t t = at + 4; remaining > 0 && t < size;) {
        size_t codes = 0;
        for (size_t i = 1; i <= 16; ++i) codes += t + i < size ? bytes[t + i] : 0;
        if (codes > 256)
            throw Error(where + ": a JPEG Huffman table of " + std::to_string(codes) +
                        " codes (byte " + std::to_string(t) + "); expected at most 256");
        defined[bytes[t] >> 4 & 1] |= uint8_t(1u << (bytes[t] & 3));
        t += 17 + codes;
        remaining -= int64_t(17 + codes);
    }
    return defined;
}

// Every FF C4 from `from` on (fill bytes before the C4 included, as stb skips them) as a DHT.
void checkEveryDhtFrom(const uint8_t* bytes, size_t size, size_t from, const std::string& where) {
    for (size_t at = from; at + 1 < size; ++at) {
        if (bytes[at] != 0xFF) continue;
        size_t marker = at + 1;
        while (marker < size && bytes[marker] == 0xFF) ++marker;
        if (marker < size && bytes[marker] == 0xC4)
            (void)checkDhtSegment(bytes, size, marker - 1, where);
        at = marker - 1;
    }
}

void checkJpegHuffmanTables(const uint8_t* bytes, size_t size, const std::string& where) {
    // stb takes 0xFF (fill bytes) 0xD8 as the start of a JPEG: the walk starts after it.
    size_t at = 0;
    if (size < 2 || bytes[0] != 0xFF) return;
    while (at + 1 < size && bytes[at + 1] == 0xFF) ++at;
    if (at + 1 >= size || bytes[at + 1] != 0xD8) return;
    at += 2;
    bool progressive = false;
    uint8_t defined[2] = {0, 0};  // the DC and AC tables defined so far, a bit per id
    while (at + 4 <= size) {
        if (bytes[at] != 0xFF) {
            ++at;  // padding between segments, which stb_image scans past as well
            continue;
        }
        const uint8_t marker = bytes[at + 1];
        if (marker == 0xFF) {
            ++at;  // fill byte
            continue;
        }
        if (marker == 0xD9) return;  // EOI
        if ((marker >= 0xD0 && marker <= 0xD7) || marker == 0x01) {
            at += 2;
            continue;
        }
        const size_t length = size_t(bytes[at + 2]) << 8 | bytes[at + 3];
        if (marker >= 0xC0 && marker <= 0xC2) progressive = marker == 0xC2;
        if (marker == 0xDA && at + 5 <= size) {
            // Every Huffman table the scan decodes with must be defined before it: stb decodes
            // with an unbuilt table's zeros and reads past its end.
            const size_t components = bytes[at + 4];
            const size_t spectral = at + 5 + 2 * components;  // Ss, Se, Ah/Al
            if (length >= 6 + 2 * components && spectral + 2 < size) {
                const bool dcScan = bytes[spectral] == 0, firstDc = (bytes[spectral + 2] >> 4) == 0;
                for (size_t c = 0; c < components; ++c) {
                    const uint8_t tables = bytes[at + 6 + 2 * c];
                    const bool needDc = !progressive || (dcScan && firstDc);
                    const bool needAc = !progressive || !dcScan;
                    if ((needDc && !(defined[0] >> (tables >> 4 & 3) & 1)) ||
                        (needAc && !(defined[1] >> (tables & 3) & 1)))
                        throw Error(where + ": a JPEG scan (byte " + std::to_string(at) +
                                    ") decodes with a Huffman table never defined; expected a "
                                    "DHT segment before it");
                }
            }
        }
        if (marker == 0xC4) {
            const std::array<uint8_t, 2> tables = checkDhtSegment(bytes, size, at, where);
            defined[0] |= tables[0];
            defined[1] |= tables[1];
        }
        at = at + 2 + length;
        if (marker == 0xDA) {
            // Where stb takes the next marker after a scan depends on how many bytes its Huffman
            // decoding consumed, which a walk cannot know: from here on every FF C4 a decoder
            // could take for a DHT segment is checked. (Entropy-coded bytes never hold one: a
            // coded FF is always followed by 00 or a restart marker.)
            checkEveryDhtFrom(bytes, size, at, where);
            while (at + 1 < size && !(bytes[at] == 0xFF && bytes[at + 1] != 0 &&
                                      !(bytes[at + 1] >= 0xD0 && bytes[at + 1] <= 0xD7)))
                ++at;
        }
    }
}

// A PNG's chunks, walked before stb reads them: each chunk's declared length must fit in the
// bytes that follow it (stb grows its IDAT buffer to a length before reading it, so a 1 KB file
// whose IDAT claims 1.5 GB allocated and zeroed that much before failing).
void checkPngChunks(const uint8_t* bytes, size_t size, const std::string& where) {
    if (size < 8 || bytes[0] != 0x89 || bytes[1] != 'P' || bytes[2] != 'N' || bytes[3] != 'G')
        return;
    size_t at = 8;
    while (at + 8 <= size) {
        const uint64_t length = uint64_t(bytes[at]) << 24 | uint64_t(bytes[at + 1]) << 16 |
                                uint64_t(bytes[at + 2]) << 8 | uint64_t(bytes[at + 3]);
        std::string type;
        for (size_t i = 4; i < 8; ++i) {
            const char c = char(bytes[at + i]);
            type += (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ? c : '?';
        }
        const uint64_t remaining = uint64_t(size - at - 8);  // the data and its 4-byte CRC
        if (length + 4 > remaining)
            throw Error(where + ": a PNG chunk '" + type + "' at byte " + std::to_string(at) +
                        " declares " + std::to_string(length) + " bytes; expected at most " +
                        std::to_string(remaining >= 4 ? remaining - 4 : 0) +
                        " (what the file holds after it)");
        if (type == "IEND") return;
        at += 12 + size_t(length);
    }
}

// A bound on the texels `size` encoded bytes can hold, known before decoding: an image whose
// header claims more is refused before anything is allocated. PNG: deflate expands at most
// 1032:1, and a 1-bit texel takes 1/8 byte; JPEG: every 8x8 block costs at least one bit
// (progressive DC); Radiance HDR (stb reads flat or new-style RLE): at least 1/16 byte a texel.
// TGA is checked exactly (checkTgaHolds).
void checkEncodedHolds(const uint8_t* bytes, size_t size, int width, int height,
                       const std::string& where) {
    const uint64_t texels = uint64_t(width) * uint64_t(height);
    uint64_t perByte = 0;
    const char* format = nullptr;
    if (size >= 8 && bytes[0] == 0x89 && bytes[1] == 'P' && bytes[2] == 'N' && bytes[3] == 'G') {
        perByte = 1032 * 8, format = "PNG";
    } else if (size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8) {
        perByte = 64 * 8, format = "JPEG";
    } else if (size >= 2 && bytes[0] == '#' && bytes[1] == '?') {
        perByte = 16, format = "Radiance HDR";
    } else {
        checkTgaHolds(bytes, size, texels, where);
        return;
    }
    if (texels > perByte * uint64_t(size))
        throw Error(where + ": a " + format + " of " + std::to_string(size) + " bytes claims " +
                    std::to_string(width) + "x" + std::to_string(height) +
                    " texels; expected at most " + std::to_string(perByte) +
                    " texels a byte of it");
}

}  // namespace

DecodedImage decodeImage(const uint8_t* bytes, size_t size, const std::string& where,
                         ImageMemoryBudget* budget) {
    if (size == 0 || size > kMaxEncodedImageBytes)
        throw Error(where + ": " + std::to_string(size) + " bytes of image data; expected 1.." +
                    std::to_string(kMaxEncodedImageBytes));
    int width = 0, height = 0, channels = 0;
    // Before stb reads anything: its header parse already builds the Huffman tables.
    checkJpegHuffmanTables(bytes, size, where);
    checkPngChunks(bytes, size, where);
    if (!stbi_info_from_memory(bytes, int(size), &width, &height, &channels))
        throw Error(where + ": not a decodable PNG, JPEG or TGA image (" + failureReason() + ")");
    checkExtent(width, height, where);
    checkEncodedHolds(bytes, size, width, height, where);
    if (budget) chargeImage(*budget, uint32_t(width), uint32_t(height), where);
    stbi_uc* pixels = stbi_load_from_memory(bytes, int(size), &width, &height, &channels, 4);
    if (!pixels)
        throw Error(where + ": not a decodable PNG, JPEG or TGA image (" + failureReason() + ")");
    DecodedImage out;
    out.width = uint32_t(width);
    out.height = uint32_t(height);
    out.rgba.assign(pixels, pixels + size_t(width) * size_t(height) * 4);
    stbi_image_free(pixels);
    return out;
}

DecodedImage readImageFile(const std::string& path, ImageMemoryBudget* budget) {
    const std::vector<uint8_t> bytes =
        readRegularFile(path, "a PNG or JPEG file", kMaxEncodedImageBytes);
    return decodeImage(bytes.data(), bytes.size(), path, budget);
}

HdrImage readHdrFile(const std::string& path, ImageMemoryBudget* budget) {
    const std::vector<uint8_t> bytes =
        readRegularFile(path, "a Radiance .hdr image", kMaxEncodedImageBytes);
    return decodeHdrImage(bytes.data(), bytes.size(), path, budget);
}

HdrImage decodeHdrImage(const uint8_t* bytes, size_t size, const std::string& where,
                        ImageMemoryBudget* budget) {
    int width = 0, height = 0, channels = 0;
    // Radiance HDR only: stb would decode any format it knows to floats here.
    if (size == 0 || size > kMaxEncodedImageBytes || !stbi_is_hdr_from_memory(bytes, int(size)))
        throw Error(where +
                    ": not a Radiance .hdr image (expected its '#?RADIANCE' or '#?RGBE' "
                    "header)");
    if (!stbi_info_from_memory(bytes, int(size), &width, &height, &channels))
        throw Error(where + ": not a decodable .hdr image (" + failureReason() + ")");
    checkExtent(width, height, where);
    checkEncodedHolds(bytes, size, width, height, where);
    if (budget) chargeImage(*budget, uint32_t(width), uint32_t(height), where);
    float* pixels = stbi_loadf_from_memory(bytes, int(size), &width, &height, &channels, 3);
    if (!pixels) throw Error(where + ": not a decodable .hdr image (" + failureReason() + ")");
    HdrImage out;
    out.width = uint32_t(width);
    out.height = uint32_t(height);
    out.rgb.assign(pixels, pixels + size_t(width) * size_t(height) * 3);
    stbi_image_free(pixels);
    for (float& v : out.rgb)
        if (!(v >= 0.0f) || !std::isfinite(v)) v = 0.0f;  // no NaN or Inf reaches a texel
    return out;
}

}  // namespace onelight::world
