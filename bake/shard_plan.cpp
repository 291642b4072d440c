#include "bake/shard_plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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

/// Spreads the low 21 bits of v to every third bit.
uint64_t spreadBits(uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffull;
    v = (v | v << 16) & 0x1f0000ff0000ffull;
    v = (v | v << 8) & 0x100f00f00f00f00full;
    v = (v | v << 4) & 0x10c30c30c30c30c3ull;
    v = (v | v << 2) & 0x1249249249249249ull;
    return v;
}

}  // namespace

std::vector<uint32_t> chartSpaceOrder(const world::CompiledLevel& level) {
    const size_t charts = level.charts.size();
    const double infinity = std::numeric_limits<double>::infinity();
    std::vector<glm::dvec3> low(charts, glm::dvec3(infinity)), high(charts, glm::dvec3(-infinity));
    glm::dvec3 levelLow(infinity), levelHigh(-infinity);
    for (const world::Surface& s : level.surfaces) {
        if (s.chart >= charts) continue;
        low[s.chart] = glm::min(low[s.chart], glm::dvec3(s.boundsMin));
        high[s.chart] = glm::max(high[s.chart], glm::dvec3(s.boundsMax));
        levelLow = glm::min(levelLow, glm::dvec3(s.boundsMin));
        levelHigh = glm::max(levelHigh, glm::dvec3(s.boundsMax));
    }
    // Each chart's centre, quantised to 21 bits per axis of the level's bounds; a chart without
    // a surface (or with bounds that are not finite) sorts first.
    const glm::dvec3 extent = levelHigh - levelLow;
    std::vector<std::pair<uint64_t, uint32_t>> keys(charts);
    for (uint32_t c = 0; c < charts; ++c) {
        uint64_t code = 0;
        const glm::dvec3 centre = 0.5 * (low[c] + high[c]);
        for (int axis = 0; axis < 3; ++axis) {
            const double t =
                extent[axis] > 0.0 ? (centre[axis] - levelLow[axis]) / extent[axis] : 0.0;
            const double clamped = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
            code |= spreadBits(uint64_t(clamped * double(0x1fffff))) << axis;
        }
        keys[c] = {code, c};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<uint32_t> order(charts);
    for (uint32_t k = 0; k < charts; ++k) order[k] = keys[k].second;
    return order;
}

uint32_t lightsReaching(const BakeLights& lights, const glm::vec3& position) {
    const auto near = static_cast<uint32_t>(lightsNear(lights, position).size());
    return near + (lights.emitters.triangles.empty() ? 0u : 1u);
}

ShardCosts estimateShardCosts(const BakeLights& lights, const world::CompiledLevel& level,
                              const std::vector<uint32_t>& chartOrder,
                              const std::vector<TexelSample>& samples, const world::LightGrid& grid,
                              size_t probes, const LightmapSettings& lightmap,
                              const GridSettings& gridSettings, const ProbeCaptureSettings& probe) {
    ShardCosts costs;
    const double path = lightmap.bouncePasses > 0 ? 1.0 : kUncachedPathFactor;
    std::vector<double> byChart(level.charts.size(), 0.0);
    for (const TexelSample& s : samples) {
        const uint32_t chart =
            s.surface < level.surfaces.size() ? level.surfaces[s.surface].chart : world::kNoIndex;
        if (chart < byChart.size())
            byChart[chart] += lightmap.indirectSamples * path * kTexelPathSeconds;
    }
    for (const uint32_t chart : chartOrder)
        costs.charts.push_back(chart < byChart.size() ? byChart[chart] : 0.0);
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
                                     const std::vector<uint32_t>& chartOrder,
                                     const std::vector<TexelSample>& samples,
                                     const world::ShardRange& range) {
    std::vector<uint8_t> inRange(level.charts.size(), 0);
    for (uint64_t k = range.chartBegin; k < range.chartEnd && k < chartOrder.size(); ++k)
        if (chartOrder[k] < inRange.size()) inRange[chartOrder[k]] = 1;
    std::vector<uint32_t> owned;
    for (uint32_t i = 0; i < samples.size(); ++i) {
        const uint32_t surface = samples[i].surface;
        const uint32_t chart =
            surface < level.surfaces.size() ? level.surfaces[surface].chart : world::kNoIndex;
        if (chart < inRange.size() && inRange[chart]) owned.push_back(i);
    }
    return owned;
}

}  // namespace onelight::bake
