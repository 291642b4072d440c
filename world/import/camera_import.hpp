// glTF cameras, named by their node so `--camera NAME` can find them.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"

namespace tinygltf {
struct Camera;
}

namespace onelight::world {

Camera import_camera(const tinygltf::Camera& source, const glm::dmat4& world_from_local,
                     const std::string& name, const std::string& where);

/// Rotation part of a world transform, scale and shear removed (unit quaternion).
glm::quat rotation_of(const glm::dmat4& world_from_local);

}  // namespace onelight::world
