// Editing a package's bytes in tests: find a section, overwrite a field, and recompute every
// CRC so that only the reader's semantic checks can object.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "world/package/format.hpp"

namespace onelight::test {

/// The table entry of section `id` (a test failure when there is none).
package::SectionEntry entry(const std::vector<uint8_t>& bytes, uint32_t id);

/// Recomputes every section CRC and the table CRC.
void fixCrcs(std::vector<uint8_t>& bytes);

/// Overwrites a uint32 field of record `record` in section `id`, then fixes the CRCs.
std::vector<uint8_t> patched(std::vector<uint8_t> bytes, uint32_t id, uint32_t record,
                             size_t fieldOffset, uint32_t value);

}  // namespace onelight::test
