// Shared helpers of the world tests.
#pragma once

#include <filesystem>
#include <string>

#include "world/compile/compile_level.hpp"
#include "world/gltf/gltf_builder.hpp"

namespace onelight::test {

using world::boxMesh;
using world::GltfBuilder;
using world::gridMesh;
using world::MeshData;

/// A fresh empty folder under the system temp folder, named after `label`.
std::filesystem::path freshFolder(const std::string& label);

/// Imports and compiles a glTF file.
world::CompileResult compileFile(const std::string& path,
                                 const world::CompileOptions& options = {});

/// Path of a file under ../shared/assets; empty when it is absent.
std::string sharedAsset(const std::string& relative);

/// A simple scene: a ground grid `size` metres wide with `cells`^2 quads and, when `lights`,
/// two point lights of equal intensity above x = -size/4 and x = +size/4.
std::string writeTwoLampFloor(const std::string& label, int cells, double size, bool lights);

}  // namespace onelight::test
