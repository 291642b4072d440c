// The `extras.onelight` object of a glTF node (schema in import/README.md): role, dynamic,
// mover, probe, spawn, grid bounds, exposure, lightmap density, probe spacing. Wrong types or
// values are CompileErrors.
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"

namespace tinygltf {
class Value;
}

namespace onelight::world {

struct NodeExtras {
    bool hasRole = false;
    LightRole role = LightRole::kPrimary;
    bool dynamic = false;
    bool spawn = false;
    bool probe = false;
    bool hasProbeBox = false;
    glm::vec3 probeBoxMin{0.0f}, probeBoxMax{0.0f};  // world metres
    bool mover = false;
    glm::vec3 moverOffset{0.0f};  // metres, world space
    bool prop = false;            // a static prop: one primary, chosen at its lighting origin
    bool hasLightingOrigin = false;
    glm::vec3 lightingOrigin{
        0.0f};                 // the prop's, in the node's space (default: its bounds' centre)
    float moverPeriod = 0.0f;  // seconds, > 0
    bool hasGrid = false;
    glm::vec3 gridMin{0.0f}, gridMax{0.0f};  // world metres, min < max
    bool hasExposure = false;
    float exposureEv100 = 0.0f;
    float texelsPerMetre = 0.0f;  // lightmap density for the level, > 0 when given
    float probeSpacing = 0.0f;    // metres between the level's automatic probes, > 0 when given
    std::optional<DiffuseModel> diffuseModel;  // "diffuse": "lambert" or "multiscatter"
    std::optional<GlossMipMethod> glossMips;   // "gloss_mips": "blit", "black_ops" or "wwii"
    bool hasSky = false;
    glm::vec3 skyRadiance{0.0f};  // cd/m^2, RGB, >= 0: the uniform sky, or the image's scale
    std::string skyImage;         // an equirectangular .hdr (as written), empty for a uniform sky
};

/// Parses node.extras; `where` names the node for errors ("file.gltf: node 'lamp'").
[[nodiscard]] NodeExtras parseNodeExtras(const tinygltf::Value& extras, const std::string& where);

}  // namespace onelight::world
