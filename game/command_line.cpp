#include "command_line.hpp"

#include <string>
#include <tuple>
#include <vector>

#include "world/command_options.hpp"
#include "world/error.hpp"

namespace onelight::game {
namespace {

using world::CommandOption;

const world::CommandTable& commandTable() {
    static const world::CommandTable table = [] {
        const CommandLine d;
        CommandOption ev100 = world::realOption("--ev100", "EV", -10.0, 30.0, "a fixed exposure",
                                                "metered in the view");
        CommandOption shadowDistance = world::realOption(
            "--shadow-distance", "M", 1.0, 10000.0,
            "metres from the camera with runtime shadows, beyond them the baked ones",
            world::shortestNumber(double(d.shadowDistance)));
        shadowDistance.expected = "metres, a number";
        CommandOption frames = world::integerOption(
            "--frames", "N", 1, double(1u << 30),
            "quit after N frames, headless capturing the last", "until Esc; headless 1");
        frames.expected = "a count of frames";
        world::CommandTable t;
        t.program = "onelight";
        t.synopsis = "onelight LEVEL(.gltf|.glb|.olpak|.bsp|PAK.pk3:maps/NAME.bsp|NAME) [OPTIONS]";
        t.summary =
            "plays LEVEL in a window (a .gltf or .glb is baked first when its package is stale; "
            "a\n  Quake 3 map NAME into NAME.olpak here, at draft quality)";
        t.options = {
            world::flagOption("--headless", "no window: draw offscreen, one frame or the replay",
                              "a window"),
            world::sizeOption("--size", 1, 16384, "frame size",
                              std::to_string(d.width) + "x" + std::to_string(d.height)),
            world::textOption("--camera", "NAME|x,y,z,yaw,pitch",
                              "view from a level camera or a pose (the level as the game "
                              "starts it, nothing moving; each dynamic object with the primary "
                              "the game picks where it stands)",
                              "the player in a window; headless, the level's first camera, else "
                              "one framing the level"),
            world::textOption("--capture", "out/NAME", "write NAME.png, NAME.exr and NAME.json",
                              "none"),
            world::integerOption("--msaa", "N", 1, 64, "samples, the nearest supported is used",
                                 std::to_string(d.msaa)),
            world::flagOption("--probes-per-normal",
                              "reflections scaled by the pixel's irradiance over the probe's at "
                              "the pixel's normal (docs/lighting.md \"Normalisation\")",
                              "over the probe's mean"),
            world::flagOption("--fxaa",
                              "post-process anti-aliasing of the tonemapped frame (FXAA), with "
                              "--msaa 1 in place of MSAA",
                              "off"),
            world::integerOption("--anisotropy", "N", 1, 16,
                                 "material textures' anisotropic filtering taps (1: off), "
                                 "clamped to the device's (slow on lavapipe: minutes a frame on a "
                                 "floor to the horizon)",
                                 std::to_string(d.anisotropy)),
            world::integerOption("--shadow-map-size", "N", 64, 8192,
                                 "texels per side of every shadow map layer",
                                 std::to_string(d.shadowMapSize)),
            world::integerOption("--sun-cascades", "N", 1, 4,
                                 "the sun's shadow maps, nearest first (1: one over the whole "
                                 "shadow distance)",
                                 std::to_string(d.sunCascades)),
            shadowDistance,
            world::flagOption("--no-probes",
                              "ignore the package's probes, a uniform environment instead",
                              "the probes"),
            world::realOption("--render-scale", "S", 0.25, 1.0,
                              "window only: draw at S of the window's size and scale up to it",
                              "0.5 on a CPU device such as lavapipe, else 1"),
            frames,
            world::flagOption("--flashlight", "the spot effect light at the camera", "off"),
            world::textOption("--replay", "SCRIPT", "play a replay script on the fixed tick",
                              "none"),
            world::textOption("--capture-dir", "DIR", "where a replay's captures go", "captures/"),
            world::textOption("--benchmark", "REPLAY",
                              "play REPLAY drawing every tick as fast as possible, no captures; "
                              "print the median and 95th-percentile frame times as key=value",
                              "none"),
            world::flagOption("--free-fly", "a free-fly camera instead of the player",
                              "the player"),
            world::flagOption("--raster-floor",
                              "draw the view's triangles with depth and one colour in the fewest "
                              "draws: the cost of rasterizing the view alone, for benchmarks",
                              "off"),
            world::flagOption("--no-visibility",
                              "draw static surfaces outside the camera's potentially visible set "
                              "too",
                              "culled by the package's visibility"),
            world::choiceOption("--quality", "Q", {"draft", "default", "high"},
                                "the bake's when LEVEL needs baking",
                                "draft for a Quake 3 map, else the baker's default"),
            world::choiceOption("--view", "onelight|q3map2", {"onelight", "q3map2"},
                                "whose baked light to show, the engine's or a Quake 3 map's own "
                                "q3map2 lightmaps",
                                d.view),
            ev100};
        t.positionalName = "level";
        t.minPositionals = t.maxPositionals = 1;
        return t;
    }();
    return table;
}

uint32_t countOf(const world::ParsedOptions& parsed, const std::string& name, uint32_t fallback) {
    return parsed.has(name) ? uint32_t(parsed.integer(name)) : fallback;
}

float realOf(const world::ParsedOptions& parsed, const std::string& name, float fallback) {
    return parsed.has(name) ? float(parsed.real(name)) : fallback;
}

}  // namespace

std::string usage() {
    return world::formatHelp(commandTable());
}

CommandLine parseCommandLine(int argc, char** argv) {
    const world::ParsedOptions parsed =
        world::parseOptions(commandTable(), std::vector<std::string>(argv + 1, argv + argc));
    CommandLine out;
    if (parsed.help) {
        out.help = true;
        return out;
    }
    out.level = parsed.positionals.at(0);
    out.quality = parsed.text("--quality");
    out.headless = parsed.has("--headless");
    if (parsed.has("--size")) std::tie(out.width, out.height) = parsed.size("--size");
    out.camera = parsed.text("--camera");
    out.capture = parsed.text("--capture");
    out.msaa = countOf(parsed, "--msaa", out.msaa);
    out.anisotropy = countOf(parsed, "--anisotropy", out.anisotropy);
    out.fxaa = parsed.has("--fxaa");
    out.probesPerNormal = parsed.has("--probes-per-normal");
    out.shadowMapSize = countOf(parsed, "--shadow-map-size", out.shadowMapSize);
    out.sunCascades = countOf(parsed, "--sun-cascades", out.sunCascades);
    out.shadowDistance = realOf(parsed, "--shadow-distance", out.shadowDistance);
    out.probes = !parsed.has("--no-probes");
    out.renderScale = realOf(parsed, "--render-scale", out.renderScale);
    out.frames = countOf(parsed, "--frames", out.frames);
    out.flashlight = parsed.has("--flashlight");
    out.replay = parsed.has("--benchmark") ? parsed.text("--benchmark") : parsed.text("--replay");
    out.benchmark = parsed.has("--benchmark");
    out.captureDir = parsed.text("--capture-dir");
    out.freeFly = parsed.has("--free-fly");
    out.visibilityCulling = !parsed.has("--no-visibility");
    out.rasterFloor = parsed.has("--raster-floor");
    if (parsed.has("--view")) out.view = parsed.text("--view");
    out.hasEv100 = parsed.has("--ev100");
    out.ev100 = realOf(parsed, "--ev100", out.ev100);

    if (out.headless && parsed.has("--render-scale"))
        throw world::Error(
            "--render-scale applies to the window; a headless frame's size is --size");
    if (parsed.has("--benchmark") && parsed.has("--replay"))
        throw world::Error(
            "--benchmark with --replay; expected one of them (--benchmark REPLAY plays REPLAY)");
    return out;
}

}  // namespace onelight::game
