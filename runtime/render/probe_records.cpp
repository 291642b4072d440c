#include "render/probe_records.hpp"

#include <algorithm>
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

GpuProbe placeholderProbeRecord() {
    GpuProbe g{};
    g.influenceMin = glm::vec4(glm::vec3(-1e20f), 1.0f);
    g.influenceMax = glm::vec4(glm::vec3(1e20f), 0.0f);
    return g;
}

}  // namespace onelight::render
