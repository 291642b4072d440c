// The command line of `onelight`.
#pragma once

#include <cstdint>
#include <string>

namespace onelight::game {

struct CommandLine {
    std::string level;    // .gltf, .glb, .olpak, or a Quake 3 map (world/level_names.hpp)
    std::string quality;  // the bake's when onelight bakes LEVEL; empty: draft for a Quake 3
                          // map, the baker's default for a glTF
    bool headless = false;
    uint32_t width = 1280, height = 720;
    std::string camera;   // NAME or x,y,z,yaw,pitch; empty = the level's first or automatic
    std::string capture;  // out/NAME: writes NAME.png, NAME.exr, NAME.json
    uint32_t msaa = 2;
    uint32_t anisotropy = 1;        // material textures' anisotropic filtering taps, 1 = off
    bool fxaa = false;              // --fxaa (RendererOptions::fxaa)
    bool probesPerNormal = false;   // --probes-per-normal (RendererOptions::probesPerNormal)
    uint32_t shadowMapSize = 1024;  // --shadow-map-size: texels per side, every shadow layer
    uint32_t sunCascades = 3;       // --sun-cascades (RendererOptions::sunCascades)
    float shadowDistance = 40.0f;   // --shadow-distance: metres from the camera with runtime
                                    // shadows (RendererOptions::shadowRadius)
    bool probes = true;             // --no-probes: the package's probes ignored
    float renderScale = 0.0f;       // --render-scale: the window's frame at this fraction of its
                                    // size; 0 = automatic (0.5 on a CPU device, else 1)
    uint32_t frames = 0;            // quit after this many frames (0: window until Esc,
                                    // headless 1); headless captures the last
    bool flashlight = false;        // the spot effect light at the camera
    std::string replay;             // a replay script to run (game mode, fixed tick)
    std::string captureDir;         // where a replay's captures go (default: captures/)
    bool benchmark = false;         // --benchmark REPLAY: every tick drawn as fast as possible,
                                    // no captures; frame-time statistics on stdout
    bool freeFly = false;           // window: a free-fly camera instead of the player
    bool visibilityCulling = true;  // --no-visibility: draw outside the visible set too
    bool rasterFloor = false;       // --raster-floor: the view's triangles alone (benchmarks)
    std::string view = "onelight";  // whose baked light is shown: onelight, or q3map2 (the
                                    // Quake 3 map's own lightmaps, game/lighting_view.hpp)
    bool hasEv100 = false;          // --ev100: a fixed exposure instead of the metered one
    float ev100 = 0.0f;
    bool help = false;  // -h or --help: print usage() and exit 0
};

/// Parses argv by the game's option table (world/command_options.hpp). Throws world::Error, one
/// line naming the option, the value and what was expected ("onelight: " not included), on a bad
/// argument or a combination that cannot work.
[[nodiscard]] CommandLine parseCommandLine(int argc, char** argv);

/// The help: synopsis, what the modes are, every option with its default.
[[nodiscard]] std::string usage();

}  // namespace onelight::game
