// Small levels built in code for the bake tests: quads, boxes, spheres, lights.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "bake/bake_level.hpp"
#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/lights.hpp"
#include "world/images/image_decode.hpp"
#include "world/source_level.hpp"

namespace onelight::bake::test {

/// Lambert-only material (no specular), so reflectance is exactly `albedo`.
uint32_t addLambertMaterial(world::SourceLevel& level, float albedo);

/// Quad p0 p1 p2 p3 (counter-clockwise seen from the side it faces) as two triangles.
void addQuad(world::SourceLevel& level, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3,
             uint32_t material, const std::string& name);

/// Axis-aligned box; `inward` makes its faces look inside (a room), else outside (a solid).
void addBox(world::SourceLevel& level, glm::vec3 lo, glm::vec3 hi, uint32_t material, bool inward,
            const std::string& name);

/// UV sphere with faces looking inward.
void addInwardSphere(world::SourceLevel& level, glm::vec3 centre, float radius, uint32_t rings,
                     uint32_t segments, uint32_t material);

/// Writes `rgba` (8-bit, width x height, top row first) as a PNG at `pngPath` and adds an image
/// and a texture reading it through `sampler`; returns the texture's index.
uint32_t addImageTexture(world::SourceLevel& level, const std::string& pngPath, uint32_t width,
                         uint32_t height, const std::vector<uint8_t>& rgba,
                         const world::Sampler& sampler = {});

/// A level's static world in Embree, as the baker builds it, and its lights, emitters and
/// uniform sky (makeBakeLights).
struct LevelScene {
    const EmbreeDevice device;
    const BakeScene scene;
    const BakeLights lights;
    explicit LevelScene(const world::SourceLevel& level);
};

/// Writes `sky` (linear RGB) as a Radiance .hdr at `hdrPath` and makes it the level's sky image,
/// each texel times `scale` cd/m^2, as extras.onelight.sky {"image", "scale"} would.
void setSkyImage(world::SourceLevel& level, const std::string& hdrPath, const world::HdrImage& sky,
                 glm::vec3 scale);

world::Light pointLight(glm::vec3 position, float candela, world::LightRole role);
/// A primary directional light named "sun" travelling along `direction` (normalised here).
world::Light sunLight(glm::vec3 direction, float lux);
world::Light spotLight(glm::vec3 position, glm::vec3 direction, float candela, float inner,
                       float outer, world::LightRole role);

/// The lightmap-vs-reference agreement room: a closed 4 x 3 x 2.5 m room (albedo 0.6) with an
/// occluding block (albedo 0.3), a primary point light and a secondary ("baked") spot.
world::SourceLevel agreementRoom();

/// The room lit through an opening: the agreement room's 4 x 3 x 2.5 m shell (albedo 0.6) with
/// a 1 x 1 m opening in its ceiling, a block (albedo 0.3) and a primary sun (20 klx) that falls
/// through the opening onto the floor; no sky. Everything but the sunlit patch is lit by bounces.
world::SourceLevel roofOpeningRoom();

/// A closed 3 x 2 x 2 m room (albedo 0.6) with a solid block and two primary point lights.
world::SourceLevel smallRoom();

/// smallRoom with a glossy block and three authored probes (the first box-projected), so that
/// the probe stage runs and two shards split its probes 1 + 2.
world::SourceLevel smallRoomWithProbes();

/// smallRoomWithProbes with every material feature the transport reads: a checker base colour
/// on the walls, a normal map on the glossy block, an emissive panel and a MASK grate with
/// holes (textures written as PNGs into `folder`; uv0 projected from the positions).
world::SourceLevel texturedRoomWithProbes(const std::string& folder);

/// An 8 x 8 m floor (albedo 0.5) with three blocks, under n x n baked point lights 1.2 m up
/// spread over it (2 to 6 cd, a third of them with a 4 m range): the many-lights level.
world::SourceLevel manyLightsFloor(uint32_t n);

/// testOptions at 4 texels/m with a few samples of everything: seconds for smallRoom.
BakeOptions fastBakeOptions();

/// Options for fast tests: no progress bar, the given lightmap density.
BakeOptions testOptions(float texelsPerMetre, BakeQuality quality = BakeQuality::kDraft);

/// True when every texel and grid cell is finite and non-negative.
bool allFiniteNonNegative(const world::BakedLighting& baked);

}  // namespace onelight::bake::test
