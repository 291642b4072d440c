#include "microfacet_diffuse.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "quadrature.hpp"
#include "reference_brdf.hpp"
#include "shading.hpp"

namespace onelight::lab {

namespace {

double dot(const Direction& a, const Direction& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
Direction negated(const Direction& a) {
    return {-a.x, -a.y, -a.z};
}
Direction normalized(const Direction& a) {
    double s = 1.0 / std::sqrt(dot(a, a));
    return {a.x * s, a.y * s, a.z * s};
}

// SplitMix64 (Steele, Lea and Flood 2014, "Fast Splittable Pseudorandom Number Generators"):
// its output function also serves to hash (seed, walk index) into the walk's own state.
std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
constexpr std::uint64_t kGoldenGamma = 0x9E3779B97F4A7C15ull;

class WalkRandom {
public:
    WalkRandom(std::uint64_t seed, std::uint64_t walk)
        : state_(mix64(mix64(seed) ^ mix64(walk * kGoldenGamma + 1))) {}
    // Uniform in [0, 1), 53 random bits.
    double uniform() {
        state_ += kGoldenGamma;
        return double(mix64(state_) >> 11) * 0x1p-53;
    }

private:
    std::uint64_t state_;
};

// ---------------------------------------------------------------------------------------------
// The Smith microsurface of Heitz et al. 2016 (their section on the Smith microsurface model and
// its free-path distribution). Directions are signed: w.z < 0 points down into the surface.

// Smith Lambda of GGX (from Walter et al. 2007's G1 = 2 / (1 + sqrt(1 + x)) = 1 / (1 + Lambda),
// x = alpha^2 tan^2 theta; written without cancellation as x / (2 (1 + sqrt(1 + x)))), extended to
// downward directions by Lambda(-w) = -1 - Lambda(w) (Heitz et al. 2016): then G1 = C1(h)^Lambda
// and the free-path formulas below hold for both hemispheres. Not for horizontal w (Lambda is
// infinite there).
double lambdaGGX(const Direction& w, double alpha) {
    double x = alpha * alpha * (w.x * w.x + w.y * w.y) / (w.z * w.z);
    double up = 0.5 * x / (1.0 + std::sqrt(1.0 + x));
    return w.z > 0.0 ? up : -1.0 - up;
}

// Below this |w.z| a direction counts as horizontal (Lambda overflows): it hits at once.
constexpr double kHorizontal = 1e-100;

// The height of the walk is carried as log C1(h), the logarithm of the Smith height CDF:
// everything in the model depends on h only through C1(h) (Smith's height-dependent masking
// G1(w, h) = C1(h)^Lambda(w), Heitz 2014, "Understanding the Masking-Shadowing Function"), which
// is why the BSDF does not depend on the height distribution (Heitz et al. 2016). For uniform
// heights on [-1, 1], h = 2 C1 - 1. log C1 = 0 is the top of the microsurface, where the walk
// starts.
//
// Free path (Heitz et al. 2016, height sampling from the Smith height CDF): a ray from height
// h0 travelling along w next meets the microsurface at h with
//   up   (w.z > 0): P(leaves) = G1(w, h0) = C1(h0)^Lambda(w); otherwise, by inverting
//                   P(no hit below h) = (C1(h0) / C1(h))^Lambda(w) at 1 - u:
//                   C1(h) = C1(h0) / (1 - u)^(1 / Lambda(w));
//   down (w.z < 0): always hits; the same inversion with Lambda(w) = -1 - Lambda(-w) <= -1 gives
//                   C1(h) = C1(h0) (1 - u)^(1 / (1 + Lambda(-w))).
// Returns false when the ray leaves; otherwise moves logC1 to the hit.
bool nextIntersection(const Direction& w, double alpha, double u, double& logC1) {
    if (std::abs(w.z) < kHorizontal) return true;
    double lambda = lambdaGGX(w, alpha);
    double logOneMinusU = std::log1p(-u);  // <= 0
    if (w.z > 0.0) {
        // Leaves iff 1 - u < G1(w, h0). Lambda = 0 (straight up, or a flat surface): G1 = 1.
        if (lambda <= 0.0 || logOneMinusU < lambda * logC1) return false;
        logC1 = std::min(0.0, logC1 - logOneMinusU / lambda);
    } else {
        logC1 += logOneMinusU / (-lambda);
    }
    return true;
}

// G1(w, h) = C1(h)^Lambda(w) for w.z > 0: the probability that w leaves from height h unblocked.
double maskingAtHeight(double lambdaW, double logC1) {
    return std::exp(lambdaW * logC1);
}

// A normal m from the visible normals of GGX seen from w, D_w(m) = <w, m>+ D(m) / int <w, m'>+
// D(m') dm': Heitz 2018, "Sampling the GGX Distribution of Visible Normals", listing 1. The walk
// also needs it for w below the horizon (light travelling upwards hits the underside of the
// microsurface's bumps). The listing holds there unchanged: stretched to alpha = 1, the visible
// part of the hemisphere of normals projects onto the disk perpendicular to wh as the half disk
// plus (wh.z > 0) or minus (wh.z < 0) a half ellipse of minor axis |wh.z|, and its warp
// t2 -> (1 - s) sqrt(1 - t1^2) + s t2, s = (1 + wh.z) / 2, maps the uniform disk onto exactly
// that region uniformly for either sign. (w straight down sees no microfacet; the walk never
// asks for it, as a ray straight up always leaves.)
Direction sampleVisibleNormal(const Direction& w, double alpha, double u1, double u2) {
    Direction wh = normalized({alpha * w.x, alpha * w.y, w.z});
    double lenSq = wh.x * wh.x + wh.y * wh.y;
    Direction t1 = lenSq > 0.0 ? Direction{-wh.y / std::sqrt(lenSq), wh.x / std::sqrt(lenSq), 0.0}
                               : Direction{1.0, 0.0, 0.0};
    Direction t2 = {wh.y * t1.z - wh.z * t1.y, wh.z * t1.x - wh.x * t1.z,
                    wh.x * t1.y - wh.y * t1.x};
    double r = std::sqrt(u1), phi = 2.0 * std::numbers::pi * u2;
    double p1 = r * std::cos(phi), p2 = r * std::sin(phi);
    double s = 0.5 * (1.0 + wh.z);
    p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
    double p3 = std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2));
    Direction nh = {p1 * t1.x + p2 * t2.x + p3 * wh.x, p1 * t1.y + p2 * t2.y + p3 * wh.y,
                    p1 * t1.z + p2 * t2.z + p3 * wh.z};
    return normalized({alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)});
}

// The Lambertian facet's scattering: a cosine lobe about m (Malley's method), the sampling of
// the diffuse microflake phase function of Heitz et al. 2016 (their diffuse material):
// p(wi, wo) = int D_wi(m) rho / pi <wo, m>+ dm, a visible normal then a cosine lobe about it.
// Directions below the microfacet have zero density and are never drawn; directions below the
// macro surface are kept (the walk continues downwards and always hits again). Orthonormal
// basis of Duff et al. 2017, "Building an Orthonormal Basis, Revisited".
Direction sampleCosineAbout(const Direction& m, double u1, double u2) {
    double sign = std::copysign(1.0, m.z);
    double a = -1.0 / (sign + m.z), b = m.x * m.y * a;
    Direction b1 = {1.0 + sign * m.x * m.x * a, sign * b, -sign * m.x};
    Direction b2 = {b, sign + m.y * m.y * a, -m.y};
    double r = std::sqrt(u1), phi = 2.0 * std::numbers::pi * u2;
    double x = r * std::cos(phi), y = r * std::sin(phi), z = std::sqrt(std::max(0.0, 1.0 - u1));
    return {x * b1.x + y * b2.x + z * m.x, x * b1.y + y * b2.y + z * m.y,
            x * b1.z + y * b2.z + z * m.z};
}

struct WalkOutcome {
    // Next-event estimates of f(wi, wo) cos(theta_o): order 1, all orders.
    double single = 0.0, total = 0.0;
    int order = 0;         // scattering events
    double weight = 1.0;   // rho^order
    bool escaped = false;  // false: cut at maxOrder
};

// One random walk of Heitz et al. 2016 (their stochastic evaluation of the BSDF, and its
// sampling), light arriving from wi, with a next-event estimate towards wo if given:
//   travel along w = -wi from the top; at each hit k (height from nextIntersection) the light
//   meets a facet m drawn from the visible normals of -w; the next-event estimate adds
//   rho^k / pi <wo, m>+ G1(wo, h_k), an unbiased one-sample estimate of p(-w, wo) G1(wo, h_k);
//   the walk goes on along a cosine lobe about the same m.
// Using the facet that scatters for the next-event estimate too (rather than a second, independent
// visible normal) keeps every term unbiased: each one's conditional expectation is the same.
WalkOutcome randomWalk(const MicrofacetDiffuse& surface, const Direction& wi, const Direction* wo,
                       WalkRandom& random, int maxOrder) {
    const double alpha = surface.alpha;
    const double lambdaO = wo ? lambdaGGX(*wo, alpha) : 0.0;
    Direction w = negated(wi);
    double logC1 = 0.0;
    WalkOutcome out;
    while (out.order < maxOrder) {
        if (!nextIntersection(w, alpha, random.uniform(), logC1)) {
            out.escaped = true;
            return out;
        }
        ++out.order;
        out.weight *= surface.albedo;
        double u1 = random.uniform(), u2 = random.uniform();
        Direction m = sampleVisibleNormal(negated(w), alpha, u1, u2);
        if (wo) {
            double nee = out.weight / std::numbers::pi * std::max(0.0, dot(*wo, m)) *
                         maskingAtHeight(lambdaO, logC1);
            out.total += nee;
            if (out.order == 1) out.single = nee;
        }
        double u3 = random.uniform(), u4 = random.uniform();
        w = sampleCosineAbout(m, u3, u4);
    }
    return out;
}

// Sums of K per-walk values and their squares over `count` walks, in blocks of fixed size summed
// in index order: the same bits for any thread count. walk(index, values) returns whether the
// walk was truncated.
template <int K>
struct WalkSums {
    std::array<double, K> sum{}, sumSq{};
    int truncated = 0;
    int count = 0;

    Estimate estimate(int k) const {
        double n = double(count), mean = sum[k] / n;
        double variance = count > 1 ? std::max(0.0, sumSq[k] - sum[k] * mean) / (n - 1.0) : 0.0;
        return {mean, std::sqrt(variance / n)};
    }
};

template <int K, class Walk>
WalkSums<K> sumWalks(int count, const Walk& walk) {
    constexpr int kBlock = 256;
    const int blocks = (count + kBlock - 1) / kBlock;
    std::vector<WalkSums<K>> partial(std::size_t(std::max(blocks, 0)));
    tbb::parallel_for(0, blocks, [&](int b) {
        WalkSums<K>& p = partial[std::size_t(b)];
        for (int i = b * kBlock; i < std::min(count, (b + 1) * kBlock); ++i) {
            std::array<double, K> v{};
            if (walk(i, v)) ++p.truncated;
            for (int k = 0; k < K; ++k) p.sum[k] += v[k], p.sumSq[k] += v[k] * v[k];
            ++p.count;
        }
    });
    WalkSums<K> total;
    for (const WalkSums<K>& p : partial) {
        for (int k = 0; k < K; ++k) total.sum[k] += p.sum[k], total.sumSq[k] += p.sumSq[k];
        total.truncated += p.truncated;
        total.count += p.count;
    }
    return total;
}

// A different stream of walks for the same seed.
constexpr std::uint64_t kIntegratedLobeStream = 0x5DEECE66Dull;

}  // namespace

Direction directionFromAngles(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

MicrofacetDiffuseBrdf estimateMicrofacetDiffuseBrdf(const MicrofacetDiffuse& surface, Direction wi,
                                                    Direction wo, const RandomWalks& walks) {
    const double invCosO = 1.0 / wo.z;
    WalkSums<3> s = sumWalks<3>(walks.count, [&](int i, std::array<double, 3>& v) {
        WalkRandom random(walks.seed, std::uint64_t(i));
        WalkOutcome o = randomWalk(surface, wi, &wo, random, walks.maxScatteringOrder);
        v = {o.single * invCosO, (o.total - o.single) * invCosO, o.total * invCosO};
        return !o.escaped;
    });
    return {s.estimate(0), s.estimate(1), s.estimate(2), s.truncated};
}

MicrofacetDiffuseAlbedo estimateMicrofacetDiffuseAlbedo(const MicrofacetDiffuse& surface,
                                                        Direction wi, const RandomWalks& walks) {
    WalkSums<2> escaped = sumWalks<2>(walks.count, [&](int i, std::array<double, 2>& v) {
        WalkRandom random(walks.seed, std::uint64_t(i));
        WalkOutcome o = randomWalk(surface, wi, nullptr, random, walks.maxScatteringOrder);
        double energy = o.escaped ? o.weight : 0.0;
        v = {o.order == 1 ? energy : 0.0, energy};
        return !o.escaped;
    });
    // wo uniform over the hemisphere (pdf 1 / (2 pi): z uniform in (0, 1]); the estimate
    // 2 pi f cos(theta_o) stays bounded.
    WalkSums<2> lobe = sumWalks<2>(walks.count, [&](int i, std::array<double, 2>& v) {
        WalkRandom random(walks.seed ^ kIntegratedLobeStream, std::uint64_t(i));
        double z = 1.0 - random.uniform(), phi = 2.0 * std::numbers::pi * random.uniform();
        double sinO = std::sqrt(std::max(0.0, 1.0 - z * z));
        Direction wo = {sinO * std::cos(phi), sinO * std::sin(phi), z};
        WalkOutcome o = randomWalk(surface, wi, &wo, random, walks.maxScatteringOrder);
        v = {2.0 * std::numbers::pi * o.single, 2.0 * std::numbers::pi * o.total};
        return !o.escaped;
    });
    return {{escaped.estimate(0), escaped.estimate(1)},
            {lobe.estimate(0), lobe.estimate(1)},
            escaped.truncated + lobe.truncated};
}

// ---------------------------------------------------------------------------------------------
// Diffuse models

namespace {

float clampedNoV(double NoV) {
    return std::clamp(float(NoV), glsl::MIN_NOV, 1.0f);
}
float unit(double x) {
    return std::clamp(float(x), 0.0f, 1.0f);
}

// f of the model for view v and light l (unit, z up), through brdfDots' definitions in double.
double evaluate(const DiffuseModel& model, const Direction& v, const Direction& l, double gloss) {
    double VoL = dot(v, l);
    double lenH2 = std::max(2.0 + 2.0 * VoL, 1e-300);
    double hx = v.x + l.x, hy = v.y + l.y;
    double LoH = (1.0 + VoL) / std::sqrt(lenH2);
    double NxH2 = (hx * hx + hy * hy) / lenH2;
    return model.f(v.z, l.z, LoH, NxH2, gloss);
}

double degrees(double d) {
    return d * std::numbers::pi / 180.0;
}

}  // namespace

DiffuseModel lambertDiffuse() {
    return {"Lambert",
            [](double, double, double, double, double) { return double(glsl::Fd_Lambert()); }};
}

DiffuseModel chanDiffuse() {
    return {"Chan", [](double NoV, double NoL, double LoH, double NxH2, double gloss) {
                return double(
                    glsl::Fd_Chan(clampedNoV(NoV), unit(NoL), unit(LoH), unit(NxH2), float(gloss)));
            }};
}

double diffuseModelAlbedo(const DiffuseModel& model, double gloss, double theta) {
    const Direction v = directionFromAngles(theta, 0.0);
    // int f NoL dl = int_0^1 mu dmu int_0^2pi f dphi; f is even in phi (v in the xz-plane).
    const QuadratureTolerance outer{1e-9, 1e-7, 400}, inner{1e-10, 1e-7, 200};
    auto overMu = [&](double mu) {
        double sinL = std::sqrt(std::max(0.0, 1.0 - mu * mu));
        auto overPhi = [&](double phi) {
            Direction l = {sinL * std::cos(phi), sinL * std::sin(phi), mu};
            return Vec<1>{evaluate(model, v, l, gloss)};
        };
        return Vec<1>{2.0 * mu * integrate<1>(overPhi, 0.0, std::numbers::pi, inner)[0]};
    };
    return integrate<1>(overMu, 0.0, 1.0, outer)[0];
}

DiffuseReference buildDiffuseReference(const DiffuseComparisonGrid& grid) {
    DiffuseReference ref{grid, {}, {}};
    std::uint64_t point = 0;
    for (double gloss : grid.glosses) {
        const MicrofacetDiffuse surface{reference::ggxAlpha(gloss), 1.0};
        for (double viewDeg : grid.viewPolarDegrees) {
            const Direction v = directionFromAngles(degrees(viewDeg), 0.0);
            RandomWalks walks = grid.walks;
            walks.seed = mix64(grid.walks.seed + point++);
            ref.albedos.push_back(
                {gloss, viewDeg, estimateMicrofacetDiffuseAlbedo(surface, v, walks)});
            for (double lightDeg : grid.lightPolarDegrees)
                for (double azimuthDeg : grid.azimuthDegrees) {
                    if ((viewDeg == 0.0 || lightDeg == 0.0) && azimuthDeg != grid.azimuthDegrees[0])
                        continue;
                    const Direction l = directionFromAngles(degrees(lightDeg), degrees(azimuthDeg));
                    walks.seed = mix64(grid.walks.seed + point++);
                    // Light from l, next-event estimates towards the view.
                    ref.points.push_back(
                        {gloss, v, l, estimateMicrofacetDiffuseBrdf(surface, l, v, walks).total});
                }
        }
    }
    return ref;
}

std::vector<DiffuseModelError> measureDiffuseModel(const DiffuseModel& model,
                                                   const DiffuseReference& reference) {
    std::vector<DiffuseModelError> errors;
    for (double gloss : reference.grid.glosses) {
        DiffuseModelError e{gloss, 0.0, 0.0, 0.0, 1e300, -1e300, 0.0};
        int n = 0;
        for (const DiffuseReferencePoint& p : reference.points) {
            if (p.gloss != gloss) continue;
            double relative = (evaluate(model, p.view, p.light, gloss) - p.f.mean) / p.f.mean;
            double noise = p.f.standardError / p.f.mean;
            e.rmsRelativeError += relative * relative;
            e.referenceNoiseRms += noise * noise;
            e.maxAbsRelativeError = std::max(e.maxAbsRelativeError, std::abs(relative));
            ++n;
        }
        e.rmsRelativeError = std::sqrt(e.rmsRelativeError / std::max(n, 1));
        e.referenceNoiseRms = std::sqrt(e.referenceNoiseRms / std::max(n, 1));
        for (const DiffuseReferenceAlbedo& a : reference.albedos) {
            if (a.gloss != gloss) continue;
            double albedo = diffuseModelAlbedo(model, gloss, degrees(a.viewPolarDegrees));
            e.minAlbedo = std::min(e.minAlbedo, albedo);
            e.maxAlbedo = std::max(e.maxAlbedo, albedo);
            e.maxAbsAlbedoError =
                std::max(e.maxAbsAlbedoError, std::abs(albedo - a.albedo.escaped.total.mean));
        }
        errors.push_back(e);
    }
    return errors;
}

}  // namespace onelight::lab
