#include "bake/bake_level.hpp"

#include <chrono>
#include <stdexcept>

#include <tbb/global_control.h>

#include "bake/dominant/dominant_primary.hpp"
#include "bake/embree/bake_scene.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "bake/probes/probe_placement.hpp"
#include "world/compile/static_split.hpp"
#include "world/error.hpp"
#include "world/light_grid_sample.hpp"
#include "world/package/baked_sections.hpp"
#include "world/package/package_writer.hpp"

namespace onelight::bake {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Shadow rays per primary per point for the region splitter: it only ranks lights, and it
/// runs at many points, so fewer than the lightmaps.
constexpr uint32_t kDominantShadowSamples = 8;

}  // namespace

const char* quality_name(BakeQuality quality) {
    switch (quality) {
        case BakeQuality::draft:
            return "draft";
        case BakeQuality::high:
            return "high";
        default:
            return "default";
    }
}

bool parse_quality(const std::string& text, BakeQuality& quality) {
    if (text == "draft")
        quality = BakeQuality::draft;
    else if (text == "default")
        quality = BakeQuality::normal;
    else if (text == "high")
        quality = BakeQuality::high;
    else
        return false;
    return true;
}

LightmapSettings lightmap_settings(const BakeOptions& options) {
    LightmapSettings s;
    switch (options.quality) {
        case BakeQuality::draft:
            s.shadow_samples = 8;
            s.indirect_samples = 128;
            break;
        case BakeQuality::normal:
            s.shadow_samples = 16;
            s.indirect_samples = 512;
            break;
        case BakeQuality::high:
            s.shadow_samples = 32;
            s.indirect_samples = 2048;
            break;
    }
    if (options.shadow_samples) s.shadow_samples = options.shadow_samples;
    if (options.indirect_samples) s.indirect_samples = options.indirect_samples;
    return s;
}

GridSettings grid_settings(const BakeOptions& options) {
    GridSettings g;
    const LightmapSettings l = lightmap_settings(options);
    g.cell_size = options.grid_cell_size;
    g.shadow_samples = l.shadow_samples;
    g.samples = options.grid_samples ? options.grid_samples : l.indirect_samples;
    return g;
}

ProbeCaptureSettings probe_settings(const BakeOptions& options) {
    ProbeCaptureSettings p;
    switch (options.quality) {
        case BakeQuality::draft:
            p.faceSize = 32;
            p.samplesPerTexel = 16;
            break;
        case BakeQuality::normal:
            p.faceSize = 64;
            p.samplesPerTexel = 64;
            break;
        case BakeQuality::high:
            p.faceSize = 128;
            p.samplesPerTexel = 256;
            break;
    }
    if (options.probe_face_size) p.faceSize = options.probe_face_size;
    if (options.probe_samples) p.samplesPerTexel = options.probe_samples;
    return p;
}

ShardRange shard_range(uint64_t texels, uint64_t cells, uint64_t probes, uint32_t index,
                       uint32_t count) {
    ShardRange r;
    r.probe_begin = probes * index / count;
    r.probe_end = probes * (index + 1) / count;
    r.texel_begin = texels * index / count;
    r.texel_end = texels * (index + 1) / count;
    r.cell_begin = cells * index / count;
    r.cell_end = cells * (index + 1) / count;
    return r;
}

BakeResult bake_level(const world::SourceLevel& source, const BakeOptions& options) {
    if (options.shard_count == 0 || options.shard_index >= options.shard_count)
        throw std::runtime_error("shard " + std::to_string(options.shard_index) + "/" +
                                 std::to_string(options.shard_count) + "; expected index < count");
    BakeResult result;
    BakeReport& report = result.report;
    report.level = source.source_path;
    report.quality = quality_name(options.quality);
    report.threads = static_cast<uint32_t>(
        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
    report.shard_index = options.shard_index;
    report.shard_count = options.shard_count;

    // 1. The Embree scene of the static world, shared by every stage.
    auto start = std::chrono::steady_clock::now();
    const EmbreeDevice device;
    const world::SplitLevel split = world::split_static_dynamic(source);
    const BakeScene scene(device, split.static_geometry, source.materials);
    const BakeLights lights = make_bake_lights(source.lights, options.light_sizes,
                                               options.sky_radiance.value_or(source.sky_radiance));
    report.stages.push_back({"scene", seconds_since(start), {}, scene.triangle_count()});
    report.triangles = scene.triangle_count();

    // 2. World compile; its region splitter asks the shadowed dominant primary.
    start = std::chrono::steady_clock::now();
    AtomicRayCount dominant_rays;
    const world::PrimaryIlluminanceFn dominant =
        make_shadowed_primary_illuminance(scene, lights, kDominantShadowSamples, &dominant_rays);
    {
        Progress progress("compile", 1, options.show_progress);
        world::CompileResult compiled = world::compile_level(source, options.compile, &dominant);
        result.level = std::move(compiled.level);
        result.compile_stats = compiled.stats;
        progress.advance(1);
    }
    StageReport compile_stage{"compile", seconds_since(start), {}, result.level.surfaces.size()};
    compile_stage.rays.shadow = dominant_rays.shadow.load();
    report.stages.push_back(compile_stage);
    const world::CompiledLevel& level = result.level;

    // 3. Lightmaps.
    const LightmapSettings lm = lightmap_settings(options);
    const std::vector<TexelSample> samples = place_texels(level);
    const uint64_t texel_count = total_texels(level);
    world::LightGrid grid = layout_light_grid(level, grid_settings(options));
    const world::LightGrid grid_layout = grid;
    const std::vector<ProbePlacement> placements =
        placeProbes(level, scene, ProbePlacementSettings{options.probe_spacing});
    for (const ProbePlacement& p : placements)
        if (p.insideSolid)
            report.warnings.push_back(
                "probe '" +
                (p.entity < level.entities.size() ? level.entities[p.entity].name : "placed") +
                "' at (" + std::to_string(p.position.x) + ", " + std::to_string(p.position.y) +
                ", " + std::to_string(p.position.z) +
                ") is inside solid geometry: its reflections will be dark; move it into the open");
    const ShardRange range = shard_range(texel_count, grid.cells.size(), placements.size(),
                                         options.shard_index, options.shard_count);
    world::BakedLighting& baked = result.baked;
    baked.texels.assign(texel_count, world::LightmapTexel{});
    baked.shadow_mask.assign(texel_count, 0);
    baked.shard_index = options.shard_index;
    baked.shard_count = options.shard_count;
    start = std::chrono::steady_clock::now();
    {
        uint64_t work = 0;
        for (const TexelSample& s : samples)
            work += s.texel >= range.texel_begin && s.texel < range.texel_end;
        Progress progress("lightmaps", work, options.show_progress);
        const LightmapStats stats =
            bake_lightmap_texels(scene, lights, level, samples, lm, range.texel_begin,
                                 range.texel_end, baked, &progress);
        progress.finish();
        report.stages.push_back(
            {"lightmaps", seconds_since(start), stats.rays, stats.texels_baked});
        report.texels_sampled = stats.texels_baked;
        report.texels_moved = stats.texels_moved;
        report.lightmap_mean_relative_noise = stats.mean_relative_noise;
    }
    report.texels_total = texel_count;
    report.shadow_samples_per_light = lm.shadow_samples;
    report.indirect_samples_per_texel = lm.indirect_samples;

    // 4. Light grid.
    start = std::chrono::steady_clock::now();
    {
        const GridSettings gs = grid_settings(options);
        Progress progress("grid", range.cell_end - range.cell_begin, options.show_progress);
        const GridStats stats =
            bake_light_grid(scene, lights, gs, range.cell_begin, range.cell_end, grid, &progress);
        progress.finish();
        report.stages.push_back({"grid", seconds_since(start), stats.rays, stats.cells_baked});
        report.grid_cells = grid.cells.size();
        report.grid_cells_inside = stats.cells_inside;
        report.grid_samples_per_cell = gs.samples;
    }
    baked.grid = std::move(grid);

    // 5. Environment probes (only where the level has them: placeProbes decides).
    start = std::chrono::steady_clock::now();
    if (!placements.empty()) {
        const ProbeCaptureSettings ps = probe_settings(options);
        RayCounts rays;
        const std::vector<glm::vec3> average = probe_average_irradiance(
            scene, lights, grid_settings(options), grid_layout, placements, rays);
        baked.probes = bakeProbes(scene, lights, placements, average, ps, range.probe_begin,
                                  range.probe_end, options.show_progress, rays);
        report.stages.push_back({"probes", seconds_since(start), rays, baked.probes.size()});
        report.probes_total = placements.size();
        report.probes_baked = baked.probes.size();
        report.probe_face_size = ps.faceSize;
        report.probe_samples_per_texel = ps.samplesPerTexel;
        if (!baked.probes.empty())
            report.probe_bytes = package::encode_probe_section(baked.probes).bytes.size();
    }

    // 6. Finish (a whole bake only; parts are finished by merge).
    start = std::chrono::steady_clock::now();
    if (options.shard_count == 1) finish_baked_lighting(level, baked);
    report.stages.push_back({"dilate", seconds_since(start), {}, texel_count});
    report.peak_memory_bytes = peak_memory_bytes();
    return result;
}

std::vector<glm::vec3> probe_average_irradiance(const BakeScene& scene, const BakeLights& lights,
                                                const GridSettings& settings,
                                                const world::LightGrid& layout,
                                                const std::vector<ProbePlacement>& probes,
                                                RayCounts& rays) {
    std::vector<glm::vec3> average(probes.size(), glm::vec3(0.0f));
    if (layout.cells.empty()) return average;
    world::LightGrid scratch = layout;
    std::vector<uint8_t> baked(scratch.cells.size(), 0);
    for (size_t i = 0; i < probes.size(); ++i) {
        const world::LightGridSample corners = world::sampleLightGrid(scratch, probes[i].position);
        for (size_t k = 0; k < corners.cells.size(); ++k) {
            const uint32_t c = corners.cells[k];
            if (corners.weights[k] <= 0.0f || baked[c]) continue;
            rays += bake_light_grid(scene, lights, settings, c, c + 1, scratch, nullptr).rays;
            baked[c] = 1;
        }
        average[i] =
            ambientCubeAverage(world::sampleLightGrid(scratch, probes[i].position).ambientCube);
    }
    return average;
}

void finish_baked_lighting(const world::CompiledLevel& level, world::BakedLighting& baked) {
    dilate_lightmaps(level, baked);
    baked.shard_index = 0;
    baked.shard_count = 1;
}

world::BakedLighting merge_baked_lighting(const world::CompiledLevel& level,
                                          std::vector<world::BakedLighting> parts) {
    if (parts.empty()) throw world::Error("merge: no parts given");
    const uint32_t count = parts[0].shard_count;
    if (parts.size() != count)
        throw world::Error("merge: " + std::to_string(parts.size()) +
                           " parts given; the first is a part of " + std::to_string(count));
    std::vector<const world::BakedLighting*> by_index(count, nullptr);
    const uint64_t texels = total_texels(level);
    for (const world::BakedLighting& p : parts) {
        if (p.shard_count != count || p.shard_index >= count)
            throw world::Error("merge: a part is shard " + std::to_string(p.shard_index) + "/" +
                               std::to_string(p.shard_count) + "; expected a part of " +
                               std::to_string(count));
        if (by_index[p.shard_index])
            throw world::Error("merge: shard " + std::to_string(p.shard_index) + " given twice");
        if (p.texels.size() != texels || p.shadow_mask.size() != texels ||
            p.grid.cells.size() != parts[0].grid.cells.size() || p.grid.dims != parts[0].grid.dims)
            throw world::Error("merge: shard " + std::to_string(p.shard_index) +
                               " does not match the level (texel or grid cell counts differ)");
        by_index[p.shard_index] = &p;
    }
    world::BakedLighting merged = parts[0];
    for (uint32_t i = 0; i < count; ++i) {
        const world::BakedLighting& p = *by_index[i];
        const ShardRange r = shard_range(texels, p.grid.cells.size(), 0, i, count);
        for (uint64_t t = r.texel_begin; t < r.texel_end; ++t) {
            merged.texels[t] = p.texels[t];
            merged.shadow_mask[t] = p.shadow_mask[t];
        }
        for (uint64_t c = r.cell_begin; c < r.cell_end; ++c) merged.grid.cells[c] = p.grid.cells[c];
    }
    // Each part holds its contiguous range of the probes: in shard order they are the whole list.
    merged.probes.clear();
    for (uint32_t i = 0; i < count; ++i)
        merged.probes.insert(merged.probes.end(), by_index[i]->probes.begin(),
                             by_index[i]->probes.end());
    finish_baked_lighting(level, merged);
    return merged;
}

std::vector<uint8_t> package_bytes(const world::CompiledLevel& level,
                                   const world::BakedLighting& baked) {
    const std::vector<package::RawSection> sections = package::encode_baked_sections(baked);
    return package::serialize_package(level, sections);
}

}  // namespace onelight::bake
