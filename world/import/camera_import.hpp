// glTF cameras, named by their node so `--camera NAME` can find them.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"

namespace tinygltf {
struct Camera;
}

namespace onelight::world {

[[nodiscard]] Camera importCamera(const tinygltf::Camera& source, const glm::dmat4& worldFromLocal,
                                  const std::string& name, const std::string& where);

/// Rotation part of a world transform, scale and shear removed (unit quaternion).
[[nodiscard]] glm::quat rotationOf(const glm::dmat4& worldFromLocal);

}  // namespace onelight::world
