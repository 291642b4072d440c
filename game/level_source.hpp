// From what the user named to a package the runtime can load: a .olpak as it is, or a glTF level
// compiled and baked by `onelight-bake` (a child process, found beside this executable) when the
// package beside it is missing or older than the glTF or than onelight-bake.
#pragma once

#include <string>

namespace onelight::game {

/// The package to load for `level`, compiling it first when needed. On failure returns false
/// and sets `error` to one line "FILE: what was expected".
bool resolveLevelPackage(const std::string& level, std::string& package, std::string& error);

/// The same with the baker's path given (tests); the one above uses onelight-bake beside this
/// executable.
bool resolveLevelPackage(const std::string& level, std::string& package, std::string& error,
                         const std::string& baker);

}  // namespace onelight::game
