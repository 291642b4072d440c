#include "bake/lightmap/lightmap_denoise.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "bake/lighting/sampling.hpp"
#include "bake/lighting/spatial_hash.hpp"

namespace onelight::bake {
namespace {

/*
   The filter at texel p (centre c_p, normal n_p, footprint h): a weighted least-squares fit
   of a plane to the indirect estimates y_q of its neighbours q, in p's tangent coordinates
   (u, v) = ((c_q - c_p) . t, (c_q - c_p) . b), read at (0, 0):
     minimise sum_q w_q (y_q - a - b u_q - c v_q)^2,   output a = sum_q k_q y_q
   with k_q = w_q (m0 + m1 u_q + m2 v_q), [m0 m1 m2] the first row of M^-1,
   M = sum_q w_q [1 u v]^T [1 u v]. So sum k_q = 1 (a uniform field is kept exactly, and a
   noisy one keeps its mean) and sum k_q u_q = sum k_q v_q = 0 (a linear field too, even where
   the window is cut by a chart's edge or a wall: no pull towards the inner neighbours). In a
   full window the fit is the weighted mean.
   Weights w_q = (1 - (d / R)^2)^2 (biweight of the distance d between centres, R = (r + 1/2) h),
   for q that:
     - was not moved out of geometry (nor p),
     - faces the same way (n_p . n_q > cos 25 degrees) and lies near p's plane
       (|(c_q - c_p) . n_p| < h / 4 + d / 10: flat charts and gently curved patches),
     - sees p (a shadow ray between their ray origins: no light crosses a wall or a block).
   The guides are position and normal only. The receiver's albedo does not change the
   irradiance a texel stores (the incoming light is continuous across a texture's edge), so
   an albedo guide would only stop the filter where nothing changes.
   The window never reaches past half the harmonic mean distance of the texel's gathering rays
   (nor a neighbour past half its own): by Ward's split-sphere bound the irradiance changes by
   about d / R_harmonic over a step d, so near a wall's foot or beside a bright patch, where the
   field curves within a few texels and a plane would not fit it, the window shrinks to what
   stays nearly linear, but never below radius 1 (1.5 texels): a texel at a room's edge or
   corner, whose rays all land close by, left unfiltered showed as a bright blotch along every
   border of a dim wall.
   The radius r (texels) is the smallest whose full window brings the neighbourhood's noise
   to settings.targetNoise: the largest relative noise among p and its neighbours within
   1.5 h (not p's own alone: a texel whose paths missed a small bright source looks quiet,
   while its neighbours show the estimate is unreliable) times the window's noise factor
   sqrt(sum w^2) / sum w. A texel already that quiet is kept as it is (r = 0).
*/
constexpr float kNormalAgreement = 0.906f;  // cos 25 degrees
constexpr float kPlaneTolerance = 0.25f;    // of the footprint
constexpr float kPlaneSlope = 0.1f;         // of the distance
constexpr float kNoiseReach = 1.5f;         // footprints: the neighbourhood whose noise counts
constexpr float kGradientReach = 0.5f;      // of the harmonic distance: the widest window

float windowReach(int radius) {
    return float(radius) + 0.5f;
}

double biweight(float d2, float r2) {
    const double x = 1.0 - double(d2) / double(r2);
    return x > 0.0 ? x * x : 0.0;
}

/// sqrt(sum w^2) / sum w of a full window of radius r on the unit texel lattice.
std::array<double, kDenoiseMaxRadius + 1> windowNoiseFactors() {
    std::array<double, kDenoiseMaxRadius + 1> f{};
    f[0] = 1.0;
    for (int r = 1; r <= kDenoiseMaxRadius; ++r) {
        const float reach = windowReach(r);
        double sum = 0.0, sum2 = 0.0;
        for (int y = -r; y <= r; ++y)
            for (int x = -r; x <= r; ++x) {
                const double w = biweight(float(x * x + y * y), reach * reach);
                sum += w;
                sum2 += w * w;
            }
        f[size_t(r)] = std::sqrt(sum2) / sum;
    }
    return f;
}

/// The largest window's reach of texel i, in metres, within the hash's cell size.
float maxReach(const TexelHash& hash, const TexelSample& s) {
    return std::min(windowReach(kDenoiseMaxRadius) * s.texelSize, 0.5f * hash.cellSize);
}

/// Calls f(j) for every texel j whose centre lies within `reach` of `centre` (the sphere lies
/// in 2 x 2 x 2 cells), buckets in a fixed order and texels in increasing index within each.
template <typename F>
void forEachNear(const TexelHash& hash, const std::vector<TexelSample>& samples,
                 const glm::vec3& centre, float reach, F&& f) {
    if (hash.texels.empty()) return;
    const glm::ivec3 base = cellOfPoint(centre - glm::vec3(reach), hash.cellSize);
    uint32_t visited[8];
    int visitedCount = 0;
    const float reach2 = reach * reach;
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                const uint32_t b = bucketOf(base + glm::ivec3(dx, dy, dz), hash.bucketMask);
                if (std::find(visited, visited + visitedCount, b) != visited + visitedCount)
                    continue;
                visited[visitedCount++] = b;
                for (uint32_t k = hash.bucketFirst[b]; k < hash.bucketFirst[b + 1]; ++k) {
                    const uint32_t j = hash.texels[k];
                    const glm::vec3 d = samples[j].centre - centre;
                    if (glm::dot(d, d) <= reach2) f(j);
                }
            }
}

/// How far a window around texel s may reach by its harmonic distance. An edge texel traces
/// from its triangle's border, where the neighbour wall's nearness says nothing about how the
/// light varies along the surface: it is not capped (and its noisy corner estimate then gets
/// a full window of the inner texels instead of staying a blotch along the border).
float gradientReach(const TexelSample& s, const TexelEstimate& e) {
    return s.centreInside ? kGradientReach * e.harmonicDistance
                          : std::numeric_limits<float>::infinity();
}

/// Whether q may join p's window by its geometry (not yet its visibility).
bool sameSurfaceSide(const TexelSample& p, const TexelSample& q) {
    if (glm::dot(p.normal, q.normal) < kNormalAgreement) return false;
    const glm::vec3 d = q.centre - p.centre;
    return std::fabs(glm::dot(d, p.normal)) <=
           kPlaneTolerance * p.texelSize + kPlaneSlope * glm::length(d);
}

}  // namespace

TexelHash makeTexelHash(const std::vector<TexelSample>& samples) {
    TexelHash hash;
    const size_t n = samples.size();
    if (n == 0) return hash;
    // A cell spans the largest window's diameter for all but the coarsest 5% of texels (their
    // windows are clamped to it), so a window lies in 2 x 2 x 2 cells, and one coarse chart
    // does not make every cell large.
    std::vector<float> sizes(n);
    for (size_t i = 0; i < n; ++i) sizes[i] = samples[i].texelSize;
    const size_t at = std::min(n - 1, n * 95 / 100);
    std::nth_element(sizes.begin(), sizes.begin() + long(at), sizes.end());
    hash.cellSize = std::max(2.0f * windowReach(kDenoiseMaxRadius) * sizes[at], 1e-6f);
    uint32_t buckets = 1;
    while (buckets < 2 * n && buckets < (1u << 30)) buckets <<= 1;
    hash.bucketMask = buckets - 1;
    hash.bucketFirst.assign(size_t(buckets) + 1, 0);
    std::vector<uint32_t> bucket(n);
    for (size_t i = 0; i < n; ++i) {
        bucket[i] = bucketOf(cellOfPoint(samples[i].centre, hash.cellSize), hash.bucketMask);
        ++hash.bucketFirst[bucket[i] + 1];
    }
    for (size_t b = 0; b < buckets; ++b) hash.bucketFirst[b + 1] += hash.bucketFirst[b];
    hash.texels.resize(n);
    std::vector<uint32_t> fill(hash.bucketFirst.begin(), hash.bucketFirst.end() - 1);
    for (size_t i = 0; i < n; ++i) hash.texels[fill[bucket[i]]++] = static_cast<uint32_t>(i);
    return hash;
}

void markDenoiseFootprint(const TexelHash& hash, const std::vector<TexelSample>& samples,
                          const std::vector<uint32_t>& owned, std::vector<uint8_t>& needed) {
    needed.resize(samples.size(), 0);
    for (const uint32_t i : owned) {
        needed[i] = 1;
        forEachNear(hash, samples, samples[i].centre, maxReach(hash, samples[i]),
                    [&](uint32_t j) { needed[j] = 1; });
    }
}

DenoisedIndirect denoiseTexel(const BakeScene& scene, const TexelHash& hash,
                              const std::vector<TexelSample>& samples,
                              const std::vector<TexelEstimate>& estimates, size_t i,
                              const DenoiseSettings& settings, RayCounts& rays) {
    static const std::array<double, kDenoiseMaxRadius + 1> kNoiseFactors = windowNoiseFactors();
    const TexelSample& p = samples[i];
    const TexelEstimate& e = estimates[i];
    DenoisedIndirect out{e.indirect, e.indirectDirection, e.indirectLuminance, e.noise, 0};
    if (!settings.enabled || e.moved) return out;

    double localNoise = relativeNoise(e);
    forEachNear(hash, samples, p.centre, std::min(kNoiseReach * p.texelSize, 0.5f * hash.cellSize),
                [&](uint32_t j) {
                    if (j != i && sameSurfaceSide(p, samples[j]) && !estimates[j].moved)
                        localNoise = std::max(localNoise, relativeNoise(estimates[j]));
                });
    int radius = 0;
    while (radius < kDenoiseMaxRadius &&
           localNoise * kNoiseFactors[size_t(radius)] > settings.targetNoise)
        ++radius;
    if (radius == 0) return out;
    out.radius = radius;

    // The window: the texel itself, then its neighbours in the hash's order.
    struct Member {
        uint32_t index;
        double w, u, v;
    };
    std::vector<Member> window;
    window.push_back({static_cast<uint32_t>(i), 1.0, 0.0, 0.0});
    const Frame frame = frameAround(p.normal);
    const float smallest = std::min(windowReach(1) * p.texelSize, 0.5f * hash.cellSize);
    const float reach = std::max(smallest, std::min({windowReach(radius) * p.texelSize,
                                                     0.5f * hash.cellSize, gradientReach(p, e)}));
    forEachNear(hash, samples, p.centre, reach, [&](uint32_t j) {
        if (j == i) return;
        const TexelSample& q = samples[j];
        const TexelEstimate& qe = estimates[j];
        if (qe.moved || !sameSurfaceSide(p, q)) return;
        const glm::vec3 d = q.centre - p.centre;
        const float d2 = glm::dot(d, d);
        const double w = biweight(d2, reach * reach);
        const float own = std::max(smallest, gradientReach(q, qe));
        if (w <= 0.0 || d2 > own * own) return;
        const glm::vec3 to = qe.origin - e.origin;
        const float distance = glm::length(to);
        if (distance > 0.0f && scene.occluded(e.origin, to / distance, distance, rays.probe))
            return;
        window.push_back({j, w, double(glm::dot(d, frame.t)) / double(p.texelSize),
                          double(glm::dot(d, frame.b)) / double(p.texelSize)});
    });

    // M = sum w [1 u v]^T [1 u v], with a small ridge on the slopes so that a window with no
    // extent along u or v (a strip one texel wide) falls back to the weighted mean there.
    glm::dmat3 m(0.0);
    double weightSum = 0.0;
    for (const Member& q : window) {
        const glm::dvec3 x(1.0, q.u, q.v);
        m += q.w * glm::outerProduct(x, x);
        weightSum += q.w;
    }
    const double ridge = 1e-3 * weightSum;
    m[1][1] += ridge;
    m[2][2] += ridge;
    const glm::dmat3 inverse = glm::inverse(m);
    const glm::dvec3 row(inverse[0][0], inverse[1][0], inverse[2][0]);  // first row (symmetric)
    out.indirect = glm::dvec3(0.0);
    out.indirectDirection = glm::dvec3(0.0);
    out.indirectLuminance = 0.0;
    double variance = 0.0;
    for (const Member& q : window) {
        const double k = q.w * glm::dot(row, glm::dvec3(1.0, q.u, q.v));
        const TexelEstimate& qe = estimates[q.index];
        out.indirect += k * qe.indirect;
        out.indirectDirection += k * qe.indirectDirection;
        out.indirectLuminance += k * qe.indirectLuminance;
        variance += k * k * qe.noise * qe.noise;
    }
    out.noise = std::sqrt(variance);
    // An extrapolated fit at a window's edge can dip below zero where the light ends.
    out.indirect = glm::max(out.indirect, glm::dvec3(0.0));
    out.indirectLuminance = std::max(out.indirectLuminance, 0.0);
    return out;
}

namespace {

/// Calls f(j) for each sampled, unmoved texel j among moved texel i's eight neighbours in its
/// chart: the texels the bilinear filter blends with it.
template <typename F>
void forEachMovedNeighbour(const world::CompiledLevel& level,
                           const std::vector<TexelSample>& samples,
                           const std::vector<TexelEstimate>& estimates, size_t i, F&& f) {
    const uint32_t chart = level.surfaces[samples[i].surface].chart;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int64_t j = dx == 0 && dy == 0 ? -1 : sampleAtOffset(level, samples, i, dx, dy);
            if (j >= 0 && !estimates[size_t(j)].moved &&
                level.surfaces[samples[size_t(j)].surface].chart == chart)
                f(uint32_t(j));
        }
}

}  // namespace

std::vector<uint32_t> movedTexelReads(const world::CompiledLevel& level,
                                      const std::vector<TexelSample>& samples,
                                      const std::vector<TexelEstimate>& estimates,
                                      const std::vector<uint32_t>& owned) {
    std::vector<uint32_t> reads;
    for (const uint32_t i : owned)
        if (estimates[i].moved)
            forEachMovedNeighbour(level, samples, estimates, i,
                                  [&](uint32_t j) { reads.push_back(j); });
    std::sort(reads.begin(), reads.end());
    reads.erase(std::unique(reads.begin(), reads.end()), reads.end());
    return reads;
}

DenoisedIndirect movedTexelIndirect(const world::CompiledLevel& level,
                                    const std::vector<TexelSample>& samples,
                                    const std::vector<TexelEstimate>& estimates, size_t i,
                                    const std::vector<uint32_t>& reads,
                                    const std::vector<DenoisedIndirect>& denoised) {
    const TexelEstimate& e = estimates[i];
    DenoisedIndirect out{e.indirect, e.indirectDirection, e.indirectLuminance, e.noise, 0};
    if (!e.moved) return out;
    struct Neighbour {
        const DenoisedIndirect* value;
        double weight;  // T_q (lux, luminance), then 1 / T_q^2
    };
    std::vector<Neighbour> neighbours;
    double brightest = 0.0;
    forEachMovedNeighbour(level, samples, estimates, i, [&](uint32_t j) {
        const auto at = std::lower_bound(reads.begin(), reads.end(), j);
        if (at == reads.end() || *at != j) return;  // not among the reads: cannot happen
        const DenoisedIndirect& d = denoised[size_t(at - reads.begin())];
        const TexelEstimate& q = estimates[j];
        const double whole =
            q.directLuminance + double(luminance(q.ownDirect)) + d.indirectLuminance;
        neighbours.push_back({&d, whole});
        brightest = std::max(brightest, whole);
    });
    if (neighbours.empty()) return out;
    // T_q floored relative to the brightest neighbour's, so that a black one counts as the
    // darkest possible rather than dividing by zero.
    const double floor = std::max(1e-6 * brightest, 1e-30);
    double weightSum = 0.0;
    for (Neighbour& q : neighbours) {
        const double t = std::max(q.weight, floor);
        q.weight = 1.0 / (t * t);
        weightSum += q.weight;
    }
    out = DenoisedIndirect{};
    double variance = 0.0;
    for (const Neighbour& q : neighbours) {
        const double k = q.weight / weightSum;
        out.indirect += k * q.value->indirect;
        out.indirectDirection += k * q.value->indirectDirection;
        out.indirectLuminance += k * q.value->indirectLuminance;
        variance += k * k * q.value->noise * q.value->noise;
    }
    out.noise = std::sqrt(variance);
    return out;
}

}  // namespace onelight::bake
