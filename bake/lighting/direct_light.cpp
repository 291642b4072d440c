#include "bake/lighting/direct_light.hpp"

#include <algorithm>
#include <cmath>

namespace onelight::bake {
namespace {

constexpr uint32_t kLightsAtFullRate = 8;  // M = 8 S: eight lights keep S rays each

}  // namespace

std::vector<uint32_t> lightsNear(const BakeLights& lights, const glm::vec3& position) {
    std::vector<uint32_t> out;
    if (lights.lightCells.empty() && lights.localLights.empty()) {
        for (uint32_t l = 0; l < lights.lights.size(); ++l) out.push_back(l);
        return out;
    }
    out = lights.directionalLights;
    const LightCellView view = lightsAt(lights.lightCells, position);
    for (uint32_t k = 0; k < view.count; ++k)
        out.push_back(lights.localLights[view.entry[k].source]);
    std::sort(out.begin(), out.end());
    return out;
}

void estimateVisibilities(const BakeScene& scene, const BakeLights& lights,
                          std::vector<LightTerm>& terms, const glm::vec3& origin,
                          uint32_t samplesPerLight, Rng& rng, RayCounts& rays) {
    const uint32_t S = samplesPerLight;
    if (terms.size() <= kLightsAtFullRate || S == 0) {
        for (LightTerm& t : terms)
            t.visibility =
                lightVisibility(scene, lights.lights[t.light], t.incidence, origin, S, rng, rays);
        return;
    }
    double total = 0.0;
    for (const LightTerm& t : terms) total += double(t.importance);
    const double budget = double(kLightsAtFullRate) * S;
    std::vector<size_t> small;
    double smallProbability = 0.0;
    for (size_t i = 0; i < terms.size(); ++i) {
        LightTerm& t = terms[i];
        const double share =
            total > 0.0 ? double(t.importance) / total : 1.0 / double(terms.size());
        if (!t.full && budget * share < 1.0) {
            small.push_back(i);
            smallProbability += share;
            t.visibility = 0.0f;
            continue;
        }
        const uint32_t n =
            t.full ? S : std::clamp(static_cast<uint32_t>(std::lround(budget * share)), 1u, S);
        t.visibility =
            lightVisibility(scene, lights.lights[t.light], t.incidence, origin, n, rng, rays);
    }
    if (small.empty() || !(smallProbability > 0.0)) return;
    // Cumulative probabilities of the small terms, relative to their total q.
    std::vector<double> cdf(small.size());
    double running = 0.0;
    for (size_t k = 0; k < small.size(); ++k) {
        running += double(terms[small[k]].importance) / total;
        cdf[k] = running / smallProbability;
    }
    cdf.back() = 1.0;
    const uint32_t m = static_cast<uint32_t>(std::ceil(budget * smallProbability - 1e-9));
    const float xi = rng.next();
    for (uint32_t j = 0; j < std::max(1u, m); ++j) {
        const double u = (double(j) + double(xi)) / double(std::max(1u, m));
        const size_t k = std::min(size_t(std::upper_bound(cdf.begin(), cdf.end(), u) - cdf.begin()),
                                  small.size() - 1);
        LightTerm& t = terms[small[k]];
        // One shadow ray towards a random point of the light: 0 or 1.
        if (lightVisibility(scene, lights.lights[t.light], t.incidence, origin, 1, rng, rays) <
            1.0f)
            continue;
        const double pk = (cdf[k] - (k > 0 ? cdf[k - 1] : 0.0));  // p_k / q
        t.visibility += static_cast<float>(1.0 / (pk * double(std::max(1u, m))));
    }
}

}  // namespace onelight::bake
