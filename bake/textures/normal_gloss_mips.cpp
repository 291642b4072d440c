#include "bake/textures/normal_gloss_mips.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <stdexcept>

#include "bake/parallel_for.hpp"
#include "bake/textures/gloss_tables.hpp"
#include "shading.hpp"

namespace onelight::bake {

namespace {

// Sums over a footprint's level-0 texels of what the four methods need (see the header).
struct FootprintSums {
    glm::dvec3 normal{0.0};                                             // sum n_i
    double xx = 0.0, yy = 0.0, zz = 0.0, xy = 0.0, xz = 0.0, yz = 0.0;  // sum n_i n_i^T
    glm::dvec3 normalOverCos{0.0};                                      // sum n_i / cos_i
    double areaOverCos = 0.0;                                           // sum A(g_i) / cos_i
    double variance = 0.0;                                              // sum var(g_i)
    double roughness = 0.0;                  // sum roughness_fromGloss(g_i)
    glm::dvec2 slope{0.0};                   // sum s_i = n_i.xy / cos_i
    double slope2 = 0.0;                     // sum |s_i|^2
    double alpha2 = 0.0;                     // sum ggxAlpha_fromGloss(g_i)^2
    double sxx = 0.0, sxy = 0.0, syy = 0.0;  // sum s_i s_i^T
    glm::dvec2 slope2Slope{0.0};             // sum |s_i|^2 s_i
    double slope4 = 0.0;                     // sum |s_i|^4
    double count = 0.0;                      // K
};

void add(FootprintSums& s, const FootprintSums& o) {
    s.normal += o.normal;
    s.xx += o.xx;
    s.yy += o.yy;
    s.zz += o.zz;
    s.xy += o.xy;
    s.xz += o.xz;
    s.yz += o.yz;
    s.normalOverCos += o.normalOverCos;
    s.areaOverCos += o.areaOverCos;
    s.variance += o.variance;
    s.roughness += o.roughness;
    s.slope += o.slope;
    s.slope2 += o.slope2;
    s.alpha2 += o.alpha2;
    s.sxx += o.sxx;
    s.sxy += o.sxy;
    s.syy += o.syy;
    s.slope2Slope += o.slope2Slope;
    s.slope4 += o.slope4;
    s.count += o.count;
}

constexpr glm::dvec3 kUp{0.0, 0.0, 1.0};
constexpr double kMinLength = 1e-12;

FootprintSums texelSums(glm::vec3 normal, float gloss) {
    glm::dvec3 n(normal);
    double len2 = glm::dot(n, n);
    n = (len2 >= kMinLength * kMinLength && std::isfinite(len2)) ? n / std::sqrt(len2) : kUp;
    double g = std::isfinite(gloss) ? std::clamp(double(gloss), 0.0, 1.0) : 0.0;
    double cosTheta = std::max(n.z, kMinCos);
    FootprintSums s;
    s.normal = n;
    s.xx = n.x * n.x;
    s.yy = n.y * n.y;
    s.zz = n.z * n.z;
    s.xy = n.x * n.y;
    s.xz = n.x * n.z;
    s.yz = n.y * n.z;
    s.normalOverCos = n / cosTheta;
    s.areaOverCos = (1.0 / averageNormalLength_fromGloss(g)) / cosTheta;
    s.variance = normalVariance_fromGloss(g);
    s.roughness = roughness_fromGloss(g);
    s.slope = glm::dvec2(n.x, n.y) / cosTheta;
    s.slope2 = glm::dot(s.slope, s.slope);
    const double alpha = ggxAlpha_fromGloss(g);
    s.alpha2 = alpha * alpha;
    s.sxx = s.slope.x * s.slope.x;
    s.sxy = s.slope.x * s.slope.y;
    s.syy = s.slope.y * s.slope.y;
    s.slope2Slope = s.slope2 * s.slope;
    s.slope4 = s.slope2 * s.slope2;
    s.count = 1.0;
    return s;
}

// Unit direction of v, or +z when v is shorter than kMinLength * scale.
glm::dvec3 directionOr(glm::dvec3 v, double scale) {
    double len = glm::length(v);
    return len > kMinLength * scale ? v / len : kUp;
}

struct Texel {
    glm::vec3 normal;
    float gloss;
};

// The gloss of the footprint's texels' own lobes, their RMS alpha: the lobe without the spread of
// the normals (CLEAN's first term, whatever the method).
float baseGloss(const FootprintSums& s) {
    const double alpha2 = std::clamp(s.alpha2 / s.count, 1e-30, 1.0);
    return float(std::clamp(std::log2(2.0 / alpha2 - 1.0) / 18.0, 0.0, 1.0));
}

// The kurtosis of the footprint's slopes about their mean (see the header); 2, a Gaussian's,
// where they do not spread (a variance under 1e-8 of the slopes' square, rounding).
float slopeKurtosis(const FootprintSums& s) {
    const double k = s.count;
    const glm::dvec2 m = s.slope / k;
    const double m2 = glm::dot(m, m);
    const double variance = s.slope2 / k - m2;
    if (!(variance > 1e-8 * (s.slope2 / k)) || !(variance > 1e-12)) return 2.0f;
    const double quadratic =
        m.x * m.x * s.sxx / k + 2.0 * m.x * m.y * s.sxy / k + m.y * m.y * s.syy / k;
    const double fourth = s.slope4 / k - 4.0 * glm::dot(m, s.slope2Slope / k) + 4.0 * quadratic +
                          2.0 * m2 * (s.slope2 / k) - 3.0 * m2 * m2;
    // >= 1 in exact arithmetic (Jensen); rounding can take a ring's a hair below.
    return float(std::max(fourth / (variance * variance), 1.0));
}

Texel resolve(const FootprintSums& s, world::GlossMipMethod method, GlossInversion inversion) {
    if (method == world::GlossMipMethod::kBlit) {
        glm::dvec3 n = directionOr(s.normal, s.count);
        float roughness = float(s.roughness / s.count);
        return {glm::vec3(n), glsl::gloss_fromRoughness(roughness)};
    }
    if (method == world::GlossMipMethod::kClean) {
        // Olano and Baker 2010, sec. 5 (isotropic): the slopes' mixture, see the header.
        const glm::dvec2 mean = s.slope / s.count;
        const double spread = std::max(s.slope2 / s.count - glm::dot(mean, mean), 0.0);
        const double alpha2 = std::clamp(s.alpha2 / s.count + spread, 1e-30, 1.0);
        const double g = std::clamp(std::log2(2.0 / alpha2 - 1.0) / 18.0, 0.0, 1.0);
        return {glm::vec3(glm::normalize(glm::dvec3(mean.x, mean.y, 1.0))), float(g)};
    }
    if (method == world::GlossMipMethod::kBlackOps) {
        glm::dvec3 n = directionOr(s.normal, s.count);
        // Lazarov 2011, slide "Normal Variance": v = (1/K) sum (1 - (n_i.nbar)^2).
        double nMn = n.x * n.x * s.xx + n.y * n.y * s.yy + n.z * n.z * s.zz +
                     2.0 * (n.x * n.y * s.xy + n.x * n.z * s.xz + n.y * n.z * s.yz);
        double v = std::max(1.0 - nMn / s.count, 0.0) + s.variance / s.count;
        double g = inversion == GlossInversion::Table ? gloss_fromNormalVariance(v)
                                                      : gloss_fromDistance(normalVarianceFit(), v);
        return {glm::vec3(n), float(g)};
    }
    // Chan 2018, sec. 2.1: the microsurface-area weighted mean normal, see the header.
    glm::dvec3 average = s.normalOverCos / s.areaOverCos;
    double length = glm::length(average);
    glm::dvec3 n = length > kMinLength ? average / length : kUp;
    double g = inversion == GlossInversion::Table
                   ? gloss_fromAverageNormalLength(length)
                   : gloss_fromDistance(averageNormalLengthFit(), 1.0 - length);
    return {glm::vec3(n), float(g)};
}

}  // namespace

int mipLevelCount(int width, int height) {
    int levels = 1;
    for (int size = std::max(width, height); size > 1; size >>= 1) ++levels;
    return levels;
}

int mipSize(int size, int level) {
    return std::max(1, size >> level);
}

TexelRange mipChildren(int parentSize, int index) {
    int childSize = mipSize(parentSize, 1);
    return {2 * index, index + 1 == childSize ? parentSize : 2 * index + 2};
}

TexelRange mipFootprint(int size, int level, int index) {
    if (size < 1 || level < 0 || index < 0 || index >= mipSize(size, level))
        throw std::invalid_argument("mipFootprint: texel outside the level");
    TexelRange r{index, index + 1};
    for (int l = level; l > 0; --l) {
        int parentSize = mipSize(size, l - 1);
        r = {mipChildren(parentSize, r.begin).begin, mipChildren(parentSize, r.end - 1).end};
    }
    return r;
}

NormalGlossChain buildNormalGlossMips(const NormalGlossLevel& level0, world::GlossMipMethod method,
                                      GlossInversion inversion) {
    const int w0 = level0.width, h0 = level0.height;
    if (w0 < 1 || h0 < 1 || level0.normals.size() != std::size_t(w0) * std::size_t(h0) ||
        level0.gloss.size() != level0.normals.size())
        throw std::invalid_argument("buildNormalGlossMips: level 0 is not width x height texels");

    NormalGlossChain chain{level0};
    chain[0].baseGloss = level0.gloss;  // a level-0 texel's lobe is its own
    chain[0].slopeKurtosis.assign(level0.normals.size(), 2.0f);
    std::vector<FootprintSums> sums(level0.normals.size());
    parallelFor(0, h0, [&](int y) {
        for (int x = 0; x < w0; ++x) {
            std::size_t i = std::size_t(y) * std::size_t(w0) + std::size_t(x);
            sums[i] = texelSums(level0.normals[i], level0.gloss[i]);
        }
    });

    const int levels = mipLevelCount(w0, h0);
    for (int level = 1; level < levels; ++level) {
        const int pw = mipSize(w0, level - 1), ph = mipSize(h0, level - 1);
        const int w = mipSize(w0, level), h = mipSize(h0, level);
        std::vector<FootprintSums> next(std::size_t(w) * std::size_t(h));
        NormalGlossLevel out{w,
                             h,
                             std::vector<glm::vec3>(next.size()),
                             std::vector<float>(next.size()),
                             std::vector<float>(next.size()),
                             std::vector<float>(next.size())};
        parallelFor(0, h, [&](int y) {
            TexelRange rows = mipChildren(ph, y);
            for (int x = 0; x < w; ++x) {
                TexelRange columns = mipChildren(pw, x);
                FootprintSums s;
                for (int py = rows.begin; py < rows.end; ++py)
                    for (int px = columns.begin; px < columns.end; ++px)
                        add(s, sums[std::size_t(py) * std::size_t(pw) + std::size_t(px)]);
                std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                Texel t = resolve(s, method, inversion);
                next[i] = s;
                out.normals[i] = t.normal;
                out.gloss[i] = t.gloss;
                out.baseGloss[i] = std::max(baseGloss(s), t.gloss);
                out.slopeKurtosis[i] = slopeKurtosis(s);
            }
        });
        sums = std::move(next);
        chain.push_back(std::move(out));
    }
    return chain;
}

}  // namespace onelight::bake
