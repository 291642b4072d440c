#include "command_line.hpp"

#include <cstdlib>
#include <exception>
#include <utility>

#include "world/error.hpp"

namespace onelight::game {

std::string usage() {
    const CommandLine d;
    const std::pair<const char*, std::string> options[] = {
        {"--headless", "no window: draw offscreen, one frame or the replay (default: a window)"},
        {"--size WxH", "frame size, 1..16384 each (default: " + std::to_string(d.width) + "x" +
                           std::to_string(d.height) + ")"},
        {"--camera NAME|x,y,z,yaw,pitch",
         "view from a level camera or a pose (default: the player in a window; headless, the "
         "level's first camera, else one framing the level)"},
        {"--capture out/NAME", "write NAME.png, NAME.exr and NAME.json (default: none)"},
        {"--msaa N",
         "samples, the nearest supported is used (default: " + std::to_string(d.msaa) + ")"},
        {"--anisotropy N",
         "material textures' anisotropic filtering, 1 (off)..16 taps, clamped to the device's "
         "(default: " +
             std::to_string(d.anisotropy) + ")"},
        {"--shadow-map-size N", "texels per side of every shadow map layer, 64..8192 (default: " +
                                    std::to_string(d.shadowMapSize) + ")"},
        {"--shadow-distance M",
         "metres from the camera with runtime shadows, beyond them the baked ones, 1..10000 "
         "(default: " +
             std::to_string(int(d.shadowDistance)) + ")"},
        {"--no-probes",
         "ignore the package's probes, a uniform environment instead (default: "
         "the probes)"},
        {"--render-scale S",
         "window only: draw at S (0.25..1) of the window's size and scale up to it (default: "
         "0.5 on a CPU device such as lavapipe, else 1)"},
        {"--frames N",
         "quit after N frames, headless capturing the last (default: until Esc; headless 1)"},
        {"--flashlight", "the spot effect light at the camera (default: off)"},
        {"--replay SCRIPT", "play a replay script on the fixed tick (default: none)"},
        {"--capture-dir DIR", "where a replay's captures go (default: captures/)"},
        {"--benchmark REPLAY",
         "play REPLAY drawing every tick as fast as possible, no captures; print the median and "
         "95th-percentile frame times as key=value (default: none)"},
        {"--free-fly", "a free-fly camera instead of the player (default: the player)"},
        {"--no-visibility",
         "draw static surfaces outside the camera's potentially visible set too (default: "
         "culled by the package's visibility)"},
        {"--quality Q",
         "draft, default or high: the bake's when LEVEL needs baking (default: draft for a "
         "Quake 3 map, else the baker's default)"},
        {"--view onelight|q3map2",
         "whose baked light to show: the engine's, or a Quake 3 map's own q3map2 lightmaps "
         "(default: onelight)"},
        {"--ev100 EV", "a fixed exposure, -10..30 (default: metered in the view)"},
        {"-h, --help", "this help"}};
    std::string text =
        "usage: onelight LEVEL(.gltf|.glb|.olpak|.bsp|PAK.pk3:maps/NAME.bsp|NAME) [OPTIONS]\n"
        "  plays LEVEL in a window (a .gltf or .glb is baked first when its package is stale; a\n"
        "  Quake 3 map NAME into NAME.olpak here, at draft quality)\n";
    for (const auto& [flag, meaning] : options) {
        const std::string f = flag;
        text += "  " + f + std::string(f.size() < 32 ? 32 - f.size() : 1, ' ') + meaning + "\n";
    }
    return text;
}

namespace {

bool parseUnsigned(const std::string& text, uint32_t low, uint32_t high, uint32_t& out) {
    try {
        size_t used = 0;
        const unsigned long value = std::stoul(text, &used);
        if (used != text.size() || value < low || value > high) return false;
        out = uint32_t(value);
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace

CommandLine parseCommandLine(int argc, char** argv) {
    CommandLine out;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool hasValue = i + 1 < argc;
        if (a == "-h" || a == "--help") {
            out.help = true;
            return out;
        } else if (a == "--headless") {
            out.headless = true;
        } else if (a == "--flashlight") {
            out.flashlight = true;
        } else if (a == "--size" && hasValue) {
            const std::string v = argv[++i];
            const size_t x = v.find('x');
            if (x == std::string::npos || !parseUnsigned(v.substr(0, x), 1, 16384, out.width) ||
                !parseUnsigned(v.substr(x + 1), 1, 16384, out.height))
                throw world::Error("--size '" + v + "': expected WxH, e.g. 1280x720");

        } else if (a == "--free-fly") {
            out.freeFly = true;
        } else if (a == "--no-visibility") {
            out.visibilityCulling = false;
        } else if (a == "--replay" && hasValue) {
            out.replay = argv[++i];
        } else if (a == "--benchmark" && hasValue) {
            out.replay = argv[++i];
            out.benchmark = true;
        } else if (a == "--capture-dir" && hasValue) {
            out.captureDir = argv[++i];
        } else if (a == "--quality" && hasValue) {
            out.quality = argv[++i];
            if (out.quality != "draft" && out.quality != "default" && out.quality != "high")
                throw world::Error("--quality '" + out.quality +
                                   "': expected draft, default or high");
        } else if (a == "--view" && hasValue) {
            out.view = argv[++i];
            if (out.view != "onelight" && out.view != "q3map2")
                throw world::Error("--view '" + out.view + "': expected onelight or q3map2");
        } else if (a == "--render-scale" && hasValue) {
            const std::string v = argv[++i];
            bool valid = false;
            try {
                size_t used = 0;
                out.renderScale = std::stof(v, &used);
                valid = used == v.size() && out.renderScale >= 0.25f && out.renderScale <= 1.0f;
            } catch (const std::exception&) {
            }
            if (!valid)
                throw world::Error("--render-scale '" + v + "': expected a number in [0.25, 1]");
        } else if (a == "--ev100" && hasValue) {
            const std::string v = argv[++i];
            try {
                size_t used = 0;
                out.ev100 = std::stof(v, &used);
                out.hasEv100 = used == v.size() && out.ev100 >= -10.0f && out.ev100 <= 30.0f;
            } catch (const std::exception&) {
                out.hasEv100 = false;
            }
            if (!out.hasEv100)
                throw world::Error("--ev100 '" + v + "': expected a number in [-10, 30]");
        } else if (a == "--camera" && hasValue) {
            out.camera = argv[++i];
        } else if (a == "--capture" && hasValue) {
            out.capture = argv[++i];
        } else if (a == "--msaa" && hasValue) {
            if (!parseUnsigned(argv[++i], 1, 64, out.msaa))
                throw world::Error(std::string("--msaa '") + argv[i] + "': expected 1, 2, 4 or 8");
        } else if (a == "--anisotropy" && hasValue) {
            if (!parseUnsigned(argv[++i], 1, 16, out.anisotropy))
                throw world::Error(std::string("--anisotropy '") + argv[i] +
                                   "': expected an integer in [1, 16]");

        } else if (a == "--shadow-map-size" && hasValue) {
            if (!parseUnsigned(argv[++i], 64, 8192, out.shadowMapSize))
                throw world::Error(std::string("--shadow-map-size '") + argv[i] +
                                   "': expected an integer in [64, 8192]");
        } else if (a == "--shadow-distance" && hasValue) {
            const std::string v = argv[++i];
            bool valid = false;
            try {
                size_t used = 0;
                out.shadowDistance = std::stof(v, &used);
                valid = used == v.size() && out.shadowDistance >= 1.0f &&
                        out.shadowDistance <= 10000.0f;
            } catch (const std::exception&) {
            }
            if (!valid)
                throw world::Error("--shadow-distance '" + v +
                                   "': expected metres, a number in [1, 10000]");
        } else if (a == "--no-probes") {
            out.probes = false;
        } else if (a == "--frames" && hasValue) {
            if (!parseUnsigned(argv[++i], 1, 1u << 30, out.frames))
                throw world::Error(std::string("--frames '") + argv[i] +
                                   "': expected a positive count");

        } else if (!a.empty() && a[0] != '-' && out.level.empty()) {
            out.level = a;
        } else
            throw world::Error("unexpected argument '" + a +
                               "' (onelight --help lists the options)");
    }
    if (out.level.empty()) throw world::Error("no level given (onelight --help lists the options)");
    if (out.headless && out.renderScale > 0.0f)
        throw world::Error(
            "--render-scale applies to the window; a headless frame's size is --size");

    return out;
}

}  // namespace onelight::game
