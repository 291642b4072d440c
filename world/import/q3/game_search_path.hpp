// Which game a Quake 3 map belongs to, and that game's files as the game itself finds them. The
// one place where a map's name (NAME, PAK.pk3:maps/NAME.bsp, or a NAME.bsp file) becomes its
// bytes and the search path its textures, shader scripts and external lightmaps come from.
//
// The installed games: OpenArena (/usr/share/games/openarena/baseoa) and Nexuiz
// (/usr/share/games/nexuiz/data), each one game folder searched as the engine searches it
// (pk3_archive.hpp GameFiles::addGameFolder: pk3s alphabetically, later wins, loose files win
// over them). A map is read with the files of one game only:
//   NAME                  the first installed game whose search path holds maps/NAME.bsp;
//   PAK.pk3:maps/X.bsp    the game whose folder holds the pk3 (a bare PAK.pk3 is looked for in
//                         the game folders); a pk3 elsewhere is searched after the game's files;
//   X.bsp                 when it lies in GAME/maps/ and GAME is an installed game folder, that
//                         game; else GAME (the folder holding maps/, when there is one) is a
//                         folder of loose files searched after the game's files.
// A map outside every game folder is given to the installed game whose files hold the most of
// its shaders' images. Quake3Options::gameFolders, when given, is the game instead (tests).
#pragma once

#include <string>
#include <vector>

#include "world/import/q3/bsp_file.hpp"
#include "world/import/q3/pk3_archive.hpp"

namespace onelight::world::q3 {

struct InstalledGame {
    std::string name;    // "OpenArena", "Nexuiz"
    std::string folder;  // its game folder
};

/// The installed games whose folder exists, OpenArena first.
[[nodiscard]] std::vector<InstalledGame> installedGames();

/// A map read and checked, with its game's files.
struct OpenedMap {
    std::string where;    // "file.bsp" or "archive.pk3:maps/NAME.bsp", for messages
    std::string name;     // NAME: its external lightmaps are maps/NAME/lm_NNNN.tga
    std::string bspFile;  // the .bsp on disk when it is a plain file, else empty
    std::string pk3;      // the pk3 holding the .bsp when one does, else empty
    std::string game;     // the game's name, or "the given folders"
    BspFile bsp;
    GameFiles files;
};

/// Throws world::Error naming the map (and the searched folders) when it is not found, or
/// naming the file, lump and index when it is broken (bsp_file.hpp).
[[nodiscard]] OpenedMap openQuake3Map(const std::string& spec,
                                      const std::vector<std::string>& gameFolders);

}  // namespace onelight::world::q3
