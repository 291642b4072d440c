// From what the user named to a package the runtime can load: a .olpak as it is, or a glTF level
// compiled and baked by `onelight-bake` (a child process, found beside this executable) when the
// package beside it is missing or older than the glTF or than onelight-bake.
#pragma once

#include <string>

namespace onelight::game {

/// The package to load for `level`, compiling it first when needed. Throws world::Error, one
/// line "FILE: what was expected".
/// `quality` (draft, default, high) is the bake's when it bakes; empty: draft for a Quake 3
/// map, the baker's default for a glTF.
[[nodiscard]] std::string resolveLevelPackage(const std::string& level,
                                              const std::string& quality = {});

/// The same with the baker's path given (tests); the one above uses onelight-bake beside this
/// executable.
[[nodiscard]] std::string resolveLevelPackageWith(const std::string& level,
                                                  const std::string& baker,
                                                  const std::string& quality = {});

}  // namespace onelight::game
