#include "level_source.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "world/error.hpp"
#include "world/level_names.hpp"
#include "world/process/child_process.hpp"

namespace onelight::game {

namespace {

namespace fs = std::filesystem;

std::string lowerExtension(const fs::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

// The compiler's error line without its own prefix, or the first line of its output.
std::string compilerError(const std::string& output) {
    const std::string prefix = "onelight-bake: error: ";
    size_t start = 0;
    std::string first;
    while (start < output.size()) {
        size_t end = output.find('\n', start);
        if (end == std::string::npos) end = output.size();
        const std::string line = output.substr(start, end - start);
        if (line.rfind(prefix, 0) == 0) return line.substr(prefix.size());
        if (first.empty() && !line.empty()) first = line;
        start = end + 1;
    }
    return first;
}

// Runs onelight-bake: compile alone first (fast, its one-line errors captured), then the bake,
// with the baker's progress bars on stderr when a person watches it (a terminal).
void compileAndBake(const std::string& level, const std::string& package, const fs::path& bake,
                    const std::vector<std::string>& bakeOptions, const std::string& why) {
    world::ChildOptions merged;
    merged.err = world::ChildStream::kIntoStdout;
    world::ChildResult run =
        world::runChild({bake.string(), "compile", level, "-o", package}, merged);
    if (run.exitCode != 0) {
        const std::string error = compilerError(run.out);
        throw world::Error(error.empty() ? level + ": onelight-bake compile failed (" +
                                               world::describeEnd(run) + ")"
                                         : error);
    }
    const bool watched = isatty(STDERR_FILENO) != 0;
    if (watched) std::fprintf(stderr, "onelight: baking %s (%s)\n", level.c_str(), why.c_str());
    std::vector<std::string> argv = {bake.string(), level, "-o", package};
    argv.insert(argv.end(), bakeOptions.begin(), bakeOptions.end());
    world::ChildOptions options = merged;
    if (watched) options.err = world::ChildStream::kInherit;  // its progress bars
    run = world::runChild(argv, options);
    if (run.exitCode != 0) {
        const std::string error = compilerError(run.out);
        throw world::Error(error.empty()
                               ? level + ": onelight-bake failed (" + world::describeEnd(run) + ")"
                               : error);
    }
}

// A Quake 3 map: its package NAME.olpak in the current folder, baked at draft quality when
// missing or older than the baker (or than the .bsp file) (a first look takes seconds; bake it
// yourself with onelight-bake --quality default for more).
std::string resolveQuake3Package(const std::string& level, const std::string& baker,
                                 const std::string& quality) {
    std::error_code ec;
    const std::string package = world::defaultPackagePath(level);
    const fs::path bake = baker;
    const bool bakerKnown = fs::exists(bake, ec);
    // A .bsp file edited since (recompiled by q3map2) makes it stale too.
    const bool mapFile = fs::is_regular_file(level, ec);
    if (fs::exists(package, ec) &&
        (!bakerKnown || fs::last_write_time(package, ec) >= fs::last_write_time(bake, ec)) &&
        (!mapFile || fs::last_write_time(package, ec) >= fs::last_write_time(level, ec)))
        return package;
    if (!bakerKnown)
        throw world::Error(level + ": needs compiling, but " + bake.string() +
                           " is missing; expected onelight-bake beside onelight");
    compileAndBake(level, package, bake, {"--quality", quality},
                   "a Quake 3 map at " + quality + " quality into " + package);
    return package;
}

}  // namespace

std::string resolveLevelPackage(const std::string& level, const std::string& quality) {
    return resolveLevelPackageWith(level, world::executableBeside("onelight-bake"), quality);
}

std::string resolveLevelPackageWith(const std::string& level, const std::string& baker,
                                    const std::string& quality) {
    std::error_code ec;
    // A Quake 3 map: NAME.bsp (a file or not), PAK.pk3:maps/NAME.bsp, or a bare NAME that is no
    // file here.
    const std::string ext = lowerExtension(level);
    if (world::isQuake3Map(level) &&
        (ext == ".bsp" || !fs::is_regular_file(level, ec) || level.find(':') != std::string::npos))
        return resolveQuake3Package(level, baker, quality.empty() ? "draft" : quality);
    if (!fs::is_regular_file(level, ec))
        throw world::Error(
            level + ": no such file; expected a glTF level (.gltf, .glb) or a .olpak package");
    if (ext == ".olpak") return level;
    if (ext != ".gltf" && ext != ".glb")
        throw world::Error(level + ": unknown kind of file; expected .gltf, .glb or .olpak");
    const fs::path compiled = fs::path(level).replace_extension(".olpak");
    const std::string package = compiled.string();
    const fs::path bake = baker;
    // Fresh: newer than the level and than the baker (a rebuilt baker bakes differently).
    const bool bakerKnown = fs::exists(bake, ec);
    const bool fresh =
        fs::exists(compiled, ec) &&
        fs::last_write_time(compiled, ec) >= fs::last_write_time(level, ec) &&
        (!bakerKnown || fs::last_write_time(compiled, ec) >= fs::last_write_time(bake, ec));
    if (fresh && !ec) return package;

    if (!bakerKnown)
        throw world::Error(level + ": needs compiling, but " + bake.string() +
                           " is missing; expected onelight-bake beside onelight");
    compileAndBake(level, package, bake,
                   quality.empty() ? std::vector<std::string>{}
                                   : std::vector<std::string>{"--quality", quality},
                   "the package is missing or older than the level or the baker" +
                       (quality.empty() ? std::string() : ", at " + quality + " quality"));
    return package;
}

}  // namespace onelight::game
