#include "bake/shard_plan.hpp"

#include <algorithm>

#include "bake/lighting/direct_light.hpp"

namespace onelight::bake {
namespace {

/// Shadow-ray terms a point pays for: estimateVisibilities spends S rays on each of at most 8
/// lights, and about 2 x 8 S over more (direct_light.hpp).
constexpr uint32_t kShadowTermCap = 16;

// Measured costs, seconds on one core (shard_plan.hpp).
constexpr double kTexelPathSeconds = 1.5e-6;
constexpr double kCellPathSeconds = 0.45e-6;
constexpr double kShadowRaySeconds = 0.1e-6;
constexpr double kProbePathSeconds = 1.9e-6;
constexpr double kUncachedPathFactor = 2.0;

}  // namespace

uint32_t lightsReaching(const BakeLights& lights, const glm::vec3& position) {
    const auto near = static_cast<uint32_t>(lightsNear(lights, position).size());
    return near + (lights.emitters.triangles.empty() ? 0u : 1u);
}

ShardCosts estimateShardCosts(const BakeLights& lights, const world::CompiledLevel& level,
                              const std::vector<TexelSample>& samples, const world::LightGrid& grid,
                              size_t probes, const LightmapSettings& lightmap,
                              const GridSettings& gridSettings, const ProbeCaptureSettings& probe) {
    ShardCosts costs;
    const double path = lightmap.bouncePasses > 0 ? 1.0 : kUncachedPathFactor;
    costs.charts.assign(level.charts.size(), 0.0);
    for (const TexelSample& s : samples) {
        const uint32_t chart =
            s.surface < level.surfaces.size() ? level.surfaces[s.surface].chart : world::kNoIndex;
        if (chart < costs.charts.size())
            costs.charts[chart] += lightmap.indirectSamples * path * kTexelPathSeconds;
    }
    costs.cells.resize(grid.cells.size());
    for (size_t i = 0; i < grid.cells.size(); ++i) {
        const double terms =
            std::min(lightsReaching(lights, world::lightGridCellCentre(grid, i)), kShadowTermCap);
        costs.cells[i] = gridSettings.samples * path * kCellPathSeconds +
                         gridSettings.shadowSamples * terms * kShadowRaySeconds;
    }
    costs.probes.assign(probes, 6.0 * double(probe.faceSize) * probe.faceSize *
                                    double(probe.samplesPerTexel) * kProbePathSeconds);
    return costs;
}

world::ShardRange shardRange(const ShardCosts& costs, uint32_t index, uint32_t count) {
    const size_t charts = costs.charts.size(), cells = costs.cells.size(),
                 probes = costs.probes.size(), items = charts + cells + probes;
    // prefix[k]: the cost of the items before k, charts then cells then probes.
    std::vector<double> prefix(items + 1, 0.0);
    for (size_t k = 0; k < items; ++k) {
        const double c = k < charts           ? costs.charts[k]
                         : k < charts + cells ? costs.cells[k - charts]
                                              : costs.probes[k - charts - cells];
        prefix[k + 1] = prefix[k] + c;
    }
    const double total = prefix[items];
    // The first item of part i: where the running cost reaches i / count of the total.
    auto cut = [&](uint32_t i) -> size_t {
        if (i == 0) return 0;
        if (i >= count) return items;
        if (!(total > 0.0)) return size_t(uint64_t(items) * i / count);
        const double target = total * double(i) / double(count);
        return size_t(std::lower_bound(prefix.begin(), prefix.end(), target) - prefix.begin());
    };
    const size_t begin = std::min(cut(index), items), end = std::min(cut(index + 1), items);
    auto within = [](size_t k, size_t first, size_t size) -> uint64_t {
        return k <= first ? 0 : std::min(k - first, size);
    };
    world::ShardRange r;
    r.chartBegin = within(begin, 0, charts);
    r.chartEnd = within(end, 0, charts);
    r.cellBegin = within(begin, charts, cells);
    r.cellEnd = within(end, charts, cells);
    r.probeBegin = within(begin, charts + cells, probes);
    r.probeEnd = within(end, charts + cells, probes);
    r.probeTotal = probes;
    return r;
}

double shardCost(const ShardCosts& costs, const world::ShardRange& range) {
    double sum = 0.0;
    for (uint64_t c = range.chartBegin; c < range.chartEnd && c < costs.charts.size(); ++c)
        sum += costs.charts[c];
    for (uint64_t c = range.cellBegin; c < range.cellEnd && c < costs.cells.size(); ++c)
        sum += costs.cells[c];
    for (uint64_t p = range.probeBegin; p < range.probeEnd && p < costs.probes.size(); ++p)
        sum += costs.probes[p];
    return sum;
}

std::vector<uint32_t> samplesOfRange(const world::CompiledLevel& level,
                                     const std::vector<TexelSample>& samples,
                                     const world::ShardRange& range) {
    std::vector<uint32_t> owned;
    for (uint32_t i = 0; i < samples.size(); ++i) {
        const uint32_t surface = samples[i].surface;
        const uint32_t chart =
            surface < level.surfaces.size() ? level.surfaces[surface].chart : world::kNoIndex;
        if (chart >= range.chartBegin && chart < range.chartEnd) owned.push_back(i);
    }
    return owned;
}

}  // namespace onelight::bake
