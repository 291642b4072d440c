// What a level argument names, shared by the compiler and the game (which never links the
// importers): a glTF (.gltf, .glb), a package (.olpak), or a Quake 3 map (NAME.bsp,
// PAK.pk3:maps/NAME.bsp, or a bare NAME found in the installed game's pk3s).
#pragma once

#include <string>

namespace onelight::world {

/// A .bsp, a "PAK.pk3:inner/path", or a bare name without an extension or a folder.
[[nodiscard]] bool isQuake3Map(const std::string& level);

/// The package a level compiles to by default: LEVEL.gltf -> LEVEL.olpak beside it; a Quake 3
/// map's NAME.olpak in the current folder (its pk3 is read-only, and usually the game's).
[[nodiscard]] std::string defaultPackagePath(const std::string& level);

}  // namespace onelight::world
