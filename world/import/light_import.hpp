// KHR_lights_punctual lights, kept in their glTF units (lux for directional, candela for point
// and spot) and placed by their node's world transform.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"

namespace tinygltf {
struct Light;
}

namespace onelight::world {

/// `where` names the node for errors. Negative or non-finite intensity, unknown types and bad
/// cone angles are CompileErrors.
[[nodiscard]] Light importLight(const tinygltf::Light& source, const glm::dmat4& worldFromLocal,
                                const std::string& name, LightRole role, const std::string& where);

}  // namespace onelight::world
