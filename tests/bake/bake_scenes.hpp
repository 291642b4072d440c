// Small levels built in code for the bake tests: quads, boxes, spheres, lights.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "bake/bake_level.hpp"
#include "world/source_level.hpp"

namespace onelight::bake::test {

/// Lambert-only material (no specular), so reflectance is exactly `albedo`.
uint32_t add_lambert_material(world::SourceLevel& level, float albedo);

/// Quad p0 p1 p2 p3 (counter-clockwise seen from the side it faces) as two triangles.
void add_quad(world::SourceLevel& level, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3,
              uint32_t material, const std::string& name);

/// Axis-aligned box; `inward` makes its faces look inside (a room), else outside (a solid).
void add_box(world::SourceLevel& level, glm::vec3 lo, glm::vec3 hi, uint32_t material, bool inward,
             const std::string& name);

/// UV sphere with faces looking inward.
void add_inward_sphere(world::SourceLevel& level, glm::vec3 centre, float radius, uint32_t rings,
                       uint32_t segments, uint32_t material);

world::Light point_light(glm::vec3 position, float candela, world::LightRole role);
world::Light spot_light(glm::vec3 position, glm::vec3 direction, float candela, float inner,
                        float outer, world::LightRole role);

/// The lightmap-vs-reference agreement room: a closed 4 x 3 x 2.5 m room (albedo 0.6) with an
/// occluding block (albedo 0.3), a primary point light and a secondary ("baked") spot.
world::SourceLevel agreement_room();

/// A closed 3 x 2 x 2 m room (albedo 0.6) with a solid block and two primary point lights.
world::SourceLevel small_room();

/// small_room with a glossy block and three authored probes (the first box-projected), so that
/// the probe stage runs and two shards split its probes 1 + 2.
world::SourceLevel small_room_with_probes();

/// test_options at 4 texels/m with a few samples of everything: seconds for small_room.
BakeOptions fast_bake_options();

/// Options for fast tests: no progress bar, the given lightmap density.
BakeOptions test_options(float texels_per_metre, BakeQuality quality = BakeQuality::draft);

/// True when every texel and grid cell is finite and non-negative.
bool all_finite_non_negative(const world::BakedLighting& baked);

}  // namespace onelight::bake::test
