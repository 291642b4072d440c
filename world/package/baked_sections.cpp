#include "world/package/baked_sections.hpp"

#include <cmath>
#include <cstring>

#include "world/error.hpp"
#include "world/package/budget_section.hpp"
#include "world/package/format.hpp"
#include "world/package/probe_section.hpp"
#include "world/package/records.hpp"
#include "world/package/visibility_section.hpp"

namespace onelight::package {
namespace {

template <class T>
void appendBytes(std::vector<uint8_t>& out, const T& value) {
    const auto* p = reinterpret_cast<const uint8_t*>(&value);
    out.insert(out.end(), p, p + sizeof(T));
}

template <class T>
T readRecord(const std::vector<uint8_t>& bytes, size_t offset) {
    T value;
    std::memcpy(&value, bytes.data() + offset, sizeof(T));
    return value;
}

/// Throws unless every element of the array field `name` is finite and >= 0; `at` names the
/// record.
template <size_t N>
void checkFiniteNonNegative(const std::string& at, const std::string& name, const float (&v)[N]) {
    for (size_t k = 0; k < N; ++k)
        if (!std::isfinite(v[k]) || v[k] < 0.0f)
            throw world::Error(at + name + "[" + std::to_string(k) + "] = " + std::to_string(v[k]) +
                               ": not finite or negative");
}

/// Throws when a lightmap texel is not one a bake can write; `at` names the record.
void check(const DiskLightmapTexel& d, const std::string& at) {
    checkFiniteNonNegative(at, "irradiance", d.irradiance);
    const float length =
        std::sqrt(d.direction[0] * d.direction[0] + d.direction[1] * d.direction[1] +
                  d.direction[2] * d.direction[2]);
    if (!(length <= 0.5f + 1e-4f))
        throw world::Error(at + "direction length " + std::to_string(length) + " > 0.5");
    if (!(d.normalWeight >= 0.5f - 1e-4f && d.normalWeight <= 1.0f + 1e-4f))
        throw world::Error(at + "normalWeight " + std::to_string(d.normalWeight) +
                           " outside [0.5, 1]");
    if (d.flags & ~kAllLightmapTexelFlags)
        throw world::Error(at + "flags " + std::to_string(d.flags) + " has unknown bits");
    checkFiniteNonNegative(at, "directIrradiance", d.directIrradiance);
    checkFiniteNonNegative(at, "indirectIrradiance", d.indirectIrradiance);
    const float light =
        std::sqrt(d.directLight[0] * d.directLight[0] + d.directLight[1] * d.directLight[1] +
                  d.directLight[2] * d.directLight[2]);
    const bool direct = d.directIrradiance[0] > 0.0f || d.directIrradiance[1] > 0.0f ||
                        d.directIrradiance[2] > 0.0f;
    if (direct ? !(std::abs(light - 1.0f) <= 1e-3f) : light != 0.0f)
        throw world::Error(
            at + "directLight length " + std::to_string(light) +
            (direct ? ": expected 1 (a direct light)" : ": expected 0 (no direct light)"));
    const auto inRange = [&](const char* name, float v, float lo, float hi) {
        if (!(v >= lo && v <= hi))
            throw world::Error(at + name + " " + std::to_string(v) + " outside [" +
                               std::to_string(lo) + ", " + std::to_string(hi) + "]");
    };
    inRange("directVisibility", d.directVisibility, 0.0f, 1.0f);
    inRange("directEdgeDistance", d.directEdgeDistance, -world::kDirectEdgeReach,
            world::kDirectEdgeReach);
    inRange("directEdgeWidth", d.directEdgeWidth, 0.0f, world::kDirectEdgeMaxWidth);
    inRange("directEdgeLow", d.directEdgeLow, 0.0f, 1.0f);
    inRange("directEdgeHigh", d.directEdgeHigh, d.directEdgeLow, 1.0f);
    inRange("directEdgeSharpness", d.directEdgeSharpness, 0.0f, 1.0f);
}

/// Throws when a light grid cell is not one a bake of `level` can write; `at` names the record.
void check(const DiskLightGridCell& d, const world::CompiledLevel& level, const std::string& at) {
    for (int f = 0; f < 6; ++f)
        checkFiniteNonNegative(at, "ambientCube[" + std::to_string(f) + "]", d.ambientCube[f]);
    if (d.dominantPrimary != kNoIndex &&
        (d.dominantPrimary >= level.lights.size() ||
         level.lights[d.dominantPrimary].role != world::LightRole::kPrimary))
        throw world::Error(at + "dominantPrimary " + std::to_string(d.dominantPrimary) +
                           " is not a primary light of " + std::to_string(level.lights.size()));
    if (!(d.primaryVisibility >= 0.0f && d.primaryVisibility <= 1.0f))
        throw world::Error(at + "primaryVisibility " + std::to_string(d.primaryVisibility) +
                           " outside [0, 1]");
    if (d.flags & ~kAllLightGridCellFlags)
        throw world::Error(at + "flags " + std::to_string(d.flags) + " has unknown bits");
}

std::string where(const std::string& name, const char* section, uint64_t record) {
    return name + ": section " + section + ", record " + std::to_string(record) + ": ";
}

}  // namespace

std::vector<RawSection> encodeBakedSections(const world::BakedLighting& baked) {
    std::vector<RawSection> out(3);
    RawSection& texels = out[0];
    texels.id = kSectionLightmapTexels;
    texels.elementSize = sizeof(DiskLightmapTexel);
    texels.count = static_cast<uint32_t>(baked.texels.size());
    texels.bytes.reserve(baked.texels.size() * sizeof(DiskLightmapTexel));
    for (const world::LightmapTexel& t : baked.texels) appendBytes(texels.bytes, toDisk(t));
    RawSection& masks = out[1];
    masks.id = kSectionShadowMasks;
    masks.elementSize = 1;
    masks.count = static_cast<uint32_t>(baked.shadowMask.size());
    masks.bytes = baked.shadowMask;

    RawSection& grid = out[2];
    grid.id = kSectionLightGrid;
    grid.elementSize = 1;
    appendBytes(grid.bytes, toDiskGridHeader(baked));
    for (const world::LightGridCell& cell : baked.grid.cells) appendBytes(grid.bytes, toDisk(cell));
    grid.count = static_cast<uint32_t>(grid.bytes.size());
    if (!baked.probes.empty()) out.push_back(encodeProbeSection(baked.probes));
    if (!baked.importedTexels.empty()) {
        RawSection imported;
        imported.id = kSectionImportedLightmap;
        imported.elementSize = sizeof(DiskImportedTexel);
        imported.count = static_cast<uint32_t>(baked.importedTexels.size());
        for (const world::LightmapTexel& t : baked.importedTexels)
            appendBytes(imported.bytes, toDiskImported(t));
        out.push_back(std::move(imported));
    }
    if (!baked.visibility.empty()) out.push_back(encodeVisibilitySection(baked.visibility));
    if (baked.budget.budget > 0.0f) out.push_back(encodeBudgetSection(baked.budget));
    if (baked.shardCount > 1) {
        RawSection range;
        range.id = kSectionShardRange;
        range.elementSize = sizeof(DiskShardRange);
        range.count = 1;
        appendBytes(range.bytes, toDisk(baked.shardRange));
        out.push_back(std::move(range));
    }
    return out;
}

namespace {

/// Section 32: one texel per atlas texel (`atlasTexels`), each checked.
std::vector<world::LightmapTexel> decodeLightmapTexels(const RawSection& s, uint64_t atlasTexels,
                                                       const std::string& name) {
    if (s.elementSize != sizeof(DiskLightmapTexel) ||
        s.bytes.size() != uint64_t(s.count) * sizeof(DiskLightmapTexel) || s.count != atlasTexels)
        throw world::Error(
            name + ": section lightmap_texels: element size " + std::to_string(s.elementSize) +
            ", count " + std::to_string(s.count) + ", " + std::to_string(s.bytes.size()) +
            " bytes; expected element size " + std::to_string(sizeof(DiskLightmapTexel)) +
            " and count " + std::to_string(atlasTexels) + " (the atlases' texels)");
    std::vector<world::LightmapTexel> texels(s.count);
    for (uint32_t i = 0; i < s.count; ++i) {
        const auto d =
            readRecord<DiskLightmapTexel>(s.bytes, size_t(i) * sizeof(DiskLightmapTexel));
        check(d, where(name, "lightmap_texels", i));
        texels[i] = fromDisk(d);
    }
    return texels;
}

/// Section 36: the level's own lightmap, one irradiance per baked texel of `texels` (whose flags
/// it takes), each finite and >= 0.
std::vector<world::LightmapTexel> decodeImportedLightmap(
    const RawSection& s, const std::vector<world::LightmapTexel>& texels, const std::string& name) {
    if (s.elementSize != sizeof(DiskImportedTexel) ||
        s.bytes.size() != uint64_t(s.count) * sizeof(DiskImportedTexel) || s.count != texels.size())
        throw world::Error(name + ": section imported_lightmap: element size " +
                           std::to_string(s.elementSize) + ", count " + std::to_string(s.count) +
                           "; expected element size " + std::to_string(sizeof(DiskImportedTexel)) +
                           " and count " + std::to_string(texels.size()) +
                           " (the atlases' texels)");
    std::vector<world::LightmapTexel> imported(s.count);
    for (uint32_t i = 0; i < s.count; ++i) {
        const auto d =
            readRecord<DiskImportedTexel>(s.bytes, size_t(i) * sizeof(DiskImportedTexel));
        checkFiniteNonNegative(where(name, "imported_lightmap", i), "irradiance", d.irradiance);
        imported[i] = fromDisk(d, texels[i].flags);
    }
    return imported;
}

/// Section 33: one byte per atlas texel (`atlasTexels`).
std::vector<uint8_t> decodeShadowMasks(const RawSection& s, uint64_t atlasTexels,
                                       const std::string& name) {
    if (s.elementSize != 1 || s.bytes.size() != s.count || s.count != atlasTexels)
        throw world::Error(name + ": section shadow_masks: element size " +
                           std::to_string(s.elementSize) + ", count " + std::to_string(s.count) +
                           "; expected element size 1 and count " + std::to_string(atlasTexels));
    return s.bytes;
}

/// Section 34's header: dims within the limits, cellCount their product and the section's size,
/// a finite origin and cell size, a shard index below the shard count.
DiskLightGridHeader checkedGridHeader(const RawSection& s, const std::string& name) {
    const std::string at = name + ": section light_grid: ";
    if (s.elementSize != 1 || s.bytes.size() != s.count ||
        s.bytes.size() < sizeof(DiskLightGridHeader))
        throw world::Error(at + std::to_string(s.bytes.size()) + " bytes; expected a header of " +
                           std::to_string(sizeof(DiskLightGridHeader)) + " bytes and cells");
    const auto h = readRecord<DiskLightGridHeader>(s.bytes, 0);
    for (int c = 0; c < 3; ++c)
        if (h.dims[c] < 1 || h.dims[c] > world::kMaxLightGridCellsPerAxis)
            throw world::Error(at + "dims[" + std::to_string(c) +
                               "] = " + std::to_string(h.dims[c]) + "; expected 1.." +
                               std::to_string(world::kMaxLightGridCellsPerAxis) + " cells");
    // Each factor is at most 4096, so the product is exact in 64 bits.
    const uint64_t cells = uint64_t(h.dims[0]) * h.dims[1] * h.dims[2];
    if (cells > world::kMaxLightGridCells)
        throw world::Error(at + std::to_string(cells) + " cells; expected at most " +
                           std::to_string(world::kMaxLightGridCells));
    const uint64_t expectedBytes =
        sizeof(DiskLightGridHeader) + uint64_t(h.cellCount) * sizeof(DiskLightGridCell);
    if (cells != h.cellCount || s.bytes.size() != expectedBytes)
        throw world::Error(at + "dims " + std::to_string(h.dims[0]) + "x" +
                           std::to_string(h.dims[1]) + "x" + std::to_string(h.dims[2]) +
                           ", cellCount " + std::to_string(h.cellCount) + ", " +
                           std::to_string(s.bytes.size()) +
                           " bytes; expected cellCount == " + std::to_string(cells) + " and " +
                           std::to_string(expectedBytes) + " bytes");
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(h.origin[c]) || !std::isfinite(h.cellSize[c]) || !(h.cellSize[c] > 0.0f))
            throw world::Error(at + "header origin/cellSize[" + std::to_string(c) +
                               "] = " + std::to_string(h.origin[c]) + "/" +
                               std::to_string(h.cellSize[c]) + "; expected finite, size > 0");
    if (h.shardCount == 0 || h.shardIndex >= h.shardCount)
        throw world::Error(at + "shard " + std::to_string(h.shardIndex) + "/" +
                           std::to_string(h.shardCount) + "; expected index < count");
    return h;
}

/// Section 34 into `baked`: the header (checkedGridHeader), then every cell checked against
/// `level`'s lights.
void decodeLightGrid(const RawSection& s, const world::CompiledLevel& level,
                     const std::string& name, world::BakedLighting& baked) {
    const DiskLightGridHeader h = checkedGridHeader(s, name);
    fromDiskGridHeader(h, baked);
    baked.grid.cells.resize(h.cellCount);
    for (uint32_t i = 0; i < h.cellCount; ++i) {
        const auto d = readRecord<DiskLightGridCell>(
            s.bytes, sizeof(DiskLightGridHeader) + size_t(i) * sizeof(DiskLightGridCell));
        check(d, level, where(name, "light_grid cells", i));
        baked.grid.cells[i] = fromDisk(d);
    }
}

/// Section 40 of a part of a level of `charts` charts holding `cells` grid cells and `probes`
/// probes.
world::ShardRange decodeShardRange(const RawSection& section, uint64_t charts, uint64_t cells,
                                   uint64_t probes, const std::string& name) {
    const std::string at = name + ": section shard_range: ";
    if (section.elementSize != sizeof(DiskShardRange) || section.count != 1 ||
        section.bytes.size() != sizeof(DiskShardRange))
        throw world::Error(
            at + "element size " + std::to_string(section.elementSize) + ", count " +
            std::to_string(section.count) + ", " + std::to_string(section.bytes.size()) +
            " bytes; expected one record of " + std::to_string(sizeof(DiskShardRange)) + " bytes");
    const auto d = readRecord<DiskShardRange>(section.bytes, 0);
    auto range = [&](const char* what, uint64_t begin, uint64_t end, uint64_t total,
                     const std::string& totalName) {
        if (begin > end || end > total)
            throw world::Error(
                at + what + " [" + std::to_string(begin) + ", " + std::to_string(end) +
                "); expected begin <= end <= " + std::to_string(total) + " (" + totalName + ")");
    };
    range("charts", d.chartBegin, d.chartEnd, charts, "the level's charts");
    range("cells", d.cellBegin, d.cellEnd, cells, "the light grid's cells");
    range("probes", d.probeBegin, d.probeEnd, d.probeTotal, "probeTotal");
    if (d.probeEnd - d.probeBegin != probes)
        throw world::Error(at + "probes [" + std::to_string(d.probeBegin) + ", " +
                           std::to_string(d.probeEnd) + ") but the probe section holds " +
                           std::to_string(probes) + "; expected as many as the range");
    if (d.reserved != 0)
        throw world::Error(at + "reserved = " + std::to_string(d.reserved) + "; expected 0");
    return fromDisk(d);
}

/// The baked sections among a package's sections, each at most once (probes are found by
/// decodeProbeSection).
struct BakedSectionSet {
    const RawSection *texels = nullptr, *masks = nullptr, *grid = nullptr, *imported = nullptr,
                     *visibility = nullptr, *budget = nullptr, *shardRange = nullptr;
};

BakedSectionSet findBakedSections(std::span<const RawSection> sections, const std::string& name) {
    BakedSectionSet set;
    for (const RawSection& s : sections) {
        const RawSection** slot = s.id == kSectionLightmapTexels     ? &set.texels
                                  : s.id == kSectionShadowMasks      ? &set.masks
                                  : s.id == kSectionLightGrid        ? &set.grid
                                  : s.id == kSectionImportedLightmap ? &set.imported
                                  : s.id == kSectionVisibility       ? &set.visibility
                                  : s.id == kSectionErrorBudget      ? &set.budget
                                  : s.id == kSectionShardRange       ? &set.shardRange
                                                                     : nullptr;
        if (!slot) continue;
        if (*slot)
            throw world::Error(name + ": section " + std::to_string(s.id) + " appears twice");
        *slot = &s;
    }
    return set;
}

/// Whether the package holds baked lighting: all of sections 32..34 or none, and the sections
/// that only come with them (35 probes, 36, 37, 39, 40) only with them.
bool hasBakedLighting(const BakedSectionSet& set, std::span<const RawSection> sections,
                      const std::string& name) {
    if (!set.texels && !set.masks && !set.grid) {
        for (const RawSection& s : sections)
            if (s.id == kSectionProbes || s.id == kSectionImportedLightmap ||
                s.id == kSectionVisibility || s.id == kSectionErrorBudget ||
                s.id == kSectionShardRange)
                throw world::Error(name + ": section " +
                                   (s.id == kSectionProbes        ? "probes"
                                    : s.id == kSectionVisibility  ? "visibility"
                                    : s.id == kSectionErrorBudget ? "error_budget"
                                    : s.id == kSectionShardRange  ? "shard_range"
                                                                  : "imported_lightmap") +
                                   " present without baked lighting; expected "
                                   "sections lightmap_texels, shadow_masks and light_grid too");
        return false;
    }
    if (!set.texels || !set.masks || !set.grid)
        throw world::Error(name + ": baked lighting incomplete: sections lightmap_texels " +
                           (set.texels ? "present" : "missing") + ", shadow_masks " +
                           (set.masks ? "present" : "missing") + ", light_grid " +
                           (set.grid ? "present" : "missing") + "; expected all three or none");
    return true;
}

}  // namespace

BakedContents decodeBakedSections(std::span<const RawSection> sections,
                                  const world::CompiledLevel& level, const std::string& name) {
    BakedContents result;
    const BakedSectionSet set = findBakedSections(sections, name);
    result.present = hasBakedLighting(set, sections, name);
    if (!result.present) return result;
    uint64_t atlasTexels = 0;
    for (const world::Atlas& a : level.atlases) atlasTexels += uint64_t(a.width) * a.height;

    world::BakedLighting& baked = result.baked;
    baked.texels = decodeLightmapTexels(*set.texels, atlasTexels, name);
    if (set.imported)
        baked.importedTexels = decodeImportedLightmap(*set.imported, baked.texels, name);
    baked.shadowMask = decodeShadowMasks(*set.masks, atlasTexels, name);
    decodeLightGrid(*set.grid, level, name, baked);
    // Environment probes (optional: only levels with glossy materials have them).
    baked.probes = decodeProbeSection(sections, level, name).probes;
    if (set.visibility) baked.visibility = decodeVisibilitySection(*set.visibility, level, name);
    if (set.budget) baked.budget = decodeBudgetSection(*set.budget, baked.grid.cells.size(), name);
    if ((baked.shardCount > 1) != (set.shardRange != nullptr))
        throw world::Error(name + ": section shard_range " +
                           (set.shardRange ? "present" : "missing") + " with light_grid's shard " +
                           std::to_string(baked.shardIndex) + "/" +
                           std::to_string(baked.shardCount) +
                           "; expected it in an unmerged part (shard count > 1) only");
    if (set.shardRange)
        baked.shardRange = decodeShardRange(*set.shardRange, level.charts.size(),
                                            baked.grid.cells.size(), baked.probes.size(), name);
    return result;
}

}  // namespace onelight::package
