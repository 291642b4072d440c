// Cavity maps from normal maps. Chan 2018, "Material Advances in Call of Duty: WWII", sec. 4:
// every surface with a normal map gets a cavity map, generated from it, and the renderer
// suppresses primary (direct) diffuse and specular light by it: cavity is the visibility of
// the small-scale geometry the normal map describes, per texel.
//
// Two steps, each a function below:
//   1. heightFromNormals: the height field whose slopes best fit the normal map's (a least-
//      squares Poisson problem, solved exactly in the eigenbasis of the discrete Laplacian).
//   2. cavityFromHeight: the cosine-weighted visible fraction of the hemisphere above the macro
//      surface (tangent-space +z) at each texel, from the height field's horizons.
//
// Conventions (glTF 2.0, "material.normalTexture" and "Texture coordinates"): maps are row-major,
// rows top to bottom (v runs down the image); a tangent-space normal's +X is right (towards
// increasing column), +Y is up in the texture (towards DECREASING row), +Z points out of the
// surface. Heights are in texel units: a normal map fixes its height field, up to a constant, in
// units of its own texel spacing, so no arbitrary scale enters (an optional depth scale
// exaggerates or flattens it).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace onelight::bake {

/// How a map continues past its border, along one axis.
enum class CavityWrap : uint8_t {
    kRepeat,  // periodic (glTF REPEAT): the map tiles
    kClamp,   // clamp to edge (glTF CLAMP_TO_EDGE): the edge texels continue outward
};

/// The wrap mode along each axis: u along a row (across columns, glTF wrapS), v along a column
/// (across rows, glTF wrapT).
struct CavityWrapModes {
    CavityWrap u = CavityWrap::kRepeat;
    CavityWrap v = CavityWrap::kRepeat;
};

/// A tangent-space normal map: width * height normals, row-major, rows top to bottom. The
/// normals need not be unit length (they are normalised); see heightSlopeFromNormal for the
/// ones that are treated as flat.
struct TangentNormalMap {
    uint32_t width = 0, height = 0;
    std::vector<glm::vec3> normals;
};

/// A height field in texel units, row-major, rows top to bottom, zero mean.
struct HeightField {
    uint32_t width = 0, height = 0;
    std::vector<float> heights;
};

/// Cavity per texel in [0, 1] (1: the whole hemisphere is visible), row-major, rows top to
/// bottom.
struct CavityMap {
    uint32_t width = 0, height = 0;
    std::vector<float> cavity;
};

/// The floor of a unit normal's z where slopes are taken: a normal more grazing than this
/// (within 2.9 degrees of the surface) is read as this steep, so |slope| <= 1 / kMinNormalZ = 20
/// texels of height per texel (87.1 degrees) and no slope is infinite.
inline constexpr float kMinNormalZ = 0.05f;

/// The height field's slope under normal `n`: (dh/dx, dh/dy), x right (per column) and y up
/// (per row upwards, i.e. dh/drow = -dh/dy).
/*
   The surface z = h(x, y) has the normal (-dh/dx, -dh/dy, 1) / |...|, so for a unit n:
                            +--------------------------------------+
                            | dh/dx = -nx / nz,   dh/dy = -ny / nz |
                            +--------------------------------------+
   with nz raised to kMinNormalZ where it is smaller. A normal that is no tangent-space normal
   (nz <= 0: at or below the macro surface; a zero vector; any component NaN or infinite, as a
   decoding error or an unused texel gives) is treated as flat: slope (0, 0).
*/
[[nodiscard]] glm::dvec2 heightSlopeFromNormal(glm::vec3 n);

/// The height field (texel units, times `depthScale`, zero mean) whose slopes fit those of
/// `normals` in the least-squares sense, continued past the border as `wrap` says.
/*
   Slopes are taken at texel centres (heightSlopeFromNormal); the difference of heights across
   the edge between two neighbouring texels is fitted to the mean of their two slopes (the
   slope at the edge's midpoint; exact for a quadratic height). Minimising
       E(h) = sum over edges (h_b - h_a - (s_a + s_b) / 2)^2
   gives the discrete Poisson equation  laplacian(h) = div(s)  (5-point Laplacian, divergence
   of the edge slopes). A repeating axis has an edge from the last texel to the first (periodic);
   a clamped axis has none (the Neumann condition dh/dn = 0 at the half-texel boundary).
   The solution is exact, not iterative: the Laplacian is diagonal in the discrete Fourier basis
   along a repeating axis and in the DCT-II basis along a clamped one (Frankot and Chellappa
   1988, "A Method for Enforcing Integrability in Shape from Shading Algorithms"; Simchony,
   Chellappa and Shao 1990, "Direct Analytical Methods for Solving Poisson Equations in Computer
   Vision Problems"), with eigenvalues 2 cos(2 pi k / n) - 2 and 2 cos(pi k / n) - 2.
   The constant (k = 0), which no slope fixes, is set so the mean height is 0. Any width and
   height (1 x n, odd, non-power-of-two: mixed-length FFTs by Bluestein's chirp z-transform);
   O(n log n), a 1024 x 1024 map in a fraction of a second. Bit-identical at any thread count.
   A plane wave of k radians per texel along x comes back scaled by (k/2) / tan(k/2) (the edge
   mean of two centre slopes), 1 - k^2 / 12: 0.3% at 32 texels per period, 1.3% at 16.
   Throws std::invalid_argument if normals.normals.size() != width * height.
*/
[[nodiscard]] HeightField heightFromNormals(const TangentNormalMap& normals, CavityWrapModes wrap,
                                            float depthScale = 1.0f);

/// The horizon scan of cavityFromHeight: `azimuths` directions, out to `radius` texels.
struct HorizonScan {
    uint32_t azimuths = 16;  // 1 .. 1024
    float radius = 32.0f;    // texels, 0 .. 4096
};

/// The cosine-weighted visibility of the hemisphere above the macro surface at each texel of
/// `height`, from its horizons within `scan.radius` texels, the field continued as `wrap` says.
/*
   A ray from a point p on a height field escapes iff it stays above the field, i.e. iff its
   elevation above the macro surface's plane (z = const) exceeds the horizon e(phi) in its
   azimuth phi, the largest elevation at which the field is seen from p:
       e(phi) = max(0, sup_t atan((h(p + t d) - h(p)) / t)),  d = (cos phi, sin phi).
   The cosine-weighted visible fraction of the hemisphere (theta from +z; theta_h = pi/2 - e):
       V = (1/pi) int_0^{2 pi} int_0^{theta_h(phi)} cos(theta) sin(theta) dtheta dphi
         = (1/pi) int_0^{2 pi} sin^2(theta_h(phi)) / 2 dphi
                            +------------------------------------------------+
                            | V = (1 / 2 pi) int_0^{2 pi} cos^2(e(phi)) dphi |
                            +------------------------------------------------+
   (the slice integral of Jimenez et al. 2016, "Practical Realtime Strategies for Accurate
   Indirect Occlusion", with the normal along the slice's axis); cos^2(e) = 1 / (1 + tan^2(e))
   is taken from the steepest rise tan(e) directly. A tilted plane of slope s gives
   V = 1/2 + 1 / (2 sqrt(1 + s^2)): cavity is against the macro normal, so the micro surface's
   own tilt counts.
   Discretised: the mean over phi_j = 2 pi j / azimuths (for a multiple of 4 azimuths, symmetric
   under the map's 90-degree rotations and mirrors), d in (column, row) units. Each azimuth's
   tan(e) is the largest of 0; the rise of the surface's own tangent along d (t -> 0: rays below
   it enter the surface at once, which the first sample, a texel away, misses where the surface
   curves down), from r = h(p + d) - h(p) and f = h(p) - h(p - d) by their harmonic mean
   2 r f / (r + f) if both rise, else 0 (van Leer 1974, "Towards the Ultimate Conservative
   Difference Scheme II", the monotone slope limiter: exact on a plane, nothing on a crest or a
   plateau's edge); and the rises at t = 1, 2, ..., floor(radius) texels, bilinear samples.
   Past the border the field continues as the sampler would continue it: repeat tiles it, clamp
   extends the edge texels outward. A flat field gives exactly 1, and so does a texel that no
   texel its samples read rises above.
   Costs azimuths x radius bilinear samples a texel at most (a scan stops once the field's
   highest texel could no longer raise its horizon): 1024 x 1024 at the defaults, ~2 s on one
   core. Each texel depends only on the field, so results are bit-identical at any thread count.
   Throws std::invalid_argument if heights.size() != width * height or the scan is out of range.
*/
[[nodiscard]] CavityMap cavityFromHeight(const HeightField& height, CavityWrapModes wrap,
                                         const HorizonScan& scan = {});

/// Everything to make a cavity map from a normal map.
struct CavitySettings {
    CavityWrapModes wrap;     // the normal map's sampler
    float depthScale = 1.0f;  // heightFromNormals
    HorizonScan scan;
};

/// cavityFromHeight(heightFromNormals(normals, wrap, depthScale), wrap, scan).
[[nodiscard]] CavityMap cavityFromNormals(const TangentNormalMap& normals,
                                          const CavitySettings& settings = {});

/// The mip chain of `cavity`, mip 0 (a copy) first, down to 1 x 1: mip k is
/// max(1, width >> k) x max(1, height >> k), each texel the mean of the 2 x 2 texels above it
/// (2 x 1 or 1 x 2 where the level above is one texel wide or high; an odd level's last row or
/// column is left out), as every mip chain of the baker. Empty for an empty map.
/// Throws std::invalid_argument if cavity.cavity.size() != width * height.
[[nodiscard]] std::vector<CavityMap> cavityMipChain(const CavityMap& cavity);

/// Cavity as an 8-bit UNORM texel: round(255 c), c clamped to [0, 1]; NaN encodes as 255
/// (no suppression).
[[nodiscard]] uint8_t cavityToUnorm8(float cavity);

/// Every texel of `cavity` through cavityToUnorm8, in the same order.
[[nodiscard]] std::vector<uint8_t> cavityToUnorm8(const CavityMap& cavity);

}  // namespace onelight::bake
