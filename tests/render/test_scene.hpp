// Small glTF levels written by tests and the benchmark (embedded buffers, KHR_lights_punctual),
// compiled with onelight-bake and loaded as packages; plus helpers to render them in-process.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "assets/level_assets.hpp"
#include "render/renderer.hpp"
#include "world/process/child_process.hpp"

namespace onelight::test {

struct SceneMaterial {
    glm::vec4 baseColor{0.8f, 0.8f, 0.8f, 1.0f};
    float metallic = 0.0f;
    float roughness = 0.5f;
    glm::vec3 emissive{0.0f};       // emissiveFactor
    float emissiveStrength = 1.0f;  // KHR_materials_emissive_strength (written when not 1)
};

struct SceneMesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<uint32_t> indices;
    uint32_t material = 0;
    bool dynamic = false;  // extras.onelight.dynamic
};

struct SceneLight {
    int type = 0;  // 0 directional (lux), 1 point (cd), 2 spot (cd)
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    float range = 0.0f;  // 0 = unlimited (omitted)
    float innerCone = 0.3f, outerCone = 0.6f;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // the way light travels
    const char* role = nullptr;              // extras.onelight.role ("baked", "effect"), or none
};

struct Scene {
    std::vector<SceneMaterial> materials;
    std::vector<SceneMesh> meshes;
    std::vector<SceneLight> lights;
    glm::vec3 sky{0.0f};   // cd/m^2: extras.onelight.sky of a settings node when non-zero...
    std::string skyImage;  // ...or the scale of this .hdr (relative to the glTF) when given
    // A perspective camera node named "view" (for `onelight-bake reference --camera view`) when
    // viewAspect > 0: its place, its rotation (world from camera, looking down -Z) and yfov.
    glm::vec3 viewPosition{0.0f};
    glm::quat viewRotation{1.0f, 0.0f, 0.0f, 0.0f};
    float viewYfov = 1.0f, viewAspect = 0.0f;
};

/// A quad in the plane y = height, facing +Y, of half size `half` around (cx, cz).
void addFloor(Scene& scene, float cx, float cz, float half, float height, uint32_t material);

/// An axis-aligned box (outward normals, 12 triangles).
void addBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material, bool dynamic = false);

/// Quad a b c d (counter-clockwise seen from the side it faces) as n x m tiles of `material`.
void addTiles(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, int n, int m,
              uint32_t material);

/// A hall 10 m deep and 4 m high (y up), its shell in 2 m tiles, cut by 2 m walls every 12 m
/// (centred at x = -6 + 12 k) into `rooms` rooms with doorways at alternate ends (z 8..10, then
/// z 0..2: a chicane), from x = -20 to 12 rooms - 16: three rooms span 40 m. A 0.5 m crate and a
/// 300 cd point light in the middle of each room. Material 0.
void addChicaneHall(Scene& scene, int rooms);

/// A UV sphere of `rings` x `segments` quads.
void addSphere(Scene& scene, glm::vec3 centre, float radius, uint32_t rings, uint32_t segments,
               uint32_t material);

/// Writes the scene as a .gltf with an embedded buffer. Throws on I/O failure.
void writeGltf(const Scene& scene, const std::string& path);

/// Runs `onelight-bake compile GLTF -o PACKAGE`; returns its exit code.
int compileLevel(const std::string& gltf, const std::string& package);

/// Runs `onelight ARGS...` (no shell) with its stdout discarded and its stderr captured.
world::ChildResult runOnelight(const std::vector<std::string>& args);

/// Compiles (when needed) and loads; throws std::runtime_error with the error line.
assets::LoadedLevel compileAndLoad(const std::string& gltf, const std::string& package);

/// Runs `onelight-bake GLTF -o PACKAGE --quality draft --quiet` plus `extraArguments` (compile
/// and bake); returns its exit code.
int bakeLevel(const std::string& gltf, const std::string& package,
              const std::string& extraArguments = "");

/// Bakes and loads; throws std::runtime_error with the error line.
assets::LoadedLevel bakeAndLoad(const std::string& gltf, const std::string& package,
                                const std::string& extraArguments = "");

/// A folder for a test's outputs under the build tree (created).
std::string outputDir();

/// One headless frame of `level`, read back.
struct RenderedFrame {
    render::CapturedFrame frame;
    render::FrameStats stats;
    uint32_t msaaInUse = 0;
    std::vector<std::string> permutations;  // the forward pipelines the renderer built
    uint32_t validationErrors = 0;
};
RenderedFrame renderOnce(const assets::LoadedLevel& level, const render::RendererOptions& options,
                         const render::FrameInputs& inputs, int frames = 1);

/// Whether any of `names` (e.g. the forward pipelines built) contains `part`.
[[nodiscard]] bool anyNamed(const std::vector<std::string>& names, const char* part);

/// The largest difference over R, G and B of pixel `pixel` of two RGBA8 frames.
[[nodiscard]] int worstChannelDifference(const std::vector<uint8_t>& a,
                                         const std::vector<uint8_t>& b, size_t pixel);

/// The share of pixels of two RGBA8 frames of one size whose worstChannelDifference exceeds
/// `threshold` (the goldens' is 8).
[[nodiscard]] double shareOfPixelsOff(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b,
                                      int threshold = 8);

/// The reference (linear RGB, 3 floats a pixel) and frames (linear RGBA, 4 floats) of
/// `width` x `height` side by side in one PNG: a common scale putting the reference's mean
/// luminance at `mean`, then x / (1 + x) and sRGB gamma: a picture of where the errors are.
void writeReferenceComparison(const std::string& path, uint32_t width, uint32_t height,
                              const std::vector<float>& reference,
                              const std::vector<const std::vector<float>*>& frames,
                              float mean = 0.5f);

}  // namespace onelight::test
