// HDR cube maps on the CPU: linear RGB radiance (cd/m^2) in float, faces in Vulkan's order and
// orientation (shaders/probe.glsl), a mip chain from the face size down to 1x1.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace onelight::bake {

struct CubeMip {
    int size = 0;                   // texels per face edge
    std::vector<glm::vec3> texels;  // 6 * size * size: face-major, then rows (v down)

    glm::vec3& at(int face, int x, int y) { return texels[(size_t(face) * size + y) * size + x]; }
    const glm::vec3& at(int face, int x, int y) const {
        return texels[(size_t(face) * size + y) * size + x];
    }
};

struct Cubemap {
    std::vector<CubeMip> mips;  // mips[0] is the largest
    int mipCount() const { return int(mips.size()); }
};

// A cube of `size` (a power of two) with every mip down to 1x1 allocated and black.
[[nodiscard]] Cubemap makeCubemap(int size);

// The unit direction through the centre of texel (x, y) of `face` at mip size `size`.
[[nodiscard]] glm::vec3 texelDirection(int face, int x, int y, int size);

// Solid angle of texel (x, y) of any face at mip size `size`, steradians (sums to 4 pi).
[[nodiscard]] float texelSolidAngle(int x, int y, int size);

struct TexelRef {
    int face, x, y;
};

// Texel (x, y) of `face` where x or y may step one past the face (-1 or size): past an edge
// it continues on the neighbouring face, found through the direction of its centre.
[[nodiscard]] TexelRef neighbourTexel(int face, int x, int y, int size);

// Bilinear radiance in direction d, seamless across faces: taps past a face's edge are found on
// the neighbouring face through their direction (no clamping, so no seams).
[[nodiscard]] glm::vec3 sampleBilinear(const CubeMip& mip, glm::vec3 d);

// Trilinear between mips at fractional `lod` (clamped to the chain).
[[nodiscard]] glm::vec3 sampleTrilinear(const Cubemap& cube, glm::vec3 d, float lod);

// Fills mips 1.. of `cube` from mip 0 by averaging 2x2 texels weighted by solid angle.
void downsampleMips(Cubemap& cube);

}  // namespace onelight::bake
