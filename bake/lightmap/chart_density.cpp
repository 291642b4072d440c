#include "bake/lightmap/chart_density.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/enumerable_thread_specific.h>

#include "bake/lighting/sampling.hpp"
#include "bake/parallel_for.hpp"

namespace onelight::bake {
namespace {

constexpr uint32_t kDistancePass = 97;  // the pilot's own random stream, apart from the bake's

/// What the pilot measures at one texel.
struct Pilot {
    float light = 0.0f;     // lux, the direct light's luminance
    float ownLight = 0.0f;  // lux, of it the own primary's (shadowed)
    glm::vec3 position{0.0f};
    float harmonicDistance = std::numeric_limits<float>::infinity();  // metres
    bool valid = false;
};

Pilot measure(const BakeScene& scene, const BakeLights& lights, const world::CompiledLevel& level,
              const TexelSample& s, const LightmapSettings& direct, uint32_t distanceRays,
              RayCounts& rays) {
    Pilot p;
    const TexelEstimate e = estimateTexelDirect(scene, lights, level, s, direct, rays);
    if (e.moved) return p;
    p.ownLight = luminance(e.ownDirect);
    p.light = p.ownLight + float(e.directLuminance);
    p.position = s.position;
    const Frame frame = frameAround(s.normal);
    Rng rng{seedFrom(s.atlas, s.x, s.y, kDistancePass)};
    const float s0 = rng.next(), s1 = rng.next();
    double inverseSum = 0.0;
    for (uint32_t i = 0; i < distanceRays; ++i) {
        const glm::vec3 d =
            frame.toWorld(sampleCosineHemisphere(rotatedHammersley(i, distanceRays, s0, s1)));
        const SurfaceHit hit = scene.intersect(e.origin, d, scene.sceneDiameter(), rays.probe);
        if (hit.found) inverseSum += 1.0 / std::max(double(hit.distance), 1e-4);
    }
    if (inverseSum > 0.0) p.harmonicDistance = float(double(distanceRays) / inverseSum);
    p.valid = std::isfinite(p.light);
    return p;
}

}  // namespace

std::vector<float> chartDensityScales(const BakeScene& scene, const BakeLights& lights,
                                      const world::CompiledLevel& level,
                                      const std::vector<TexelSample>& samples,
                                      const ChartDensitySettings& settings,
                                      ChartDensityStats* stats) {
    std::vector<float> scales(level.charts.size(), 1.0f);
    if (samples.empty() || level.charts.empty()) return scales;
    LightmapSettings direct;
    direct.shadowSamples = settings.shadowSamples;

    // Every texel whose centre is on its triangle, measured once.
    std::vector<Pilot> pilots(samples.size());
    tbb::enumerable_thread_specific<RayCounts> rays;
    bake::parallelFor(tbb::blocked_range<size_t>(0, samples.size(), 64), [&](const auto& r) {
        RayCounts& local = rays.local();
        for (size_t i = r.begin(); i != r.end(); ++i)
            if (samples[i].centreInside)
                pilots[i] =
                    measure(scene, lights, level, samples[i], direct, settings.distanceRays, local);
    });

    // Texel (atlas, x, y) -> sample, per atlas page.
    std::vector<uint64_t> atlasFirst(level.atlases.size() + 1, 0);
    for (size_t a = 0; a < level.atlases.size(); ++a)
        atlasFirst[a + 1] =
            atlasFirst[a] + uint64_t(level.atlases[a].width) * level.atlases[a].height;
    std::vector<uint32_t> sampleOf(atlasFirst.back(), ~0u);
    for (size_t i = 0; i < samples.size(); ++i)
        if (pilots[i].valid) sampleOf[samples[i].texel] = static_cast<uint32_t>(i);

    bake::parallelFor(size_t(0), level.charts.size(), [&](size_t c) {
        const world::Chart& chart = level.charts[c];
        if (chart.authored || chart.width == 0 || chart.height == 0) return;
        const uint32_t w = chart.width, h = chart.height;
        const auto at = [&](int32_t x, int32_t y) -> const Pilot* {
            if (x < 0 || y < 0 || uint32_t(x) >= w || uint32_t(y) >= h) return nullptr;
            const uint64_t t = atlasFirst[chart.atlas] +
                               uint64_t(chart.y + uint32_t(y)) * level.atlases[chart.atlas].width +
                               chart.x + uint32_t(x);
            return sampleOf[t] == ~0u ? nullptr : &pilots[sampleOf[t]];
        };
        // Whether any view sees the chart's shadow mask (beyond the runtime's shadows).
        bool maskSeen = settings.views.empty();
        for (uint32_t y = 0; y < h && !maskSeen; ++y)
            for (uint32_t x = 0; x < w && !maskSeen; ++x)
                if (const Pilot* p = at(int32_t(x), int32_t(y)))
                    for (const glm::vec3& v : settings.views)
                        maskSeen =
                            maskSeen || glm::distance(v, p->position) > settings.maskDistance;
        const auto lightOf = [&](const Pilot& p) {
            return maskSeen ? p.light : p.light - p.ownLight;
        };
        float brightest = 0.0f, texelSize = 0.0f;
        std::vector<float> distances;
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                if (const Pilot* p = at(int32_t(x), int32_t(y))) {
                    brightest = std::max(brightest, lightOf(*p));
                    distances.push_back(p->harmonicDistance);
                }
        if (distances.empty() || chart.texelsPerMetre <= 0.0f) return;
        const size_t skipped = std::min(
            distances.size() - 1, size_t(settings.distanceQuantile * float(distances.size())));
        std::nth_element(distances.begin(), distances.begin() + long(skipped), distances.end());
        const float nearest = distances[skipped];
        texelSize = 1.0f / chart.texelsPerMetre;
        const float floor = std::max(0.01f * brightest, 1e-6f);
        const auto smooth = [&](int32_t k) {
            if (float(k) * texelSize > settings.distanceFraction * nearest) return false;
            if (w < uint32_t(2 * k + 1) && h < uint32_t(2 * k + 1)) return false;
            for (int32_t y = 0; y < int32_t(h); ++y)
                for (int32_t x = 0; x < int32_t(w); ++x) {
                    const Pilot* p = at(x, y);
                    if (!p) continue;
                    const float limit = settings.curvatureTolerance * std::max(lightOf(*p), floor);
                    const Pilot* pairs[2][2] = {{at(x - k, y), at(x + k, y)},
                                                {at(x, y - k), at(x, y + k)}};
                    for (const auto& pair : pairs)
                        if (pair[0] && pair[1] &&
                            std::fabs(lightOf(*pair[0]) + lightOf(*pair[1]) - 2.0f * lightOf(*p)) >
                                limit)
                            return false;
                }
            return true;
        };
        int32_t best = 1;
        for (int32_t k = 2; k <= int32_t(settings.maxReduction); k *= 2) {
            if (!smooth(k)) break;
            best = k;
        }
        scales[c] = 1.0f / float(best);
    });
    if (stats) {
        stats->chartsReduced = 0;
        for (float s : scales) stats->chartsReduced += s < 1.0f;
        for (const RayCounts& r : rays) stats->rays += r;
    }
    return scales;
}

}  // namespace onelight::bake
