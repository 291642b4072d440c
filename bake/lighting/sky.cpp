#include "bake/lighting/sky.hpp"

#include <algorithm>
#include <cmath>

#include "bake/lighting/sampling.hpp"
#include "shading.hpp"

namespace onelight::bake {
namespace {

// The cumulative sums of `weights`, normalized to end at 1: uniform when they sum to 0.
void appendCdf(const std::vector<double>& weights, std::vector<float>& cdf) {
    double total = 0.0;
    for (double w : weights) total += w;
    double sum = 0.0;
    cdf.push_back(0.0f);
    for (size_t k = 0; k < weights.size(); ++k) {
        sum += weights[k];
        const double f = total > 0.0 ? sum / total : double(k + 1) / double(weights.size());
        cdf.push_back(float(f));
    }
    cdf.back() = 1.0f;
}

// The interval k of `cdf` (begin .. begin + n + 1) holding x, and x's place within it.
uint32_t findInterval(const float* cdf, uint32_t n, float x, float& within) {
    const float* at = std::upper_bound(cdf, cdf + n + 1, x);
    const uint32_t k = uint32_t(std::clamp<std::ptrdiff_t>(at - cdf - 1, 0, std::ptrdiff_t(n) - 1));
    const float width = cdf[k + 1] - cdf[k];
    within = width > 0.0f ? std::clamp((x - cdf[k]) / width, 0.0f, 0.99999994f) : 0.5f;
    return k;
}

// sin(theta) of a direction, from its height.
float sinTheta(const glm::vec3& d) {
    return std::sqrt(std::max(0.0f, 1.0f - d.y * d.y));
}

// p(w) from the texel's p(u, v): dw = 2 pi^2 sin(theta) du dv.
float solidAngleDensity(float texelDensity, float sine) {
    return sine > 0.0f ? texelDensity / (2.0f * glsl::PI * glsl::PI * sine) : 0.0f;
}

}  // namespace

SkyImage makeSkyImage(const world::HdrImage& image, glm::vec3 scale) {
    SkyImage sky;
    sky.width = image.width;
    sky.height = image.height;
    const size_t count = size_t(image.width) * image.height;
    if (count == 0) return sky;
    sky.radiance.resize(count);
    double meanY = 0.0;
    for (size_t t = 0; t < count; ++t) {
        const glm::vec3 l =
            glm::vec3(image.rgb[3 * t], image.rgb[3 * t + 1], image.rgb[3 * t + 2]) * scale;
        sky.radiance[t] = glm::max(l, glm::vec3(0.0f));
        meanY += double(glsl::luminance(sky.radiance[t]));
    }
    meanY /= double(count);
    const double floorY = meanY > 0.0 ? meanY / 64.0 : 1.0;
    // The mean of the bilinear lookup over each texel: [1/8, 3/4, 1/8] each way (wrapping in
    // u, clamped in v), so the light a hot texel spreads into its neighbours has density there.
    const int w = int(image.width), h = int(image.height);
    const auto luminanceAt = [&](int i, int j) {
        i = std::clamp(i, 0, h - 1);
        j = ((j % w) + w) % w;
        return double(glsl::luminance(sky.radiance[size_t(i) * image.width + size_t(j)]));
    };
    constexpr double kTexelMean[3] = {0.125, 0.75, 0.125};
    std::vector<double> weights(count), rowWeights(image.height), row(image.width);
    double total = 0.0;
    for (uint32_t i = 0; i < image.height; ++i) {
        const double sine = std::sin(double(glsl::PI) * (double(i) + 0.5) / double(image.height));
        double sum = 0.0;
        for (uint32_t j = 0; j < image.width; ++j) {
            const size_t t = size_t(i) * image.width + j;
            double mean = 0.0;
            for (int a = -1; a <= 1; ++a)
                for (int b = -1; b <= 1; ++b)
                    mean +=
                        kTexelMean[a + 1] * kTexelMean[b + 1] * luminanceAt(int(i) + a, int(j) + b);
            weights[t] = (mean + floorY) * sine;
            sum += weights[t];
        }
        rowWeights[i] = sum;
        total += sum;
    }
    appendCdf(rowWeights, sky.rowCdf);
    sky.columnCdf.reserve(size_t(image.height) * (image.width + 1));
    sky.texelDensity.resize(count);
    for (uint32_t i = 0; i < image.height; ++i) {
        for (uint32_t j = 0; j < image.width; ++j) row[j] = weights[size_t(i) * image.width + j];
        appendCdf(row, sky.columnCdf);
    }
    for (size_t t = 0; t < count; ++t)
        sky.texelDensity[t] = float(weights[t] * double(count) / total);
    return sky;
}

glm::vec3 skyRadiance(const SkyImage& sky, const glm::vec3& direction) {
    if (sky.empty()) return glm::vec3(0.0f);
    const glm::vec2 uv = glsl::equirectUv_fromDirection(direction);
    const float x = uv.x * float(sky.width) - 0.5f, y = uv.y * float(sky.height) - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = std::clamp(y - y0, 0.0f, 1.0f);
    const int w = int(sky.width), h = int(sky.height);
    const int j0 = ((int(x0) % w) + w) % w, j1 = (j0 + 1) % w;
    const int i0 = std::clamp(int(y0), 0, h - 1), i1 = std::clamp(int(y0) + 1, 0, h - 1);
    const auto at = [&](int i, int j) { return sky.radiance[size_t(i) * sky.width + size_t(j)]; };
    const glm::vec3 top = glm::mix(at(i0, j0), at(i0, j1), fx);
    const glm::vec3 bottom = glm::mix(at(i1, j0), at(i1, j1), fx);
    return glm::mix(top, bottom, fy);
}

SkySample sampleSky(const SkyImage& sky, glm::vec2 u) {
    SkySample out;
    if (sky.empty()) return out;
    float dv = 0.0f, du = 0.0f;
    const uint32_t i = findInterval(sky.rowCdf.data(), sky.height, u.y, dv);
    const uint32_t j =
        findInterval(sky.columnCdf.data() + size_t(i) * (sky.width + 1), sky.width, u.x, du);
    const glm::vec2 uv((float(j) + du) / float(sky.width), (float(i) + dv) / float(sky.height));
    out.direction = glsl::direction_fromEquirectUv(uv);
    out.pdf =
        solidAngleDensity(sky.texelDensity[size_t(i) * sky.width + j], std::sin(glsl::PI * uv.y));
    if (out.pdf > 0.0f) out.radiance = skyRadiance(sky, out.direction);
    return out;
}

float skyPdf(const SkyImage& sky, const glm::vec3& direction) {
    if (sky.empty()) return 0.0f;
    const glm::vec2 uv = glsl::equirectUv_fromDirection(direction);
    const uint32_t j = std::min(sky.width - 1, uint32_t(std::max(0.0f, uv.x * float(sky.width))));
    const uint32_t i = std::min(sky.height - 1, uint32_t(std::max(0.0f, uv.y * float(sky.height))));
    return solidAngleDensity(sky.texelDensity[size_t(i) * sky.width + j], sinTheta(direction));
}

}  // namespace onelight::bake
