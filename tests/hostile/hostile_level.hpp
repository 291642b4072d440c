// The smallest level a hostile-input test edits: one floor triangle, a sun and a camera, as a
// .gltf with its .bin beside it, written from JSON so that a test can break any one field.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

namespace onelight::test {

/// The level's JSON, valid as written (HostileImport.TheUneditedLevelImports checks it).
nlohmann::json triangleLevelJson();

/// Writes `folder`/level.gltf (the JSON after `edit`) and `folder`/level.bin; returns the .gltf.
std::string writeTriangleLevel(const std::filesystem::path& folder,
                               const std::function<void(nlohmann::json&)>& edit = {});

/// A fresh empty folder under the system's temporary folder.
std::filesystem::path hostileFolder(const std::string& name);

}  // namespace onelight::test
