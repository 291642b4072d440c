// CRC32 (IEEE 802.3 polynomial, reflected, as zlib's crc32) over bytes.
#pragma once

#include <cstddef>
#include <cstdint>

namespace onelight::package {

/// Continues `crc` (0 to start) over `size` bytes.
[[nodiscard]] uint32_t crc32(const void* data, size_t size, uint32_t crc = 0);

}  // namespace onelight::package
