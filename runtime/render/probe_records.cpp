#include "render/probe_records.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace onelight::render {
namespace {

bool hasBox(const world::EnvironmentProbe& p) {
    return p.boxMin.x < p.boxMax.x && p.boxMin.y < p.boxMax.y && p.boxMin.z < p.boxMax.z;
}

}  // namespace

ProbeRecords makeProbeRecords(const std::vector<world::EnvironmentProbe>& probes,
                              glm::vec3 levelMin, glm::vec3 levelMax) {
    std::vector<GpuProbe> byIndex(probes.size());
    std::vector<float> volume(probes.size());
    for (size_t i = 0; i < probes.size(); ++i) {
        const world::EnvironmentProbe& p = probes[i];
        GpuProbe& g = byIndex[i];
        g.position = glm::vec4(p.position, 0.0f);
        glm::vec3 lo, hi;
        float band;
        if (hasBox(p)) {
            lo = p.boxMin;
            hi = p.boxMax;
            const glm::vec3 extent = hi - lo;
            band = std::min(kMaxProbeBand, 0.1f * std::min({extent.x, extent.y, extent.z}));
            g.boxMin = glm::vec4(lo, 1.0f);
            g.boxMax = glm::vec4(hi, 0.0f);
        } else {
            float radius = 0.0f;
            for (size_t j = 0; j < probes.size(); ++j)
                if (j != i) {
                    const float d = glm::length(probes[j].position - p.position);
                    radius = radius == 0.0f ? d : std::min(radius, d);
                }
            if (probes.size() == 1) {
                const glm::vec3 far =
                    glm::max(glm::abs(levelMin - p.position), glm::abs(levelMax - p.position));
                radius = std::max({far.x, far.y, far.z}) * 2.0f;  // inside: weight 1 everywhere
            }
            radius = std::max(radius, kMinProbeRadius);
            lo = p.position - glm::vec3(radius);
            hi = p.position + glm::vec3(radius);
            band = probes.size() == 1 ? radius * 0.5f : radius;
            g.boxMin = glm::vec4(0.0f);
            g.boxMax = glm::vec4(0.0f);
        }
        g.influenceMin = glm::vec4(lo, band);
        g.influenceMax = glm::vec4(hi, 0.0f);
        for (size_t f = 0; f < 6; ++f)
            g.relativeIrradiance[f] = glm::vec4(p.irradianceCube[f] / p.irradianceAverage, 0.0f);
        const glm::vec3 e = hi - lo;
        volume[i] = e.x * e.y * e.z;
    }
    ProbeRecords out;
    out.order.resize(probes.size());
    std::iota(out.order.begin(), out.order.end(), 0u);
    std::stable_sort(out.order.begin(), out.order.end(),
                     [&](uint32_t a, uint32_t b) { return volume[a] < volume[b]; });
    for (uint32_t i : out.order) out.records.push_back(byIndex[i]);
    return out;
}

ProbeCells makeProbeCells(const std::vector<GpuProbe>& records, glm::vec3 levelMin,
                          glm::vec3 levelMax) {
    ProbeCells out;
    const glm::vec3 extent = levelMax - levelMin;
    const float longest = std::max({extent.x, extent.y, extent.z});
    if (records.size() <= kProbeGridMinRecords || !(longest > 0.0f) || !std::isfinite(longest)) {
        out.words = {0u};
        return out;
    }
    const float cell = longest / float(kProbeCellsPerAxis);
    const glm::vec3 margin = glm::vec3(0.5f * cell);
    const glm::vec3 origin = levelMin - margin;
    const glm::uvec3 dims = glm::min(glm::uvec3(glm::ceil((extent + 2.0f * margin) / cell)),
                                     glm::uvec3(kProbeCellsPerAxis + 1));
    out.grid.origin = glm::vec4(origin, 0.0f);
    out.grid.cellSize = glm::vec4(glm::vec3(cell), 0.0f);
    out.grid.dims = glm::uvec4(dims, 1u);
    const uint32_t cells = dims.x * dims.y * dims.z;
    out.words.assign(2 * size_t(cells), 0u);
    const float slack = 1e-3f * cell;
    std::vector<uint32_t> influence, nearest;
    for (uint32_t z = 0; z < dims.z; ++z)
        for (uint32_t y = 0; y < dims.y; ++y)
            for (uint32_t x = 0; x < dims.x; ++x) {
                const glm::vec3 lo = origin + glm::vec3(x, y, z) * cell - slack;
                const glm::vec3 hi = origin + glm::vec3(x + 1, y + 1, z + 1) * cell + slack;
                influence.clear();
                nearest.clear();
                float bestFarthest = std::numeric_limits<float>::infinity();
                for (const GpuProbe& g : records) {
                    const glm::vec3 p(g.position);
                    const glm::vec3 far = glm::max(glm::abs(p - lo), glm::abs(p - hi));
                    bestFarthest = std::min(bestFarthest, glm::dot(far, far));
                }
                for (uint32_t i = 0; i < records.size(); ++i) {
                    const GpuProbe& g = records[i];
                    if (glm::all(glm::lessThan(glm::vec3(g.influenceMin), hi)) &&
                        glm::all(glm::greaterThan(glm::vec3(g.influenceMax), lo)))
                        influence.push_back(i);
                    const glm::vec3 p(g.position);
                    const glm::vec3 gap = glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f));
                    if (glm::dot(gap, gap) <= bestFarthest * (1.0f + 1e-4f)) nearest.push_back(i);
                }
                const uint32_t c = x + dims.x * (y + dims.y * z);
                out.words[2 * c] = uint32_t(out.words.size());
                out.words[2 * c + 1] = uint32_t(influence.size()) | uint32_t(nearest.size()) << 16;
                out.words.insert(out.words.end(), influence.begin(), influence.end());
                out.words.insert(out.words.end(), nearest.begin(), nearest.end());
            }
    return out;
}

uint32_t probeCellOf(const GpuProbeGrid& grid, glm::vec3 p) {
    if (grid.dims.w == 0) return kNoIndex;
    const glm::vec3 f = glm::floor((p - glm::vec3(grid.origin)) / glm::vec3(grid.cellSize));
    if (!(f.x >= 0.0f && f.y >= 0.0f && f.z >= 0.0f && f.x < float(grid.dims.x) &&
          f.y < float(grid.dims.y) && f.z < float(grid.dims.z)))
        return kNoIndex;
    const glm::uvec3 c(f);
    return c.x + grid.dims.x * (c.y + grid.dims.y * c.z);
}

GpuProbe placeholderProbeRecord() {
    GpuProbe g{};
    g.influenceMin = glm::vec4(glm::vec3(-1e20f), 1.0f);
    g.influenceMax = glm::vec4(glm::vec3(1e20f), 0.0f);
    for (glm::vec4& face : g.relativeIrradiance) face = glm::vec4(1.0f);
    return g;
}

}  // namespace onelight::render
