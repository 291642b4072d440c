// The `extras.onelight` object of a glTF node (schema in import/README.md): role, dynamic,
// mover, probe, spawn, grid bounds, exposure, lightmap density, probe spacing. Wrong types or
// values are CompileErrors.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"

namespace tinygltf {
class Value;
}

namespace onelight::world {

struct NodeExtras {
    bool has_role = false;
    LightRole role = LightRole::primary;
    bool dynamic = false;
    bool spawn = false;
    bool probe = false;
    bool has_probe_box = false;
    glm::vec3 probe_box_min{0.0f}, probe_box_max{0.0f};  // world metres
    bool mover = false;
    glm::vec3 mover_offset{0.0f};  // metres, world space
    float mover_period = 0.0f;     // seconds, > 0
    bool has_grid = false;
    glm::vec3 grid_min{0.0f}, grid_max{0.0f};  // world metres, min < max
    bool has_exposure = false;
    float exposure_ev100 = 0.0f;
    float texels_per_metre = 0.0f;  // lightmap density for the level, > 0 when given
    float probe_spacing = 0.0f;     // metres between the level's automatic probes, > 0 when given
    bool has_sky = false;
    glm::vec3 sky_radiance{0.0f};  // cd/m^2, RGB, >= 0: the level's uniform sky
};

/// Parses node.extras; `where` names the node for errors ("file.gltf: node 'lamp'").
NodeExtras parse_node_extras(const tinygltf::Value& extras, const std::string& where);

}  // namespace onelight::world
