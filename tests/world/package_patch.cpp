#include "tests/world/package_patch.hpp"

#include <cstring>

#include <gtest/gtest.h>

#include "world/package/crc32.hpp"

namespace onelight::test {

using namespace onelight::package;

SectionEntry entry(const std::vector<uint8_t>& bytes, uint32_t id) {
    FileHeader header;
    std::memcpy(&header, bytes.data(), sizeof header);
    for (uint32_t i = 0; i < header.sectionCount; ++i) {
        SectionEntry e;
        std::memcpy(&e, bytes.data() + sizeof(FileHeader) + i * sizeof(SectionEntry), sizeof e);
        if (e.id == id) return e;
    }
    ADD_FAILURE() << "no section " << id;
    return {};
}

void fixCrcs(std::vector<uint8_t>& bytes) {
    FileHeader header;
    std::memcpy(&header, bytes.data(), sizeof header);
    for (uint32_t i = 0; i < header.sectionCount; ++i) {
        uint8_t* at = bytes.data() + sizeof(FileHeader) + i * sizeof(SectionEntry);
        SectionEntry e;
        std::memcpy(&e, at, sizeof e);
        e.crc32 = crc32(bytes.data() + e.offset, e.size);
        std::memcpy(at, &e, sizeof e);
    }
    header.tableCrc32 = 0;
    std::memcpy(bytes.data(), &header, sizeof header);
    header.tableCrc32 =
        crc32(bytes.data(), sizeof(FileHeader) + header.sectionCount * sizeof(SectionEntry));
    std::memcpy(bytes.data(), &header, sizeof header);
}

std::vector<uint8_t> patched(std::vector<uint8_t> bytes, uint32_t id, uint32_t record,
                             size_t fieldOffset, uint32_t value) {
    const SectionEntry e = entry(bytes, id);
    EXPECT_LT(record, e.count);
    std::memcpy(bytes.data() + e.offset + uint64_t(record) * e.elementSize + fieldOffset, &value,
                4);
    fixCrcs(bytes);
    return bytes;
}

}  // namespace onelight::test
