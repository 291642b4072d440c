#include "world/package/visibility_section.hpp"

#include <cmath>
#include <cstring>

#include "world/error.hpp"
#include "world/package/format.hpp"
#include "world/package/records.hpp"

namespace onelight::package {
namespace {

void appendWords(std::vector<uint8_t>& out, const std::vector<uint32_t>& words) {
    const size_t at = out.size();
    out.resize(at + words.size() * sizeof(uint32_t));
    if (!words.empty()) std::memcpy(out.data() + at, words.data(), words.size() * sizeof(uint32_t));
}

std::vector<uint32_t> readWords(const std::vector<uint8_t>& bytes, size_t offset, size_t count) {
    std::vector<uint32_t> words(count);
    if (count > 0) std::memcpy(words.data(), bytes.data() + offset, count * sizeof(uint32_t));
    return words;
}

}  // namespace

RawSection encodeVisibilitySection(const world::Visibility& v) {
    const DiskVisibilityHeader h = toDiskVisibilityHeader(v);
    RawSection s;
    s.id = kSectionVisibility;
    s.elementSize = 1;
    s.bytes.resize(sizeof(h));
    std::memcpy(s.bytes.data(), &h, sizeof(h));
    appendWords(s.bytes, v.surfaceCluster);
    appendWords(s.bytes, v.cellRow);
    appendWords(s.bytes, v.rows);
    s.count = uint32_t(s.bytes.size());
    return s;
}

world::Visibility decodeVisibilitySection(const RawSection& section,
                                          const world::CompiledLevel& level,
                                          const std::string& name) {
    const std::string at = name + ": section visibility: ";
    if (section.elementSize != 1 || section.bytes.size() != section.count ||
        section.bytes.size() < sizeof(DiskVisibilityHeader))
        throw world::Error(at + std::to_string(section.bytes.size()) +
                           " bytes; expected a header of " +
                           std::to_string(sizeof(DiskVisibilityHeader)) + " bytes and its arrays");
    DiskVisibilityHeader h;
    std::memcpy(&h, section.bytes.data(), sizeof(h));
    uint64_t cells = 1;
    for (int c = 0; c < 3; ++c) {
        if (h.dims[c] < 1 || h.dims[c] > world::kMaxVisibilityCellsPerAxis)
            throw world::Error(at + "dims[" + std::to_string(c) +
                               "] = " + std::to_string(h.dims[c]) + "; expected 1.." +
                               std::to_string(world::kMaxVisibilityCellsPerAxis));
        cells *= h.dims[c];  // at most 2^30: no overflow
        if (!std::isfinite(h.origin[c]))
            throw world::Error(at + "origin[" + std::to_string(c) + "] is not finite");
    }
    if (!std::isfinite(h.cellSize) || !(h.cellSize > 0.0f))
        throw world::Error(at + "cellSize " + std::to_string(h.cellSize) +
                           "; expected finite and > 0");
    if (cells > world::kMaxVisibilityCells || h.cellCount != cells)
        throw world::Error(at + "cellCount " + std::to_string(h.cellCount) + " for dims " +
                           std::to_string(h.dims[0]) + "x" + std::to_string(h.dims[1]) + "x" +
                           std::to_string(h.dims[2]) + "; expected their product, at most " +
                           std::to_string(world::kMaxVisibilityCells));
    if (h.surfaceCount != level.surfaces.size() || h.surfaceCount == 0)
        throw world::Error(at + "surfaceCount " + std::to_string(h.surfaceCount) + "; expected " +
                           std::to_string(level.surfaces.size()) +
                           " (the level's static surfaces, at least 1)");
    if (h.clusterCount < 1 || h.clusterCount > h.surfaceCount)
        throw world::Error(at + "clusterCount " + std::to_string(h.clusterCount) +
                           "; expected 1.." + std::to_string(h.surfaceCount));
    if (h.rowCount > h.cellCount)
        throw world::Error(at + "rowCount " + std::to_string(h.rowCount) +
                           "; expected at most cellCount " + std::to_string(h.cellCount));
    if (h.reserved != 0) throw world::Error(at + "reserved is not 0");
    const uint64_t wordsPerRow = (uint64_t(h.clusterCount) + 31) / 32;
    const uint64_t words =
        uint64_t(h.surfaceCount) + h.cellCount + uint64_t(h.rowCount) * wordsPerRow;
    const uint64_t expected = sizeof(DiskVisibilityHeader) + words * sizeof(uint32_t);
    if (section.bytes.size() != expected)
        throw world::Error(at + std::to_string(section.bytes.size()) + " bytes; expected " +
                           std::to_string(expected) + " for its header's counts");
    world::Visibility v;
    fromDiskVisibilityHeader(h, v);
    size_t offset = sizeof(DiskVisibilityHeader);
    v.surfaceCluster = readWords(section.bytes, offset, h.surfaceCount);
    offset += size_t(h.surfaceCount) * 4;
    v.cellRow = readWords(section.bytes, offset, h.cellCount);
    offset += size_t(h.cellCount) * 4;
    v.rows = readWords(section.bytes, offset, size_t(h.rowCount * wordsPerRow));
    for (size_t i = 0; i < v.surfaceCluster.size(); ++i)
        if (v.surfaceCluster[i] >= h.clusterCount)
            throw world::Error(at + "surface " + std::to_string(i) + " has cluster " +
                               std::to_string(v.surfaceCluster[i]) + "; expected < " +
                               std::to_string(h.clusterCount));
    for (size_t i = 0; i < v.cellRow.size(); ++i)
        if (v.cellRow[i] != world::kNoIndex && v.cellRow[i] >= h.rowCount)
            throw world::Error(at + "cell " + std::to_string(i) + " has row " +
                               std::to_string(v.cellRow[i]) + "; expected < " +
                               std::to_string(h.rowCount) + " or none (4294967295)");
    const uint32_t tailBits = h.clusterCount % 32;
    if (tailBits != 0)
        for (uint32_t r = 0; r < h.rowCount; ++r)
            if (v.rows[(r + 1) * wordsPerRow - 1] >> tailBits)
                throw world::Error(at + "row " + std::to_string(r) +
                                   " sets bits past clusterCount " +
                                   std::to_string(h.clusterCount));
    return v;
}

}  // namespace onelight::package
