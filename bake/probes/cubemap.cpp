#include "cubemap.hpp"

#include <algorithm>
#include <cmath>

#include "shading.hpp"

namespace onelight::bake {

namespace glsl = onelight::glsl;

Cubemap makeCubemap(int size) {
    Cubemap c;
    for (int s = size; s >= 1; s /= 2)
        c.mips.push_back(CubeMip{s, std::vector<glm::vec3>(6 * size_t(s) * s)});
    return c;
}

glm::vec3 texelDirection(int face, int x, int y, int size) {
    return glsl::cubeDirection(face, glm::vec2((x + 0.5f) / size, (y + 0.5f) / size));
}

float texelSolidAngle(int x, int y, int size) {
    return glsl::cubeTexelSolidAngle(float(x) / size, float(y) / size, float(x + 1) / size,
                                     float(y + 1) / size);
}

namespace {

// Direction of the (possibly out-of-face) texel centre (i, j) of `face`, not normalised.
glm::vec3 texelCentreDirection(int face, int i, int j, int size) {
    float s = 2.0f * (i + 0.5f) / size - 1.0f, t = 2.0f * (j + 0.5f) / size - 1.0f;
    switch (face) {
        case 0:
            return {1.0f, -t, -s};
        case 1:
            return {-1.0f, -t, s};
        case 2:
            return {s, 1.0f, t};
        case 3:
            return {s, -1.0f, -t};
        case 4:
            return {s, -t, 1.0f};
        default:
            return {-s, -t, -1.0f};
    }
}

}  // namespace

TexelRef neighbourTexel(int face, int x, int y, int size) {
    if (x >= 0 && y >= 0 && x < size && y < size) return {face, x, y};
    glm::vec3 d = texelCentreDirection(face, x, y, size);
    int f = glsl::cubeFace(d);
    glm::vec2 uv = glsl::cubeFaceUV(d, f);
    return {f, std::clamp(int(uv.x * size), 0, size - 1),
            std::clamp(int(uv.y * size), 0, size - 1)};
}

glm::vec3 sampleBilinear(const CubeMip& mip, glm::vec3 d) {
    int face = glsl::cubeFace(d);
    glm::vec2 uv = glsl::cubeFaceUV(d, face);
    float fx = uv.x * mip.size - 0.5f, fy = uv.y * mip.size - 0.5f;
    int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
    float tx = fx - x0, ty = fy - y0;
    auto tap = [&](int i, int j) {
        TexelRef t = neighbourTexel(face, i, j, mip.size);
        return mip.at(t.face, t.x, t.y);
    };
    return glm::mix(glm::mix(tap(x0, y0), tap(x0 + 1, y0), tx),
                    glm::mix(tap(x0, y0 + 1), tap(x0 + 1, y0 + 1), tx), ty);
}

glm::vec3 sampleTrilinear(const Cubemap& cube, glm::vec3 d, float lod) {
    lod = std::clamp(lod, 0.0f, float(cube.mipCount() - 1));
    int m0 = int(std::floor(lod));
    int m1 = std::min(m0 + 1, cube.mipCount() - 1);
    float t = lod - m0;
    glm::vec3 a = sampleBilinear(cube.mips[m0], d);
    return t > 0.0f ? glm::mix(a, sampleBilinear(cube.mips[m1], d), t) : a;
}

void downsampleMips(Cubemap& cube) {
    for (int m = 1; m < cube.mipCount(); ++m) {
        const CubeMip& src = cube.mips[m - 1];
        CubeMip& dst = cube.mips[m];
        for (int face = 0; face < 6; ++face)
            for (int y = 0; y < dst.size; ++y)
                for (int x = 0; x < dst.size; ++x) {
                    glm::vec3 sum(0.0f);
                    float weight = 0.0f;
                    for (int j = 0; j < 2; ++j)
                        for (int i = 0; i < 2; ++i) {
                            float w = texelSolidAngle(2 * x + i, 2 * y + j, src.size);
                            sum += src.at(face, 2 * x + i, 2 * y + j) * w;
                            weight += w;
                        }
                    dst.at(face, x, y) = sum / weight;
                }
    }
}

}  // namespace onelight::bake
