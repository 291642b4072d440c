#include "bake/materials/bake_textures.hpp"

#include "shading.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/packing.hpp>

namespace onelight::bake {
namespace {

constexpr uint16_t kClampToEdge = 33071;
constexpr uint16_t kMirroredRepeat = 33648;
constexpr uint16_t kNearest = 9728;

const std::array<float, 256>& srgbTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[size_t(i)] = glsl::srgbDecode(float(i) / 255.0f);
        return t;
    }();
    return table;
}

// Texel index along one axis of `size` texels for integer coordinate i under wrap mode `wrap`.
int32_t wrapIndex(int32_t i, int32_t size, uint16_t wrap) {
    if (wrap == kClampToEdge) return std::clamp(i, 0, size - 1);
    if (wrap == kMirroredRepeat) {
        const int32_t period = 2 * size;
        int32_t m = i % period;
        if (m < 0) m += period;
        return m < size ? m : period - 1 - m;
    }
    int32_t m = i % size;  // REPEAT (and anything unknown)
    return m < 0 ? m + size : m;
}

// Bilinear sample of mip `level` at uv.
glm::vec4 bilinear(const BakeTexture& t, uint32_t level, glm::vec2 uv, bool nearest) {
    const int32_t w = int32_t(std::max(t.width >> level, 1u));
    const int32_t h = int32_t(std::max(t.height >> level, 1u));
    const glm::vec4* texels = t.texels.data() + t.mipOffset[level];
    // A uv that is not finite reads texel 0 (no NaN reaches a sample).
    const float fx = std::isfinite(uv.x) ? uv.x * float(w) - 0.5f : 0.0f;
    const float fy = std::isfinite(uv.y) ? uv.y * float(h) - 0.5f : 0.0f;
    const float x0f = std::floor(fx), y0f = std::floor(fy);
    const float tx = fx - x0f, ty = fy - y0f;
    // Far outside the texture only the position within the wrap's period matters (repeat and
    // mirror: 4 size is a multiple of both periods), or which edge is nearest (clamp).
    const auto reduce = [](float v, int32_t size, uint16_t wrap) {
        if (wrap == kClampToEdge) return int32_t(std::clamp(v, -1.0f, float(size)));
        return int32_t(std::fmod(double(v), double(4 * size)));
    };
    const int32_t x0 = reduce(x0f, w, t.wrapS), y0 = reduce(y0f, h, t.wrapT);
    auto at = [&](int32_t x, int32_t y) {
        return texels[size_t(wrapIndex(y, h, t.wrapT)) * size_t(w) +
                      size_t(wrapIndex(x, w, t.wrapS))];
    };
    if (nearest) return at(tx < 0.5f ? x0 : x0 + 1, ty < 0.5f ? y0 : y0 + 1);
    const glm::vec4 top = at(x0, y0) * (1.0f - tx) + at(x0 + 1, y0) * tx;
    const glm::vec4 bottom = at(x0, y0 + 1) * (1.0f - tx) + at(x0 + 1, y0 + 1) * tx;
    return top * (1.0f - ty) + bottom * ty;
}

}  // namespace

BakeTexture makeBakeTexture(const world::DecodedImage& image, bool srgb, bool overCoverage,
                            const world::Sampler& sampler) {
    BakeTexture t;
    t.width = std::max(image.width, 1u);
    t.height = std::max(image.height, 1u);
    t.wrapS = sampler.wrapS;
    t.wrapT = sampler.wrapT;
    t.magNearest = sampler.magFilter == kNearest;
    uint32_t levels = 1;
    while ((t.width | t.height) >> levels) ++levels;
    t.mipCount = levels;
    uint64_t total = 0;
    for (uint32_t m = 0; m < levels; ++m) {
        t.mipOffset.push_back(total);
        total += uint64_t(std::max(t.width >> m, 1u)) * std::max(t.height >> m, 1u);
    }
    t.texels.resize(total);
    const std::array<float, 256>& decode = srgbTable();
    const size_t pixels = size_t(image.width) * image.height;
    for (size_t i = 0; i < pixels && i < t.texels.size(); ++i) {
        const uint8_t* p = &image.rgba[4 * i];
        const float alpha = float(p[3]) / 255.0f;  // alpha is linear in every format
        t.texels[i] = srgb ? glm::vec4(decode[p[0]], decode[p[1]], decode[p[2]], alpha)
                           : glm::vec4(float(p[0]), float(p[1]), float(p[2]), float(p[3])) / 255.0f;
    }
    // Each mip texel: the mean of the 2x2 (or 2x1, 1x2) texels above it; with `overCoverage` the
    // colour averaged over the coverage, sum(c a) / sum(a), where some but not all of them cover.
    const auto mean = [overCoverage](glm::vec4 a, glm::vec4 b, glm::vec4 c, glm::vec4 d) {
        const glm::vec4 plain = 0.25f * (a + b + c + d);
        if (!overCoverage || plain.w >= 1.0f || plain.w <= 0.0f) return plain;
        const glm::vec3 covered =
            (glm::vec3(a) * a.w + glm::vec3(b) * b.w + glm::vec3(c) * c.w + glm::vec3(d) * d.w) /
            (a.w + b.w + c.w + d.w);
        return glm::vec4(covered, plain.w);
    };
    for (uint32_t m = 1; m < levels; ++m) {
        const uint32_t pw = std::max(t.width >> (m - 1), 1u),
                       ph = std::max(t.height >> (m - 1), 1u);
        const uint32_t w = std::max(t.width >> m, 1u), h = std::max(t.height >> m, 1u);
        const glm::vec4* src = t.texels.data() + t.mipOffset[m - 1];
        glm::vec4* dst = t.texels.data() + t.mipOffset[m];
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                const uint32_t x0 = std::min(2 * x, pw - 1), x1 = std::min(2 * x + 1, pw - 1);
                const uint32_t y0 = std::min(2 * y, ph - 1), y1 = std::min(2 * y + 1, ph - 1);
                dst[size_t(y) * w + x] = mean(src[size_t(y0) * pw + x0], src[size_t(y0) * pw + x1],
                                              src[size_t(y1) * pw + x0], src[size_t(y1) * pw + x1]);
            }
    }
    // A cut-out's wholly clear texels take their parent's colour, the coarsest first: the colour
    // of what covers nearby, as the texture stage's mips (fillClearTexels in
    // bake/textures/texture_stage.cpp), so that no filter blends the holes' colour into an edge.
    if (overCoverage)
        for (uint32_t m = levels - 1; m-- > 0;) {
            const uint32_t w = std::max(t.width >> m, 1u), h = std::max(t.height >> m, 1u);
            const uint32_t pw = std::max(t.width >> (m + 1), 1u);
            const uint32_t ph = std::max(t.height >> (m + 1), 1u);
            glm::vec4* here = t.texels.data() + t.mipOffset[m];
            const glm::vec4* parent = t.texels.data() + t.mipOffset[m + 1];
            for (uint32_t y = 0; y < h; ++y)
                for (uint32_t x = 0; x < w; ++x) {
                    glm::vec4& texel = here[size_t(y) * w + x];
                    if (texel.w > 0.0f) continue;
                    const glm::vec4& p =
                        parent[size_t(std::min(y / 2, ph - 1)) * pw + std::min(x / 2, pw - 1)];
                    texel = glm::vec4(glm::vec3(p), texel.w);
                }
        }
    return t;
}

BakeTexture makeBakeTexture(const world::ProcessedTexture& processed) {
    BakeTexture t;
    t.width = processed.width;
    t.height = processed.height;
    t.mipCount = processed.mipCount;
    t.wrapS = processed.sampler.wrapS;
    t.wrapT = processed.sampler.wrapT;
    t.magNearest = processed.sampler.magFilter == kNearest;
    uint64_t total = 0;
    for (uint32_t m = 0; m < t.mipCount; ++m) {
        t.mipOffset.push_back(total);
        total += uint64_t(std::max(t.width >> m, 1u)) * std::max(t.height >> m, 1u);
    }
    t.texels.resize(total);
    const std::array<float, 256>& decode = srgbTable();
    const uint8_t* p = processed.texels.data();
    const uint32_t stride = world::bytesPerTexel(processed.format);
    if (uint64_t(processed.texels.size()) != total * stride) return BakeTexture{};
    for (uint64_t i = 0; i < total; ++i, p += stride) {
        switch (processed.format) {
            case world::TexelFormat::kRgba8Srgb:  // alpha is linear in every format
                t.texels[i] =
                    glm::vec4(decode[p[0]], decode[p[1]], decode[p[2]], float(p[3]) / 255.0f);
                break;
            case world::TexelFormat::kRgba8Unorm:
                t.texels[i] =
                    glm::vec4(float(p[0]), float(p[1]), float(p[2]), float(p[3])) / 255.0f;
                break;
            case world::TexelFormat::kR8Unorm:  // as the GPU reads R8: (r, 0, 0, 1)
                t.texels[i] = glm::vec4(float(p[0]) / 255.0f, 0.0f, 0.0f, 1.0f);
                break;
            case world::TexelFormat::kR16Float:  // as the GPU reads R16F: (r, 0, 0, 1)
                t.texels[i] =
                    glm::vec4(glm::unpackHalf1x16(uint16_t(p[0] | (p[1] << 8))), 0.0f, 0.0f, 1.0f);
                break;
        }
    }
    return t;
}

glm::vec4 sampleTexture(const BakeTexture& texture, glm::vec2 uv, float lod) {
    if (texture.texels.empty()) return glm::vec4(1.0f);
    const float top = float(texture.mipCount - 1);
    const float l = std::isfinite(lod) ? std::clamp(lod, 0.0f, top) : 0.0f;
    const uint32_t lo = uint32_t(l);
    const float t = l - float(lo);
    const bool nearest = texture.magNearest && l <= 0.0f;
    const glm::vec4 a = bilinear(texture, lo, uv, nearest);
    if (t <= 0.0f || lo + 1 >= texture.mipCount) return a;
    return a * (1.0f - t) + bilinear(texture, lo + 1, uv, false) * t;
}

}  // namespace onelight::bake
