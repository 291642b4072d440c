// onelight-lab horizon-cut: what the floor takes from a normal map's specular. The split-sum
// table counts a texel's lobe over the hemisphere of its own (bent) normal; the reference ends
// the paths that leave below the surface's plane instead (bake/lighting/radiance.cpp), and a
// tilted texel's lobe crosses that plane. Over the texels of scripts/scenes.py's normal-mapped
// floor (egg-crate bumps, slopes up to 0.6 on each axis, roughness 0.15, f0 0.04, seen from
// 1.7 m), the mean specular albedo of the runtime lobe (shaders/brdf.glsl), by a midpoint
// quadrature over each texel's hemisphere, with and without the cut, at points of the floor
// straight ahead (docs/materials.md, "A footprint's bumps"). Beside it, the runtime's closed form
// of the share kept (specularShareAboveSurface, shaders/material.glsl) over the same texels, and
// both over the six normals of the footprint's ring (footprintRingNormal) that stand for them
// where a pixel covers whole bumps. At roughness 0.15 (the scenes'), 0.32 and 0.55.
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <numbers>

#include "commands.hpp"
#include "shading.hpp"

namespace onelight::lab {

namespace {

struct Albedo {
    double whole = 0.0;  // over the texel's hemisphere
    double above = 0.0;  // the part above the surface's plane
};

// The runtime lobe's albedo for shading normal n (surface normal ns) and view v, by the midpoint
// rule in (cos theta, phi) about n with `steps` x 4 `steps` cells.
Albedo albedoOf(glm::vec3 n, glm::vec3 ns, glm::vec3 v, float gloss, int steps) {
    const glm::vec3 t = glm::normalize(
        glm::cross(n, std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
    const glm::vec3 b = glm::cross(n, t);
    const double dMu = 1.0 / steps, dPhi = 2.0 * std::numbers::pi / (4.0 * steps);
    Albedo a;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < 4 * steps; ++j) {
            const double mu = (i + 0.5) * dMu, phi = (j + 0.5) * dPhi;
            const double s = std::sqrt(1.0 - mu * mu);
            const glm::vec3 l =
                n * float(mu) + t * float(s * std::cos(phi)) + b * float(s * std::sin(phi));
            const double f =
                double(glsl::specularLobe(NDF_GGX, VIS_SMITH_CORRELATED, FRESNEL_SCHLICK,
                                          glsl::vec3(0.04f), gloss, glsl::brdfDots(n, v, l))
                           .x) *
                dMu * dPhi;
            a.whole += f;
            if (glm::dot(l, ns) > 0.0f) a.above += f;
        }
    return a;
}

}  // namespace

int horizonCut(int steps) {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    constexpr int kTexels = 16;  // per axis of one bump
    constexpr float kAmplitude = 0.6f;
    // The egg crate's RMS slope over both axes: 0.6^2 (1/4 + 1/4).
    const float ringRadius = kAmplitude * std::sqrt(0.5f);
    std::printf(
        "roughness,distance m,view elevation deg,albedo over each texel's hemisphere,"
        "above the floor,ratio,closed form,ring ratio,ring closed form\n");
    for (float roughness : {0.15f, 0.32f, 0.55f}) {
        const float gloss = glsl::gloss_fromRoughness(roughness);
        const float alpha = glsl::ggxAlpha_fromGloss(gloss);
        for (float distance : {2.8f, 6.6f, 12.7f, 46.6f}) {
            const glm::vec3 v = glm::normalize(glm::vec3(0.0f, 1.7f, distance));
            // albedo-weighted means: the quadrature's whole and above, the closed form's share
            double whole = 0.0, above = 0.0, closed = 0.0;
            for (int i = 0; i < kTexels; ++i)
                for (int j = 0; j < kTexels; ++j) {
                    const double u = 2.0 * std::numbers::pi * (i + 0.5) / kTexels;
                    const double w = 2.0 * std::numbers::pi * (j + 0.5) / kTexels;
                    const float sx = float(double(kAmplitude) * std::cos(u) * std::sin(w));
                    const float sy = float(double(kAmplitude) * std::sin(u) * std::cos(w));
                    const glm::vec3 n = glsl::normal_withValidReflection(
                        glm::normalize(glm::vec3(-sx, 1.0f, -sy)), up, v);
                    const Albedo a = albedoOf(n, up, v, gloss, steps);
                    whole += a.whole;
                    above += a.above;
                    closed += a.whole * double(glsl::specularShareAboveSurface(n, up, v, alpha));
                }
            double ringWhole = 0.0, ringAbove = 0.0, ringClosed = 0.0;
            const glm::vec3 t = glm::normalize(v - up * glm::dot(up, v));
            const glm::vec3 b = glm::cross(up, t);
            for (int k = 0; k < glsl::FOOTPRINT_RING_COUNT; ++k) {
                const glm::vec3 n = glsl::normal_withValidReflection(
                    glsl::footprintRingNormal(up, t, b, ringRadius, k), up, v);
                const Albedo a = albedoOf(n, up, v, gloss, steps);
                ringWhole += a.whole;
                ringAbove += a.above;
                ringClosed += a.whole * double(glsl::specularShareAboveSurface(n, up, v, alpha));
            }
            std::printf("%.2f,%.1f,%.2f,%.4f,%.4f,%.3f,%.3f,%.3f,%.3f\n", double(roughness),
                        double(distance), std::asin(double(v.y)) * 180.0 / std::numbers::pi,
                        whole / (kTexels * kTexels), above / (kTexels * kTexels), above / whole,
                        closed / whole, ringAbove / ringWhole, ringClosed / ringWhole);
            std::fflush(stdout);
        }
    }
    return 0;
}

}  // namespace onelight::lab
