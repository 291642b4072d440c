#include "bake/textures/mip_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "bake/parallel_for.hpp"
#include "shading.hpp"

namespace onelight::bake {

namespace {

// The runtime specular lobe f_spec * NoL for a grey f0 (shaders/brdf.glsl, specularLobe).
double lobe(glm::vec3 n, float gloss, const ViewLight& p, float f0) {
    glsl::BrdfDots d = glsl::brdfDots(n, p.view, p.light);
    return double(
        glsl::specularLobe(NDF_GGX, VIS_SMITH_CORRELATED, FRESNEL_SCHLICK, glsl::vec3(f0), gloss, d)
            .x);
}

// The runtime footprint's specular for a mip texel of gloss g and base gloss gb
// (footprintReflectance of lighting.glsl, no diffuse); the lobe where gb is not known.
double footprintSpecular(glm::vec3 n, float gloss, float baseGloss, const ViewLight& p, float f0) {
    glsl::BrdfDots d = glsl::brdfDots(n, p.view, p.light);
    return double(glsl::footprintReflectance(MATERIAL_DIELECTRIC, DIFFUSE_LAMBERT, glsl::vec3(0.0f),
                                             glsl::vec3(0.0f), glsl::vec3(f0), gloss,
                                             glsl::bumpShare(gloss, baseGloss), 1.0f, d)
                      .x);
}

// Sums of level-0 shading over a footprint.
struct Footprint {
    double shading = 0.0;
    double texels = 0.0;
};

// Per mip of one chain, for one (v, l) pair: sums of |F| S_ref^2, |F| (S_mip - S_ref)^2, |F|.
struct Accumulator {
    double reference2 = 0.0, difference2 = 0.0, weight = 0.0;
};

void accumulate(Accumulator& a, double mip, double reference, double texels) {
    a.reference2 += texels * reference * reference;
    a.difference2 += texels * (mip - reference) * (mip - reference);
    a.weight += texels;
}

void checkChain(const NormalGlossLevel& level0, const NormalGlossChain& chain) {
    const int levels = mipLevelCount(level0.width, level0.height);
    bool ok = int(chain.size()) == levels;
    for (int k = 0; ok && k < levels; ++k) {
        const NormalGlossLevel& m = chain[std::size_t(k)];
        std::size_t texels = std::size_t(m.width) * std::size_t(m.height);
        ok = m.width == mipSize(level0.width, k) && m.height == mipSize(level0.height, k) &&
             m.normals.size() == texels && m.gloss.size() == texels;
    }
    if (!ok) throw std::invalid_argument("mipError: the chain does not fit level 0");
}

}  // namespace

std::vector<ViewLight> incidencePlaneSweep(
    const std::vector<glm::vec2>& viewElevationAzimuthDegrees, int lightsPerView) {
    const double degree = std::numbers::pi / 180.0;
    std::vector<ViewLight> sweep;
    for (glm::vec2 ea : viewElevationAzimuthDegrees) {
        double e = double(ea.x) * degree, a = double(ea.y) * degree;
        glm::dvec3 horizontal(std::cos(a), std::sin(a), 0.0);
        glm::dvec3 view = std::cos(e) * horizontal + glm::dvec3(0.0, 0.0, std::sin(e));
        for (int j = 0; j < lightsPerView; ++j) {
            double psi = (j + 0.5) * 180.0 / lightsPerView * degree;
            glm::dvec3 light = -std::cos(psi) * horizontal + glm::dvec3(0.0, 0.0, std::sin(psi));
            sweep.push_back({glm::vec3(view), glm::vec3(light)});
        }
    }
    return sweep;
}

std::vector<std::vector<MipLevelError>> mipErrors(const NormalGlossLevel& level0,
                                                  std::span<const NormalGlossChain> chains,
                                                  const std::vector<ViewLight>& sweep, float f0,
                                                  MipShading shading) {
    const int w0 = level0.width, h0 = level0.height;
    if (w0 < 1 || h0 < 1 || level0.normals.size() != std::size_t(w0) * std::size_t(h0) ||
        level0.gloss.size() != level0.normals.size())
        throw std::invalid_argument("mipError: level 0 is not width x height texels");
    for (const NormalGlossChain& chain : chains) checkChain(level0, chain);

    const int levels = mipLevelCount(w0, h0);
    const std::size_t perPair = chains.size() * std::size_t(levels);
    std::vector<Accumulator> accumulators(sweep.size() * perPair);

    parallelFor(std::size_t(0), sweep.size(), [&](std::size_t p) {
        const ViewLight& pair = sweep[p];
        Accumulator* acc = &accumulators[p * perPair];
        std::vector<Footprint> sums(level0.normals.size());
        for (std::size_t i = 0; i < sums.size(); ++i)
            sums[i] = {lobe(level0.normals[i], level0.gloss[i], pair, f0), 1.0};

        for (int level = 0; level < levels; ++level) {
            const int pw = mipSize(w0, std::max(level - 1, 0)),
                      ph = mipSize(h0, std::max(level - 1, 0));
            const int w = mipSize(w0, level), h = mipSize(h0, level);
            if (level > 0) {
                std::vector<Footprint> next(std::size_t(w) * std::size_t(h));
                for (int y = 0; y < h; ++y) {
                    TexelRange rows = mipChildren(ph, y);
                    for (int x = 0; x < w; ++x) {
                        TexelRange columns = mipChildren(pw, x);
                        Footprint f;
                        for (int py = rows.begin; py < rows.end; ++py)
                            for (int px = columns.begin; px < columns.end; ++px) {
                                const Footprint& c =
                                    sums[std::size_t(py) * std::size_t(pw) + std::size_t(px)];
                                f.shading += c.shading;
                                f.texels += c.texels;
                            }
                        next[std::size_t(y) * std::size_t(w) + std::size_t(x)] = f;
                    }
                }
                sums = std::move(next);
            }
            for (std::size_t c = 0; c < chains.size(); ++c) {
                const NormalGlossLevel& mip = chains[c][std::size_t(level)];
                Accumulator& a = acc[c * std::size_t(levels) + std::size_t(level)];
                for (std::size_t i = 0; i < sums.size(); ++i) {
                    double reference = sums[i].shading / sums[i].texels;
                    const double shaded =
                        shading == MipShading::kFootprint && !mip.baseGloss.empty()
                            ? footprintSpecular(mip.normals[i], mip.gloss[i], mip.baseGloss[i],
                                                pair, f0)
                            : lobe(mip.normals[i], mip.gloss[i], pair, f0);
                    accumulate(a, shaded, reference, sums[i].texels);
                }
            }
        }
    });

    std::vector<std::vector<MipLevelError>> result(chains.size());
    for (std::size_t c = 0; c < chains.size(); ++c) {
        for (int level = 0; level < levels; ++level) {
            Accumulator total;
            for (std::size_t p = 0; p < sweep.size(); ++p) {
                const Accumulator& a =
                    accumulators[p * perPair + c * std::size_t(levels) + std::size_t(level)];
                total.reference2 += a.reference2;
                total.difference2 += a.difference2;
                total.weight += a.weight;
            }
            MipLevelError e;
            e.level = level;
            e.width = mipSize(w0, level);
            e.height = mipSize(h0, level);
            if (total.weight > 0.0) {
                e.rmsReference = std::sqrt(total.reference2 / total.weight);
                e.rmsDifference = std::sqrt(total.difference2 / total.weight);
            }
            e.relativeError = e.rmsReference > 0.0    ? e.rmsDifference / e.rmsReference
                              : e.rmsDifference > 0.0 ? std::numeric_limits<double>::infinity()
                                                      : 0.0;
            result[c].push_back(e);
        }
    }
    return result;
}

std::vector<MipLevelError> mipError(const NormalGlossLevel& level0, const NormalGlossChain& chain,
                                    const std::vector<ViewLight>& sweep, float f0) {
    return mipErrors(level0, std::span<const NormalGlossChain>(&chain, 1), sweep, f0).front();
}

}  // namespace onelight::bake
