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

/// The texels of a section whose sizes were checked, each record checked.
std::vector<world::LightmapTexel> decodeTexels(const RawSection& s, const std::string& name,
                                               const char* section) {
    std::vector<world::LightmapTexel> texels(s.count);
    for (uint32_t i = 0; i < s.count; ++i) {
        const auto d =
            readRecord<DiskLightmapTexel>(s.bytes, size_t(i) * sizeof(DiskLightmapTexel));
        check(d, where(name, section, i));
        texels[i] = fromDisk(d);
    }
    return texels;
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
            appendBytes(imported.bytes,
                        DiskImportedTexel{{t.irradiance.x, t.irradiance.y, t.irradiance.z}});
        out.push_back(std::move(imported));
    }
    if (!baked.visibility.empty()) out.push_back(encodeVisibilitySection(baked.visibility));
    if (baked.budget.budget > 0.0f) out.push_back(encodeBudgetSection(baked.budget));
    if (baked.shardCount > 1) {
        const world::ShardRange& r = baked.shardRange;
        RawSection range;
        range.id = kSectionShardRange;
        range.elementSize = sizeof(DiskShardRange);
        range.count = 1;
        appendBytes(range.bytes, DiskShardRange{r.chartBegin, r.chartEnd, r.cellBegin, r.cellEnd,
                                                r.probeBegin, r.probeEnd, r.probeTotal, 0});
        out.push_back(std::move(range));
    }
    return out;
}

namespace {

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
    return {d.chartBegin, d.chartEnd, d.cellBegin, d.cellEnd,
            d.probeBegin, d.probeEnd, d.probeTotal};
}

}  // namespace

BakedContents decodeBakedSections(std::span<const RawSection> sections,
                                  const world::CompiledLevel& level, const std::string& name) {
    BakedContents result;
    const RawSection *texels = nullptr, *masks = nullptr, *grid = nullptr, *imported = nullptr,
                     *visibility = nullptr, *budget = nullptr, *shardRange = nullptr;
    for (const RawSection& s : sections) {
        const RawSection** slot = s.id == kSectionLightmapTexels     ? &texels
                                  : s.id == kSectionShadowMasks      ? &masks
                                  : s.id == kSectionLightGrid        ? &grid
                                  : s.id == kSectionImportedLightmap ? &imported
                                  : s.id == kSectionVisibility       ? &visibility
                                  : s.id == kSectionErrorBudget      ? &budget
                                  : s.id == kSectionShardRange       ? &shardRange
                                                                     : nullptr;
        if (!slot) continue;
        if (*slot) {
            throw world::Error(name + ": section " + std::to_string(s.id) + " appears twice");
        }
        *slot = &s;
    }
    if (!texels && !masks && !grid) {
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
        return result;  // no baked lighting
    }
    if (!texels || !masks || !grid) {
        throw world::Error(name + ": baked lighting incomplete: sections lightmap_texels " +
                           (texels ? "present" : "missing") + ", shadow_masks " +
                           (masks ? "present" : "missing") + ", light_grid " +
                           (grid ? "present" : "missing") + "; expected all three or none");
    }
    result.present = true;
    uint64_t expectedTexels = 0;
    for (const world::Atlas& a : level.atlases) expectedTexels += uint64_t(a.width) * a.height;

    // Lightmap texels.
    if (texels->elementSize != sizeof(DiskLightmapTexel) ||
        texels->bytes.size() != uint64_t(texels->count) * sizeof(DiskLightmapTexel) ||
        texels->count != expectedTexels) {
        throw world::Error(name + ": section lightmap_texels: element size " +
                           std::to_string(texels->elementSize) + ", count " +
                           std::to_string(texels->count) + ", " +
                           std::to_string(texels->bytes.size()) + " bytes; expected element size " +
                           std::to_string(sizeof(DiskLightmapTexel)) + " and count " +
                           std::to_string(expectedTexels) + " (the atlases' texels)");
    }
    world::BakedLighting& baked = result.baked;
    baked.texels = decodeTexels(*texels, name, "lightmap_texels");
    if (imported) {
        if (imported->elementSize != sizeof(DiskImportedTexel) ||
            imported->bytes.size() != uint64_t(imported->count) * sizeof(DiskImportedTexel) ||
            imported->count != expectedTexels)
            throw world::Error(name + ": section imported_lightmap: element size " +
                               std::to_string(imported->elementSize) + ", count " +
                               std::to_string(imported->count) + "; expected element size " +
                               std::to_string(sizeof(DiskImportedTexel)) + " and count " +
                               std::to_string(expectedTexels) + " (the atlases' texels)");
        baked.importedTexels.resize(imported->count);
        for (uint32_t i = 0; i < imported->count; ++i) {
            const auto d = readRecord<DiskImportedTexel>(imported->bytes,
                                                         size_t(i) * sizeof(DiskImportedTexel));
            checkFiniteNonNegative(where(name, "imported_lightmap", i), "irradiance", d.irradiance);
            world::LightmapTexel& t = baked.importedTexels[i];
            t.irradiance = glm::vec3(d.irradiance[0], d.irradiance[1], d.irradiance[2]);
            t.direction = glm::vec3(0.0f);
            t.normalWeight = 0.5f;
            t.flags = baked.texels[i].flags;
        }
    }

    // Shadow masks.
    if (masks->elementSize != 1 || masks->bytes.size() != masks->count ||
        masks->count != expectedTexels) {
        throw world::Error(name + ": section shadow_masks: element size " +
                           std::to_string(masks->elementSize) + ", count " +
                           std::to_string(masks->count) + "; expected element size 1 and count " +
                           std::to_string(expectedTexels));
    }
    baked.shadowMask = masks->bytes;

    // Light grid.
    if (grid->elementSize != 1 || grid->bytes.size() != grid->count ||
        grid->bytes.size() < sizeof(DiskLightGridHeader)) {
        throw world::Error(name + ": section light_grid: " + std::to_string(grid->bytes.size()) +
                           " bytes; expected a header of " +
                           std::to_string(sizeof(DiskLightGridHeader)) + " bytes and cells");
    }
    const auto h = readRecord<DiskLightGridHeader>(grid->bytes, 0);
    for (int c = 0; c < 3; ++c)
        if (h.dims[c] < 1 || h.dims[c] > world::kMaxLightGridCellsPerAxis)
            throw world::Error(name + ": section light_grid: dims[" + std::to_string(c) +
                               "] = " + std::to_string(h.dims[c]) + "; expected 1.." +
                               std::to_string(world::kMaxLightGridCellsPerAxis) + " cells");
    // Each factor is at most 4096, so the product is exact in 64 bits.
    const uint64_t cells = uint64_t(h.dims[0]) * h.dims[1] * h.dims[2];
    if (cells > world::kMaxLightGridCells)
        throw world::Error(name + ": section light_grid: " + std::to_string(cells) +
                           " cells; expected at most " + std::to_string(world::kMaxLightGridCells));
    const uint64_t expectedBytes =
        sizeof(DiskLightGridHeader) + uint64_t(h.cellCount) * sizeof(DiskLightGridCell);
    if (cells != h.cellCount || grid->bytes.size() != expectedBytes) {
        throw world::Error(name + ": section light_grid: dims " + std::to_string(h.dims[0]) + "x" +
                           std::to_string(h.dims[1]) + "x" + std::to_string(h.dims[2]) +
                           ", cellCount " + std::to_string(h.cellCount) + ", " +
                           std::to_string(grid->bytes.size()) +
                           " bytes; expected cellCount == " + std::to_string(cells) + " and " +
                           std::to_string(expectedBytes) + " bytes");
    }
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(h.origin[c]) || !std::isfinite(h.cellSize[c]) ||
            !(h.cellSize[c] > 0.0f)) {
            throw world::Error(name + ": section light_grid: header origin/cellSize[" +
                               std::to_string(c) + "] = " + std::to_string(h.origin[c]) + "/" +
                               std::to_string(h.cellSize[c]) + "; expected finite, size > 0");
        }
    }
    if (h.shardCount == 0 || h.shardIndex >= h.shardCount) {
        throw world::Error(name + ": section light_grid: shard " + std::to_string(h.shardIndex) +
                           "/" + std::to_string(h.shardCount) + "; expected index < count");
    }
    fromDiskGridHeader(h, baked);
    baked.grid.cells.resize(h.cellCount);
    for (uint32_t i = 0; i < h.cellCount; ++i) {
        const auto d = readRecord<DiskLightGridCell>(
            grid->bytes, sizeof(DiskLightGridHeader) + size_t(i) * sizeof(DiskLightGridCell));
        check(d, level, where(name, "light_grid cells", i));
        baked.grid.cells[i] = fromDisk(d);
    }

    // Environment probes (optional: only levels with glossy materials have them).
    baked.probes = decodeProbeSection(sections, level, name).probes;
    if (visibility) baked.visibility = decodeVisibilitySection(*visibility, level, name);
    if (budget) baked.budget = decodeBudgetSection(*budget, baked.grid.cells.size(), name);
    if ((baked.shardCount > 1) != (shardRange != nullptr))
        throw world::Error(name + ": section shard_range " + (shardRange ? "present" : "missing") +
                           " with light_grid's shard " + std::to_string(baked.shardIndex) + "/" +
                           std::to_string(baked.shardCount) +
                           "; expected it in an unmerged part (shard count > 1) only");
    if (shardRange)
        baked.shardRange = decodeShardRange(*shardRange, level.charts.size(),
                                            baked.grid.cells.size(), baked.probes.size(), name);
    return result;
}

}  // namespace onelight::package
