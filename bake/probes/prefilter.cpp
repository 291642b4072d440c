#include "prefilter.hpp"

#include <algorithm>
#include <cmath>

#include "bake/parallel_for.hpp"
#include "shading.hpp"

namespace onelight::bake {

namespace glsl = onelight::glsl;

namespace {

// Van der Corput radical inverse in base 2 (the second Hammersley coordinate).
float radicalInverse(uint32_t bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return float(bits) * 2.3283064365386963e-10f;
}

// An orthonormal frame around unit n (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited").
void frame(glm::vec3 n, glm::vec3& t, glm::vec3& b) {
    float sign = std::copysign(1.0f, n.z);
    float a = -1.0f / (sign + n.z), c = n.x * n.y * a;
    t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

}  // namespace

int prefilterSampleCount(float alpha, int sourceSize, const PrefilterOptions& options) {
    // GGX: P(tan^2 theta_h <= x) = x / (alpha^2 + x), so 90% of the half vectors lie within
    // tan^2 = 9 alpha^2; the reflected directions spread over twice that angle.
    float thetaH = std::atan(3.0f * alpha);
    float lobeSolidAngle =
        2.0f * glsl::PI * (1.0f - std::cos(std::min(2.0f * thetaH, glsl::PI / 2)));
    float texel = 4.0f * glsl::PI / (6.0f * float(sourceSize) * float(sourceSize));
    float wanted = std::ceil(4.0f * lobeSolidAngle / texel);
    return int(
        std::clamp(wanted, float(options.samplesPerTexel), float(options.maxSamplesPerTexel)));
}

namespace {

// L(r) = sum_t L_t D(h_t) NoL_t Omega_t / sum_t D(h_t) NoL_t Omega_t over every texel t of `src`.
glm::vec3 sumOverTexels(const CubeMip& src, glm::vec3 r, float alpha) {
    glm::vec3 sum(0.0f);
    float weight = 0.0f;
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < src.size; ++y)
            for (int x = 0; x < src.size; ++x) {
                glm::vec3 l = texelDirection(face, x, y, src.size);
                float NoL = glm::dot(r, l);
                if (NoL <= 0.0f) continue;
                glm::vec3 c = glm::cross(r, glm::normalize(r + l));
                float w =
                    glsl::D_GGX(glm::dot(c, c), alpha) * NoL * texelSolidAngle(x, y, src.size);
                sum += src.at(face, x, y) * w;
                weight += w;
            }
    return weight > 0.0f ? sum / weight : glm::vec3(0.0f);
}

}  // namespace

Cubemap prefilterGGX(Cubemap radiance, const PrefilterOptions& options) {
    downsampleMips(radiance);
    Cubemap out = makeCubemap(radiance.mips[0].size);
    out.mips[0] = radiance.mips[0];
    const int mipCount = out.mipCount();
    const float baseTexelSolidAngle =
        4.0f * glsl::PI / (6.0f * float(radiance.mips[0].size) * float(radiance.mips[0].size));
    for (int m = 1; m < mipCount; ++m) {
        CubeMip& dst = out.mips[m];
        float alpha = glsl::ggxAlpha_fromGloss(glsl::probeGlossOfMip(m, mipCount));
        float a2 = alpha * alpha;
        const int n = prefilterSampleCount(alpha, radiance.mips[0].size, options);
        // The coarsest source mip with texels at most alpha / 16 across (a texel spans about
        // (pi / 2) / size radians), and what summing over it would cost against sampling.
        float baseTexelAngle = 0.5f * glsl::PI / float(radiance.mips[0].size);
        int sourceMip = std::clamp(int(std::floor(std::log2(alpha / (16.0f * baseTexelAngle)))), 0,
                                   mipCount - 1);
        const CubeMip& coarse = radiance.mips[sourceMip];
        bool sumTexels = 6.0 * coarse.size * coarse.size <= 2.0 * double(n);  // exact: wins ties
        bake::parallelFor(0, 6 * dst.size, [&](int row) {
            int face = row / dst.size, y = row % dst.size;
            for (int x = 0; x < dst.size; ++x) {
                if (sumTexels) {
                    dst.at(face, x, y) =
                        sumOverTexels(coarse, texelDirection(face, x, y, dst.size), alpha);
                    continue;
                }
                glm::vec3 r = texelDirection(face, x, y, dst.size), t, b;
                frame(r, t, b);
                glm::vec3 sum(0.0f);
                float weight = 0.0f;
                for (int k = 0; k < n; ++k) {
                    // GGX half vector about r: cos^2 theta = (1 - u) / (1 + (a^2 - 1) u)
                    // (Walter et al. 2007, eq. 35); pdf(h) = D(h) NoH.
                    float u1 = (k + 0.5f) / n, u2 = radicalInverse(uint32_t(k));
                    float cos2 = (1.0f - u1) / (1.0f + (a2 - 1.0f) * u1);
                    float cosH = std::sqrt(cos2), sinH = std::sqrt(std::max(0.0f, 1.0f - cos2));
                    float phi = 2.0f * glsl::PI * u2;
                    glm::vec3 h =
                        t * (sinH * std::cos(phi)) + b * (sinH * std::sin(phi)) + r * cosH;
                    glm::vec3 l = 2.0f * glm::dot(r, h) * h - r;
                    float NoL = glm::dot(r, l);
                    if (NoL <= 0.0f) continue;
                    // pdf(l) = D(h) NoH / (4 VoH) = D(h) / 4 with n = v = r.
                    float D = glsl::D_GGX(sinH * sinH, alpha);
                    float sampleSolidAngle = 4.0f / (float(n) * D);
                    float lod = 0.5f * std::log2(sampleSolidAngle / baseTexelSolidAngle);
                    sum += sampleTrilinear(radiance, l, lod) * NoL;
                    weight += NoL;
                }
                dst.at(face, x, y) = weight > 0.0f ? sum / weight : glm::vec3(0.0f);
            }
        });
    }
    return out;
}

glm::vec3 prefilteredReference(const Cubemap& radiance, glm::vec3 r, float alpha,
                               int subdivisions) {
    const CubeMip& src = radiance.mips[0];
    double sum[3] = {0, 0, 0}, weight = 0.0;
    int fine = src.size * subdivisions;
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < fine; ++y)
            for (int x = 0; x < fine; ++x) {
                glm::vec3 l = texelDirection(face, x, y, fine);
                double NoL = glm::dot(r, l);
                if (NoL <= 0.0) continue;
                glm::vec3 h = glm::normalize(r + l);
                glm::vec3 c = glm::cross(r, h);
                double w = double(glsl::D_GGX(glm::dot(c, c), alpha)) * NoL *
                           double(texelSolidAngle(x, y, fine));
                glm::vec3 L = sampleBilinear(src, l);
                for (int i = 0; i < 3; ++i) sum[i] += w * double(L[i]);
                weight += w;
            }
    return glm::vec3(float(sum[0] / weight), float(sum[1] / weight), float(sum[2] / weight));
}

}  // namespace onelight::bake
