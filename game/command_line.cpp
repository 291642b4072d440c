#include "command_line.hpp"

#include <cstdlib>
#include <exception>

namespace onelight::game {

const char* const kUsage =
    "usage: onelight LEVEL(.gltf|.glb|.olpak) [--headless] [--size WxH] "
    "[--camera NAME|x,y,z,yaw,pitch] [--capture out/NAME] [--msaa N] [--frames N] [--flashlight] "
    "[--replay SCRIPT [--capture-dir DIR]] [--free-fly]";

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

bool parseCommandLine(int argc, char** argv, CommandLine& out, std::string& error) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool hasValue = i + 1 < argc;
        if (a == "--headless") {
            out.headless = true;
        } else if (a == "--flashlight") {
            out.flashlight = true;
        } else if (a == "--size" && hasValue) {
            const std::string v = argv[++i];
            const size_t x = v.find('x');
            if (x == std::string::npos || !parseUnsigned(v.substr(0, x), 1, 16384, out.width) ||
                !parseUnsigned(v.substr(x + 1), 1, 16384, out.height)) {
                error = "--size '" + v + "': expected WxH, e.g. 1280x720";
                return false;
            }
        } else if (a == "--free-fly") {
            out.freeFly = true;
        } else if (a == "--replay" && hasValue) {
            out.replay = argv[++i];
        } else if (a == "--capture-dir" && hasValue) {
            out.captureDir = argv[++i];
        } else if (a == "--camera" && hasValue) {
            out.camera = argv[++i];
        } else if (a == "--capture" && hasValue) {
            out.capture = argv[++i];
        } else if (a == "--msaa" && hasValue) {
            if (!parseUnsigned(argv[++i], 1, 64, out.msaa)) {
                error = std::string("--msaa '") + argv[i] + "': expected 1, 2, 4 or 8";
                return false;
            }
        } else if (a == "--frames" && hasValue) {
            if (!parseUnsigned(argv[++i], 1, 1u << 30, out.frames)) {
                error = std::string("--frames '") + argv[i] + "': expected a positive count";
                return false;
            }
        } else if (!a.empty() && a[0] != '-' && out.level.empty()) {
            out.level = a;
        } else {
            error = "unexpected argument '" + a + "'; " + kUsage;
            return false;
        }
    }
    if (out.level.empty()) {
        error = std::string("no level given; ") + kUsage;
        return false;
    }
    return true;
}

}  // namespace onelight::game
