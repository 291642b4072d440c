// A copy of a glTF level with one level-wide extras.onelight key set, for the knobs that are per
// level (docs/level-authoring.md: the last node's value wins, so a node is appended). The copy
// sits beside the level so that its relative buffer and image URIs still resolve.
#pragma once

#include <string>

namespace onelight::lab {

// True for a level the patch can copy (a .gltf; a .glb's JSON is inside its binary).
[[nodiscard]] bool canPatchLevel(const std::string& level);

// Writes LEVEL_FOLDER/STEM.level-report-KEY-VALUE.gltf (through a temporary name) and returns
// its path; the caller removes it. Throws std::runtime_error naming the level on failure.
[[nodiscard]] std::string writePatchedLevel(const std::string& level, const std::string& key,
                                            const std::string& value);

}  // namespace onelight::lab
