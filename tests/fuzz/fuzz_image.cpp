// libFuzzer target: the image decoder, as the import and the runtime call it: PNG, JPEG and TGA
// (Quake 3 textures) to RGBA8, and Radiance HDR skies to float RGB, each charged to a budget from
// its header. Any input must end in a world::Error or an image, never a crash, and never an
// allocation past the budget (-rss_limit_mb stops the run if one slips through).
#include <cstddef>
#include <cstdint>

#include "world/error.hpp"
#include "world/images/image_decode.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace onelight::world;
    // 256 MB of decoded texels: room for any real texture, not for a header that lies.
    ImageMemoryBudget rgba8{4.0, uint64_t(256) << 20, 0};
    try {
        (void)decodeImage(data, size, "fuzz.tga", &rgba8);
    } catch (const Error&) {
    }
    ImageMemoryBudget hdr{12.0, uint64_t(256) << 20, 0};
    try {
        (void)decodeHdrImage(data, size, "fuzz.hdr", &hdr);
    } catch (const Error&) {
    }
    return 0;
}
