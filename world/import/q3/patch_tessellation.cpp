#include "world/import/q3/patch_tessellation.hpp"

#include <cmath>

namespace onelight::world::q3 {
namespace {

// B(P0, P1, P2; k) of the header, for any interpolated quantity.
template <typename T>
T bezier(const T& p0, const T& p1, const T& p2, uint32_t k, uint32_t level) {
    if (k == 0) return p0;
    if (k == level) return p2;
    const float l = float(level), a = float(level - k), b = float(k);
    const T ends = p0 * (a * a) + p2 * (b * b);  // commutative: the same bits reversed
    return (ends + p1 * (2.0f * a * b)) / (l * l);
}

PatchPoint bezierPoint(const PatchPoint& p0, const PatchPoint& p1, const PatchPoint& p2, uint32_t k,
                       uint32_t level) {
    return {bezier(p0.position, p1.position, p2.position, k, level),
            bezier(p0.normal, p1.normal, p2.normal, k, level),
            bezier(p0.uv, p1.uv, p2.uv, k, level),
            bezier(p0.lightmapUv, p1.lightmapUv, p2.lightmapUv, k, level),
            bezier(p0.vertexLight, p1.vertexLight, p2.vertexLight, k, level)};
}

}  // namespace

PatchMesh tessellatePatch(const std::vector<PatchPoint>& controls, uint32_t width, uint32_t height,
                          uint32_t level) {
    PatchMesh mesh;
    if (level == 0 || width < 3 || height < 3 || width % 2 == 0 || height % 2 == 0 ||
        controls.size() != size_t(width) * height)
        return mesh;
    const uint32_t piecesX = (width - 1) / 2, piecesY = (height - 1) / 2;
    const auto at = [&](uint32_t x, uint32_t y) -> const PatchPoint& {
        return controls[size_t(y) * width + x];
    };
    for (uint32_t py = 0; py < piecesY; ++py)
        for (uint32_t px = 0; px < piecesX; ++px) {
            const uint32_t base = uint32_t(mesh.vertices.size());
            for (uint32_t j = 0; j <= level; ++j) {
                // The piece's three control rows, each reduced along y first.
                PatchPoint column[3];
                for (uint32_t c = 0; c < 3; ++c)
                    column[c] = bezierPoint(at(2 * px + c, 2 * py), at(2 * px + c, 2 * py + 1),
                                            at(2 * px + c, 2 * py + 2), j, level);
                for (uint32_t i = 0; i <= level; ++i) {
                    PatchPoint p = bezierPoint(column[0], column[1], column[2], i, level);
                    const float length = glm::length(p.normal);
                    p.normal = length > 1e-12f ? p.normal / length : glm::vec3(0.0f, 0.0f, 1.0f);
                    mesh.vertices.push_back(p);
                }
            }
            const uint32_t row = level + 1;
            for (uint32_t j = 0; j < level; ++j)
                for (uint32_t i = 0; i < level; ++i) {
                    const uint32_t a = base + j * row + i, b = a + 1, c = a + row, d = c + 1;
                    mesh.triangles.insert(mesh.triangles.end(), {a, b, d, a, d, c});
                }
        }
    return mesh;
}

}  // namespace onelight::world::q3
