// Light evaluation in physical units for the baker and the reference path tracer: glTF
// directional lights in lux, point and spot lights in candela with inverse-square falloff and
// the KHR_lights_punctual cone (evaluatePunctualLight of shaders/lighting.glsl, shared with the
// runtime), the sky in cd/m^2 (uniform, or an image: sky.hpp), the level's emissive surfaces
// (emitters.hpp), and the
// visibility of a light of finite size (a sphere for point/spot, a cone of directions for the
// sun) by shadow rays.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/emitters.hpp"
#include "bake/lighting/light_cells.hpp"
#include "bake/lighting/sampling.hpp"
#include "bake/lighting/sky.hpp"
#include "world/compiled_level.hpp"
#include "world/source_level.hpp"

namespace onelight::bake {

/// Light sizes: glTF lights are punctual, shadows need a size. Until the level format carries
/// one per light, these apply to every light.
struct LightSizes {
    float pointRadius = 0.05f;          // metres: sphere radius of point and spot lights
    float sunAngularRadius = 0.00465f;  // radians: the sun's (0.27 degrees)
};

/// A light as the baker uses it.
struct BakeLight {
    world::Light light;
    uint32_t levelIndex = world::kNoIndex;  // into CompiledLevel::lights
    float radius = 0.0f;                    // metres (point, spot) or radians (directional)
};

/// The lights a bake uses (effect lights are runtime-only and left out), the scene's emissive
/// surfaces, and the sky.
struct BakeLights {
    std::vector<BakeLight> lights;
    // Lights drawn by importance: the point and spot lights (`localLights`, indices into
    // `lights`) through the light cells, whose sources index `localLights`. Directional lights
    // (`directionalLights`) reach everywhere and are evaluated at every point. No cells: every
    // light is evaluated.
    LightCells lightCells;
    std::vector<uint32_t> localLights, directionalLights;
    Emitters emitters;
    glm::vec3 skyRadiance{0.0f};  // cd/m^2, uniform over every direction that escapes...
    SkyImage skyImage;            // ...unless the sky is an image (then skyRadiance is unused)
};

/// The sky's radiance (cd/m^2) arriving from `direction` (unit, towards the sky).
[[nodiscard]] inline glm::vec3 skyAlong(const BakeLights& lights, const glm::vec3& direction) {
    return lights.skyImage.empty() ? lights.skyRadiance : skyRadiance(lights.skyImage, direction);
}

/// The level's lights and the sky, without emitters: for tools that evaluate punctual light
/// alone (the lightmap's primary term at runtime, seam checks).
[[nodiscard]] BakeLights makePunctualLights(const std::vector<world::Light>& levelLights,
                                            const LightSizes& sizes, glm::vec3 skyRadiance);

/// Everything a bake lights with: the level's lights (indexed by light cells over the scene),
/// the sky and the emissive triangles of `scene`.
[[nodiscard]] BakeLights makeBakeLights(const BakeScene& scene,
                                        const std::vector<world::Light>& levelLights,
                                        const LightSizes& sizes, glm::vec3 skyRadiance);

/// Everything `source` bakes with: its lights, the emissive triangles of `scene` and its sky,
/// the image it names (decoded from its file, times its skyRadiance) or its uniform radiance;
/// `uniformSky`, when set, replaces either (onelight-bake --sky). Throws world::Error naming
/// the sky's file when it cannot be read.
[[nodiscard]] BakeLights makeLevelLights(const BakeScene& scene, const world::SourceLevel& source,
                                         const LightSizes& sizes,
                                         std::optional<glm::vec3> uniformSky);

/// How far and in which cone a light can reach, for the light cells.
[[nodiscard]] LightBound lightBoundOf(const BakeLight& light);

/// A light seen from a point: where its centre is and how much it gives there.
struct LightIncidence {
    glm::vec3 direction{0.0f, 0.0f, 1.0f};  // unit, from the point towards the light's centre
    float distance = 0.0f;                  // metres to the centre; +inf for directional
    glm::vec3 irradiance{0.0f};  // lux (RGB) on a surface facing the light, before shadowing
};

/// The unshadowed light at `position`: E = I / d^2 x range window x spot cone for point and
/// spot lights, E = I for directional, times the colour.
[[nodiscard]] LightIncidence lightIncidence(const BakeLight& light, const glm::vec3& position);

/// A direction towards a uniformly chosen point of the light's apparent disc and the length
/// of the shadow ray that tests it (stops at the light's surface).
struct LightDirection {
    glm::vec3 direction{0.0f, 0.0f, 1.0f};
    float shadowDistance = 0.0f;  // metres
};
// pdf = 1 / (2 pi (1 - cos theta_max)), uniform over the cone of directions the light covers
// (sin theta_max = radius / distance for a sphere, the angular radius for the sun).
[[nodiscard]] LightDirection sampleLightDirection(const BakeLight& light,
                                                  const LightIncidence& incidence, glm::vec2 u,
                                                  float sceneDiameter);

/// Fraction of the light's apparent disc visible from `origin` (already offset off its
/// surface), by `samples` shadow rays on a rotated Hammersley set seeded by `rng`.
/*
   V = (1 / Omega) int_cone vis(w) dw,  uniform w in the cone (pdf 1 / Omega):
   V ~ (1 / N) sum_i vis(w_i)
                                        +---------------------------+
                                        | V = (1/N) sum_i vis(w_i)  |
                                        +---------------------------+
*/
[[nodiscard]] float lightVisibility(const BakeScene& scene, const BakeLight& light,
                                    const LightIncidence& incidence, const glm::vec3& origin,
                                    uint32_t samples, Rng& rng, RayCounts& rays);

}  // namespace onelight::bake
