// The memory a level's decoded images may take together, charged image by image before each is
// decoded, so that a level of many huge textures is refused with the figure instead of running
// out of memory halfway.
#pragma once

#include <cstdint>
#include <string>

namespace onelight::world {

/// The most memory one tool gives a level's decoded images at once (8 GiB).
inline constexpr uint64_t kMaxDecodedImageBytes = uint64_t(8) << 30;

/// A running total of decoded image memory. `bytesPerTexel` is what one texel costs its holder:
/// 4 for the runtime's RGBA8, 16 * 4 / 3 for the baker's float texels with their mips.
struct ImageMemoryBudget {
    double bytesPerTexel = 4.0;
    uint64_t limitBytes = kMaxDecodedImageBytes;
    uint64_t usedBytes = 0;
};

/// Adds an image of `width` x `height` texels to `budget`, or throws world::Error naming `where`,
/// the total it would bring and the limit (nothing is charged then).
void chargeImage(ImageMemoryBudget& budget, uint32_t width, uint32_t height,
                 const std::string& where);

}  // namespace onelight::world
