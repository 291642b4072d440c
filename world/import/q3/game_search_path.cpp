#include "world/import/q3/game_search_path.hpp"

#include <filesystem>

#include "world/error.hpp"
#include "world/file_read.hpp"

namespace onelight::world::q3 {
namespace {

namespace fs = std::filesystem;

bool endsWithKey(const std::string& s, const std::string& end) {
    const std::string key = fileKey(s);
    return key.size() >= end.size() && key.compare(key.size() - end.size(), end.size(), end) == 0;
}

// The path with links and dots resolved, to compare folders; as given when that fails.
std::string canonicalFolder(const fs::path& path) {
    std::error_code ec;
    const fs::path c = fs::weakly_canonical(path, ec);
    return ec ? path.lexically_normal().string() : c.string();
}

const InstalledGame* gameOfFolder(const std::vector<InstalledGame>& games, const fs::path& folder) {
    const std::string wanted = canonicalFolder(folder);
    for (const InstalledGame& g : games)
        if (canonicalFolder(g.folder) == wanted) return &g;
    return nullptr;
}

// How many of the map's shaders have an image of their name in `files` (an estimate of which
// game the map was made for: scripts that name other images are not counted).
size_t imagesFound(const GameFiles& files, const BspFile& bsp) {
    size_t found = 0;
    for (const BspShader& shader : bsp.shaders) {
        std::string base = shaderName(shader);
        for (const char* ext : {".tga", ".jpg", ".png"})
            if (endsWithKey(base, ext)) base.resize(base.size() - 4);
        for (const char* ext : {".tga", ".jpg", ".png"})
            if (files.has(base + ext)) {
                ++found;
                break;
            }
    }
    return found;
}

// The files of the game `folders` name, or when none do, those of the installed game holding the
// most of the map's images (the first on a tie).
void openGame(OpenedMap& map, const std::vector<std::string>& folders) {
    if (!folders.empty()) {
        for (const std::string& folder : folders) map.files.addGameFolder(folder);
        return;
    }
    size_t best = 0;
    bool chosen = false;
    for (const InstalledGame& g : installedGames()) {
        GameFiles files;
        files.addGameFolder(g.folder);
        const size_t found = imagesFound(files, map.bsp);
        if (!chosen || found > best) {
            map.files = std::move(files);
            map.game = g.name;
            best = found;
            chosen = true;
        }
    }
    if (!chosen) map.game = "no installed game";
}

std::string listOf(const std::vector<std::string>& folders) {
    std::string out;
    for (const std::string& f : folders) out += (out.empty() ? "" : ", ") + f;
    return out;
}

OpenedMap openFromPk3(const std::string& spec, size_t colon,
                      const std::vector<std::string>& gameFolders) {
    const std::vector<InstalledGame> games = installedGames();
    fs::path pk3 = spec.substr(0, colon + 4);
    const std::string inside = spec.substr(colon + 5);
    // A bare pk3 name that is not here is looked for in the game folders
    // (pak1-maps.pk3:maps/aggressor.bsp).
    std::error_code ec;
    if (!fs::exists(pk3, ec) && pk3.is_relative()) {
        std::vector<std::string> folders = gameFolders;
        if (folders.empty())
            for (const InstalledGame& g : games) folders.push_back(g.folder);
        for (const std::string& folder : folders)
            if (fs::exists(fs::path(folder) / pk3, ec)) {
                pk3 = fs::path(folder) / pk3;
                break;
            }
    }
    OpenedMap map;
    {
        const Pk3Archive archive(pk3.string());
        bool found = false;
        for (const std::string& n : archive.names())
            if (fileKey(n) == fileKey(inside)) {
                map.where = pk3.string() + ":" + n;
                map.pk3 = pk3.string();
                map.bsp = parseBsp(archive.read(n, kMaxMapBytes, "a Quake 3 map"), map.where);
                found = true;
                break;
            }
        if (!found) throw Error(spec + ": " + pk3.string() + " holds no '" + inside + "'");
    }
    map.name = fs::path(inside).stem().string();
    const fs::path folder = pk3.parent_path().empty() ? fs::path(".") : pk3.parent_path();
    bool inGame = false;
    if (!gameFolders.empty()) {
        map.game = "the given folders";
        for (const std::string& f : gameFolders)
            inGame |= canonicalFolder(f) == canonicalFolder(folder);
        openGame(map, gameFolders);
    } else if (const InstalledGame* g = gameOfFolder(games, folder)) {
        map.game = g->name;
        inGame = true;
        openGame(map, {g->folder});
    } else {
        openGame(map, {});
    }
    if (!inGame) map.files.add(pk3.string());  // a map pk3 of its own: searched last, wins
    return map;
}

OpenedMap openFromFile(const std::string& spec, const std::vector<std::string>& gameFolders) {
    OpenedMap map;
    map.where = spec;
    map.bspFile = spec;
    map.name = fs::path(spec).stem().string();
    map.bsp = parseBsp(readRegularFile(spec, "a Quake 3 .bsp map"), spec);
    // GAME/maps/NAME.bsp: GAME is the game folder, or a folder of loose files beside the game.
    const fs::path parent = fs::path(spec).parent_path();
    const fs::path root =
        fileKey(parent.filename().string()) == "maps"
            ? (parent.parent_path().empty() ? fs::path(".") : parent.parent_path())
            : fs::path();
    const InstalledGame* g = root.empty() ? nullptr : gameOfFolder(installedGames(), root);
    bool inGame = false;
    if (!gameFolders.empty()) {
        map.game = "the given folders";
        for (const std::string& f : gameFolders)
            inGame |= !root.empty() && canonicalFolder(f) == canonicalFolder(root);
        openGame(map, gameFolders);
    } else if (g) {
        map.game = g->name;
        inGame = true;
        openGame(map, {g->folder});
    } else {
        openGame(map, {});
    }
    if (!root.empty() && !inGame) map.files.addLooseFiles(root.string());
    return map;
}

OpenedMap openByName(const std::string& spec, const std::vector<std::string>& gameFolders) {
    const std::string name = "maps/" + spec + ".bsp";
    OpenedMap map;
    map.name = spec;
    std::vector<std::string> searched;
    bool found = false;
    if (!gameFolders.empty()) {
        map.game = "the given folders";
        openGame(map, gameFolders);
        searched = gameFolders;
        found = map.files.has(name);
    } else {
        for (const InstalledGame& g : installedGames()) {
            GameFiles files;
            files.addGameFolder(g.folder);
            searched.push_back(g.folder);
            if (!files.has(name)) continue;
            map.files = std::move(files);
            map.game = g.name;
            found = true;
            break;
        }
    }
    if (!found)
        throw Error(spec + ": no map of that name (" + name + ") in the pk3s and files of " +
                    (searched.empty() ? std::string("no game folder (install openarena-data and "
                                                    "openarena-081-maps, or nexuiz-data)")
                                      : listOf(searched)));
    map.where = map.files.where(name);
    const size_t archive = map.files.files.at(fileKey(name)).first;
    if (archive != GameFiles::kLoose) map.pk3 = map.files.archives[archive]->path();
    map.bsp = parseBsp(*map.files.read(name, kMaxMapBytes, "a Quake 3 map"), map.where);
    return map;
}

}  // namespace

std::vector<InstalledGame> installedGames() {
    std::vector<InstalledGame> out;
    for (const InstalledGame& g : {InstalledGame{"OpenArena", "/usr/share/games/openarena/baseoa"},
                                   InstalledGame{"Nexuiz", "/usr/share/games/nexuiz/data"}}) {
        std::error_code ec;
        if (fs::is_directory(g.folder, ec)) out.push_back(g);
    }
    return out;
}

OpenedMap openQuake3Map(const std::string& spec, const std::vector<std::string>& gameFolders) {
    const size_t colon = fileKey(spec).find(".pk3:");
    if (colon != std::string::npos) return openFromPk3(spec, colon, gameFolders);
    if (endsWithKey(spec, ".bsp")) return openFromFile(spec, gameFolders);
    return openByName(spec, gameFolders);
}

}  // namespace onelight::world::q3
