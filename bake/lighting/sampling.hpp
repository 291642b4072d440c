// Random numbers and sampling routines of the baker. Every sequence is counter-based: a texel,
// a grid cell or a pixel seeds its own stream from its identity, so results never depend on
// which thread ran it or in which order.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "shading.hpp"

namespace onelight::bake {

// Jarzynski and Olano 2020, "Hash Functions for GPU Rendering", JCGT 9(3), "pcg" (the PCG
// output permutation applied to one LCG step of the input).
[[nodiscard]] inline uint32_t pcgHash(uint32_t input) {
    const uint32_t state = input * 747796405u + 2891336453u;
    const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

/// Seed from an identity of up to four words (e.g. atlas, x, y, pass); order matters.
[[nodiscard]] inline uint32_t seedFrom(uint32_t a, uint32_t b = 0, uint32_t c = 0, uint32_t d = 0) {
    return pcgHash(d ^ pcgHash(c ^ pcgHash(b ^ pcgHash(a))));
}

/// A stream of uniform numbers: the hash of (seed, counter). Counter-based, so a sample's
/// numbers depend only on the seed and how many numbers came before it in that stream.
struct Rng {
    uint32_t seed = 0;
    uint32_t counter = 0;

    /// Uniform in [0, 1): the top 24 bits of the hash, exactly representable in float.
    float next() {
        const uint32_t bits = pcgHash(seed ^ pcgHash(counter++));
        return static_cast<float>(bits >> 8) * (1.0f / 16777216.0f);
    }
};

/// Van der Corput radical inverse in base 2 (bit reversal), in [0, 1).
[[nodiscard]] inline float radicalInverse2(uint32_t i) {
    i = (i << 16u) | (i >> 16u);
    i = ((i & 0x00ff00ffu) << 8u) | ((i & 0xff00ff00u) >> 8u);
    i = ((i & 0x0f0f0f0fu) << 4u) | ((i & 0xf0f0f0f0u) >> 4u);
    i = ((i & 0x33333333u) << 2u) | ((i & 0xccccccccu) >> 2u);
    i = ((i & 0x55555555u) << 1u) | ((i & 0xaaaaaaaau) >> 1u);
    return static_cast<float>(i >> 8) * (1.0f / 16777216.0f);
}

/// Point i of an n-point Hammersley set shifted by (s0, s1) modulo 1 (Cranley-Patterson
/// rotation): stratified within a texel, decorrelated between texels.
[[nodiscard]] inline glm::vec2 rotatedHammersley(uint32_t i, uint32_t n, float s0, float s1) {
    float u = (static_cast<float>(i) + 0.5f) / static_cast<float>(n) + s0;
    float v = radicalInverse2(i) + s1;
    u -= std::floor(u);
    v -= std::floor(v);
    return {u < 1.0f ? u : 0.0f, v < 1.0f ? v : 0.0f};
}

/// Orthonormal basis around a unit vector. Duff et al. 2017, "Building an Orthonormal Basis,
/// Revisited", JCGT 6(1), listing 3: branchless, no singularity except exactly at the sign flip.
struct Frame {
    glm::vec3 t, b, n;
    glm::vec3 toWorld(const glm::vec3& v) const { return t * v.x + b * v.y + n * v.z; }
};
[[nodiscard]] inline Frame frameAround(const glm::vec3& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return {glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x),
            glm::vec3(b, sign + n.y * n.y * a, -n.y), n};
}

/// Cosine-weighted direction on the hemisphere around +z, by Malley's method (a uniform
/// point on the unit disc lifted to the hemisphere).
// pdf = cos(theta) / pi   (solid angle)
[[nodiscard]] inline glm::vec3 sampleCosineHemisphere(glm::vec2 u) {
    const float r = std::sqrt(u.x);
    const float phi = 2.0f * glsl::PI * u.y;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x))};
}

/// Uniform direction on the unit sphere (Archimedes: z uniform in [-1, 1]).
// pdf = 1 / (4 pi)   (solid angle)
[[nodiscard]] inline glm::vec3 sampleUniformSphere(glm::vec2 u) {
    const float z = 1.0f - 2.0f * u.x;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * glsl::PI * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

/// Uniform direction inside the cone of half-angle acos(cos_max) around +z. The cosine is
/// written as 1 - u (1 - cos_max) with 1 - cos_max passed in directly, so cones of a few
/// arc-minutes (the sun) keep their digits: Pharr et al., PBRT 3rd ed., sec. 13.6.4.
// pdf = 1 / (2 pi oneMinusCosMax)   (solid angle)
[[nodiscard]] inline glm::vec3 sampleUniformCone(glm::vec2 u, float oneMinusCosMax) {
    const float oneMinusCos = u.x * oneMinusCosMax;
    const float cosTheta = 1.0f - oneMinusCos;
    const float sinTheta = std::sqrt(std::max(0.0f, oneMinusCos * (2.0f - oneMinusCos)));
    const float phi = 2.0f * glsl::PI * u.y;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

/// Rec. 709 luminance of linear RGB (shaders/common.glsl).
using glsl::luminance;

}  // namespace onelight::bake
