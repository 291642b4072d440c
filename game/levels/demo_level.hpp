// The demo level, generated from this source so that it can be read and diffed.
#pragma once

#include <string>

namespace onelight::game {

// Writes demo.gltf and demo.bin into `folder` (created if needed); returns the .gltf path.
[[nodiscard]] std::string writeDemoLevel(const std::string& folder);

}  // namespace onelight::game
