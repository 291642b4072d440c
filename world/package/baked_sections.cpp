#include "world/package/baked_sections.hpp"

#include <cmath>
#include <cstring>

#include "world/error.hpp"
#include "world/package/format.hpp"
#include "world/package/probe_section.hpp"
#include "world/package/records.hpp"

namespace onelight::package {
namespace {

template <class T>
void append_bytes(std::vector<uint8_t>& out, const T& value) {
    const auto* p = reinterpret_cast<const uint8_t*>(&value);
    out.insert(out.end(), p, p + sizeof(T));
}

template <class T>
T read_record(const std::vector<uint8_t>& bytes, size_t offset) {
    T value;
    std::memcpy(&value, bytes.data() + offset, sizeof(T));
    return value;
}

/// Throws unless every element of the array field `name` is finite and >= 0; `at` names the
/// record.
template <size_t N>
void check_finite_non_negative(const std::string& at, const std::string& name,
                               const float (&v)[N]) {
    for (size_t k = 0; k < N; ++k)
        if (!std::isfinite(v[k]) || v[k] < 0.0f)
            throw world::Error(at + name + "[" + std::to_string(k) + "] = " + std::to_string(v[k]) +
                               ": not finite or negative");
}

/// Throws when a lightmap texel is not one a bake can write; `at` names the record.
void check(const DiskLightmapTexel& d, const std::string& at) {
    check_finite_non_negative(at, "irradiance", d.irradiance);
    const float length =
        std::sqrt(d.direction[0] * d.direction[0] + d.direction[1] * d.direction[1] +
                  d.direction[2] * d.direction[2]);
    if (!(length <= 0.5f + 1e-4f))
        throw world::Error(at + "direction length " + std::to_string(length) + " > 0.5");
    if (!(d.normal_weight >= 0.5f - 1e-4f && d.normal_weight <= 1.0f + 1e-4f))
        throw world::Error(at + "normal_weight " + std::to_string(d.normal_weight) +
                           " outside [0.5, 1]");
    if (d.flags & ~kAllLightmapTexelFlags)
        throw world::Error(at + "flags " + std::to_string(d.flags) + " has unknown bits");
}

/// Throws when a light grid cell is not one a bake of `level` can write; `at` names the record.
void check(const DiskLightGridCell& d, const world::CompiledLevel& level, const std::string& at) {
    for (int f = 0; f < 6; ++f)
        check_finite_non_negative(at, "ambient_cube[" + std::to_string(f) + "]", d.ambient_cube[f]);
    if (d.dominant_primary != kNoIndex &&
        (d.dominant_primary >= level.lights.size() ||
         level.lights[d.dominant_primary].role != world::LightRole::primary))
        throw world::Error(at + "dominant_primary " + std::to_string(d.dominant_primary) +
                           " is not a primary light of " + std::to_string(level.lights.size()));
    if (!(d.primary_visibility >= 0.0f && d.primary_visibility <= 1.0f))
        throw world::Error(at + "primary_visibility " + std::to_string(d.primary_visibility) +
                           " outside [0, 1]");
    if (d.flags & ~kAllLightGridCellFlags)
        throw world::Error(at + "flags " + std::to_string(d.flags) + " has unknown bits");
}

std::string where(const std::string& name, const char* section, uint64_t record) {
    return name + ": section " + section + ", record " + std::to_string(record) + ": ";
}

}  // namespace

std::vector<RawSection> encode_baked_sections(const world::BakedLighting& baked) {
    std::vector<RawSection> out(3);
    RawSection& texels = out[0];
    texels.id = section_lightmap_texels;
    texels.element_size = sizeof(DiskLightmapTexel);
    texels.count = static_cast<uint32_t>(baked.texels.size());
    texels.bytes.reserve(baked.texels.size() * sizeof(DiskLightmapTexel));
    for (const world::LightmapTexel& t : baked.texels) append_bytes(texels.bytes, to_disk(t));
    RawSection& masks = out[1];
    masks.id = section_shadow_masks;
    masks.element_size = 1;
    masks.count = static_cast<uint32_t>(baked.shadow_mask.size());
    masks.bytes = baked.shadow_mask;

    RawSection& grid = out[2];
    grid.id = section_light_grid;
    grid.element_size = 1;
    append_bytes(grid.bytes, to_disk_grid_header(baked));
    for (const world::LightGridCell& cell : baked.grid.cells)
        append_bytes(grid.bytes, to_disk(cell));
    grid.count = static_cast<uint32_t>(grid.bytes.size());
    if (!baked.probes.empty()) out.push_back(encode_probe_section(baked.probes));
    return out;
}

BakedContents decode_baked_sections(std::span<const RawSection> sections,
                                    const world::CompiledLevel& level, const std::string& name) {
    BakedContents result;
    const RawSection *texels = nullptr, *masks = nullptr, *grid = nullptr;
    for (const RawSection& s : sections) {
        const RawSection** slot = s.id == section_lightmap_texels ? &texels
                                  : s.id == section_shadow_masks  ? &masks
                                  : s.id == section_light_grid    ? &grid
                                                                  : nullptr;
        if (!slot) continue;
        if (*slot) {
            throw world::Error(name + ": section " + std::to_string(s.id) + " appears twice");
        }
        *slot = &s;
    }
    if (!texels && !masks && !grid) {
        for (const RawSection& s : sections)
            if (s.id == section_probes)
                throw world::Error(name +
                                   ": section probes present without baked lighting; expected "
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
    uint64_t expected_texels = 0;
    for (const world::Atlas& a : level.atlases) expected_texels += uint64_t(a.width) * a.height;

    // Lightmap texels.
    if (texels->element_size != sizeof(DiskLightmapTexel) ||
        texels->bytes.size() != uint64_t(texels->count) * sizeof(DiskLightmapTexel) ||
        texels->count != expected_texels) {
        throw world::Error(name + ": section lightmap_texels: element size " +
                           std::to_string(texels->element_size) + ", count " +
                           std::to_string(texels->count) + ", " +
                           std::to_string(texels->bytes.size()) + " bytes; expected element size " +
                           std::to_string(sizeof(DiskLightmapTexel)) + " and count " +
                           std::to_string(expected_texels) + " (the atlases' texels)");
    }
    world::BakedLighting& baked = result.baked;
    baked.texels.resize(texels->count);
    for (uint32_t i = 0; i < texels->count; ++i) {
        const auto d =
            read_record<DiskLightmapTexel>(texels->bytes, size_t(i) * sizeof(DiskLightmapTexel));
        check(d, where(name, "lightmap_texels", i));
        baked.texels[i] = from_disk(d);
    }

    // Shadow masks.
    if (masks->element_size != 1 || masks->bytes.size() != masks->count ||
        masks->count != expected_texels) {
        throw world::Error(name + ": section shadow_masks: element size " +
                           std::to_string(masks->element_size) + ", count " +
                           std::to_string(masks->count) + "; expected element size 1 and count " +
                           std::to_string(expected_texels));
    }
    baked.shadow_mask = masks->bytes;

    // Light grid.
    if (grid->element_size != 1 || grid->bytes.size() != grid->count ||
        grid->bytes.size() < sizeof(DiskLightGridHeader)) {
        throw world::Error(name + ": section light_grid: " + std::to_string(grid->bytes.size()) +
                           " bytes; expected a header of " +
                           std::to_string(sizeof(DiskLightGridHeader)) + " bytes and cells");
    }
    const auto h = read_record<DiskLightGridHeader>(grid->bytes, 0);
    const uint64_t cells = uint64_t(h.dims[0]) * h.dims[1] * h.dims[2];
    const uint64_t expected_bytes =
        sizeof(DiskLightGridHeader) + uint64_t(h.cell_count) * sizeof(DiskLightGridCell);
    if (cells != h.cell_count || grid->bytes.size() != expected_bytes) {
        throw world::Error(name + ": section light_grid: dims " + std::to_string(h.dims[0]) + "x" +
                           std::to_string(h.dims[1]) + "x" + std::to_string(h.dims[2]) +
                           ", cell_count " + std::to_string(h.cell_count) + ", " +
                           std::to_string(grid->bytes.size()) +
                           " bytes; expected cell_count == " + std::to_string(cells) + " and " +
                           std::to_string(expected_bytes) + " bytes");
    }
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(h.origin[c]) || !std::isfinite(h.cell_size[c]) ||
            !(h.cell_size[c] > 0.0f)) {
            throw world::Error(name + ": section light_grid: header origin/cell_size[" +
                               std::to_string(c) + "] = " + std::to_string(h.origin[c]) + "/" +
                               std::to_string(h.cell_size[c]) + "; expected finite, size > 0");
        }
    }
    if (h.shard_count == 0 || h.shard_index >= h.shard_count) {
        throw world::Error(name + ": section light_grid: shard " + std::to_string(h.shard_index) +
                           "/" + std::to_string(h.shard_count) + "; expected index < count");
    }
    from_disk_grid_header(h, baked);
    baked.grid.cells.resize(h.cell_count);
    for (uint32_t i = 0; i < h.cell_count; ++i) {
        const auto d = read_record<DiskLightGridCell>(
            grid->bytes, sizeof(DiskLightGridHeader) + size_t(i) * sizeof(DiskLightGridCell));
        check(d, level, where(name, "light_grid cells", i));
        baked.grid.cells[i] = from_disk(d);
    }

    // Environment probes (optional: only levels with glossy materials have them).
    baked.probes = decode_probe_section(sections, level, name).probes;
    return result;
}

}  // namespace onelight::package
