#!/usr/bin/env python3
"""The frame rate against the game's own renderers, view by view.

For each of the four real-level maps (aggressor, q3dm6ish, kaos, oa_bases3) and each of its
spawns 0-2, at 1280x720 with MSAA 4x:
  - ours: `onelight PACKAGE --headless --camera spawnN --frames F` (the package baked at draft
    quality when missing, as ./play bakes a map): the first frame after load, the median of the
    frames after it (wall time, each frame waited for), the GPU median and the renderer's
    creation (pipelines warmed included);
  - the raster floor of the same view (`--raster-floor`: the view's triangles, depth and one
    colour, the same targets, tonemap and MSAA);
  - the window at the default render scale, under Xvfb: the median frame time after the first;
  - OpenArena's own engine (ioquake3, Debian's `openarena`) on the same view: a demo recorded
    standing at the spawn (`setviewpos` from our camera, vertical field of view matched through
    cg_fov), then `timedemo` with the opengl1 and the opengl2 renderer, per-frame times from
    cl_timedemoLog, the median after the first frame (the view's miss in the table: how far
    from our camera OpenArena's player came to rest).

    scripts/frame-rate.py [--out DIR] [--maps a,b] [--spawns 0,1,2] [--frames N]

Needs a build (build/bin/onelight, onelight-bake) and the Debian packages openarena, xvfb and
mesa-utils (./test installs them: scripts/test-packages.txt). Run it on a quiet machine: both engines rasterize on the CPU, and frame times rise
several-fold when another process uses the cores. Writes DIR/frame-rate.md and .json.
"""
import argparse
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.path.join(ROOT, "build", "bin")
MAPS = {"aggressor": "pak1-maps.pk3:maps/aggressor.bsp", "q3dm6ish": "q3dm6ish", "kaos": "kaos",
        "oa_bases3": "oa_bases3"}
WIDTH, HEIGHT = 1280, 720
XVFB = ["xvfb-run", "-a", "-s", f"-screen 0 {WIDTH}x{HEIGHT}x24"]
QUAKE_UNITS_PER_METRE = 32.0
VIEW_HEIGHT = 26.0  # Quake 3's DEFAULT_VIEWHEIGHT, units above the player's origin


def log(message):
    print(f"frame-rate: {message}", file=sys.stderr, flush=True)


def run(command, what, timeout=1800, env=None):
    result = subprocess.run(command, capture_output=True, text=True, timeout=timeout, env=env)
    if result.returncode != 0:
        raise RuntimeError(f"{what} failed ({result.returncode}): {' '.join(command)}\n"
                           f"{result.stderr[-2000:]}")
    return result.stdout


def median_after_first(values):
    rest = values[1:] if len(values) > 1 else values
    return statistics.median(rest) if rest else float("nan")


def ours(package, spawn, out, frames, extra=(), window=False):
    """One run of the game; the capture's sidecar with its timings."""
    capture = os.path.join(out, os.path.basename(package).replace(".olpak", "") + "_" + spawn +
                           ("_floor" if "--raster-floor" in extra else "") +
                           ("_window" if window else ""))
    command = [os.path.join(BIN, "onelight"), package, "--size", f"{WIDTH}x{HEIGHT}", "--msaa",
               "4", "--camera", spawn, "--frames", str(frames), "--capture", capture, *extra]
    if window:
        command = XVFB + command
    else:
        command.append("--headless")
    run(command, "onelight")
    with open(capture + ".json") as f:
        return json.load(f)


def quake_view(sidecar):
    """Our camera as Quake 3 sees it: origin (feet, units) and yaw (degrees)."""
    x, y, z = sidecar["camera"]["position"]
    fx, fy, fz = sidecar["camera"]["forward"]
    origin = (x * QUAKE_UNITS_PER_METRE, -z * QUAKE_UNITS_PER_METRE,
              y * QUAKE_UNITS_PER_METRE - VIEW_HEIGHT)
    yaw = math.degrees(math.atan2(-fz, fx))
    # cg_fov is horizontal for the frame's aspect: the one giving our vertical field of view.
    fov_x = 2.0 * math.degrees(math.atan(math.tan(sidecar["camera"]["yfov"] / 2.0) *
                                         WIDTH / HEIGHT))
    return origin, yaw, fov_x


def openarena(home, args, what, timeout=900):
    command = XVFB + ["/usr/games/openarena", "+set", "fs_homepath", home, "+set", "r_fullscreen",
                      "0", "+set", "r_mode", "-1", "+set", "com_introplayed", "1", "+set",
                      "r_swapInterval", "0", "+set", "cg_draw2D", "0", "+set", "cg_drawGun", "0",
                      *args]
    result = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    if result.returncode != 0:
        raise RuntimeError(f"{what} failed ({result.returncode}): {' '.join(command)}\n"
                           f"{result.stderr[-2000:]}")
    return result.stdout + result.stderr  # ioquake3 prints its console to either


def record_demo(home, game_map, name, origin, yaw):
    """A demo of the player standing at origin, facing yaw (recorded small: only its content
    counts). Quake 3's setviewpos teleports, and a teleport pushes the player 400 units/s along
    its facing: in noclip (no gravity, no walls, steady friction) it drifts the same way every
    time, so a first run measures the drift and the second starts that far behind. Returns the
    distance (units) between where it rests and origin."""
    os.makedirs(os.path.join(home, "baseoa"), exist_ok=True)
    target = origin

    def rest_point(start, record):
        script = os.path.join(home, "baseoa", name + ".cfg")
        with open(script, "w") as f:
            f.write("set bot_enable 0\nset g_doWarmup 0\nset g_synchronousClients 1\nwait 150\n"
                    f"noclip\nsetviewpos {start[0]:.1f} {start[1]:.1f} {start[2]:.1f} {yaw:.1f}\n"
                    "wait 90\nviewpos\n" +
                    (f"record {name}\nwait 120\nstoprecord\n" if record else "") +
                    "wait 5\nquit\n")
        out = openarena(home, ["+set", "r_customwidth", "320", "+set", "r_customheight", "180",
                               "+set", "cl_renderer", "opengl1", "+set", "sv_pure", "0",
                               "+devmap", game_map, "+exec", name + ".cfg"],
                        "recording the OpenArena demo")
        for line in out.splitlines():
            line = line.strip()
            if line.startswith("(") and ") :" in line:
                return [float(v) for v in line[1:line.index(")")].split()]
        raise RuntimeError(f"OpenArena printed no viewpos on {game_map}")

    rest = rest_point(target, False)
    start = (2 * target[0] - rest[0], 2 * target[1] - rest[1], target[2])
    rest = rest_point(start, True)
    return math.hypot(rest[0] - target[0], rest[1] - target[1])


def timedemo(home, name, renderer, fov_x):
    """Per-frame milliseconds of OpenArena playing demo `name` as fast as it can."""
    log_name = f"{name}_{renderer}.log"
    path = os.path.join(home, "baseoa", log_name)
    if os.path.exists(path):
        os.remove(path)
    openarena(home, ["+set", "r_customwidth", str(WIDTH), "+set", "r_customheight", str(HEIGHT),
                     "+set", "r_ext_multisample", "4", "+set", "cl_renderer", renderer, "+set",
                     "cg_fov", f"{fov_x:.1f}", "+set", "timedemo", "1", "+set",
                     "cl_timedemoLog", log_name, "+set", "nextdemo", "quit", "+demo", name],
              f"OpenArena's timedemo ({renderer})")
    with open(path) as f:
        lines = f.read().split("\n")
    return [float(v) for v in lines[1:] if v.strip()]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "frame-rate"))
    parser.add_argument("--maps", default=",".join(MAPS))
    parser.add_argument("--spawns", default="0,1,2")
    parser.add_argument("--frames", type=int, default=13)
    args = parser.parse_args()
    for tool in ("onelight", "onelight-bake"):
        if not os.access(os.path.join(BIN, tool), os.X_OK):
            sys.exit(f"frame-rate: {BIN}/{tool} is missing; build first (./test)")
    for tool in ("xvfb-run", "/usr/games/openarena"):
        if not shutil.which(tool):
            sys.exit(f"frame-rate: {tool} is missing; install the Debian packages openarena, "
                     "xvfb and mesa-utils")
    os.makedirs(args.out, exist_ok=True)
    home = os.path.join(args.out, "openarena-home")
    rows, figures = [], []
    for game_map in args.maps.split(","):
        package = os.path.join(args.out, game_map + ".olpak")
        baker = os.path.join(BIN, "onelight-bake")
        if not os.path.exists(package) or os.path.getmtime(package) < os.path.getmtime(baker):
            log(f"{game_map}: baking at draft quality (no package, or one older than the baker)")
            run([os.path.join(BIN, "onelight-bake"), MAPS.get(game_map, game_map), "-o", package,
                 "--quality", "draft", "--quiet"], "onelight-bake")
        for spawn in (f"spawn{s}" for s in args.spawns.split(",")):
            log(f"{game_map} {spawn}: ours, its raster floor, the window")
            full = ours(package, spawn, args.out, args.frames)
            floor = ours(package, spawn, args.out, args.frames, ("--raster-floor",))
            window = ours(package, spawn, args.out, 2 * args.frames, window=True)
            origin, yaw, fov_x = quake_view(full)
            log(f"{game_map} {spawn}: OpenArena at {origin[0]:.0f} {origin[1]:.0f} "
                f"{origin[2]:.0f}, yaw {yaw:.0f}, cg_fov {fov_x:.1f}")
            demo = f"{game_map}_{spawn}"
            miss = record_demo(home, game_map, demo, origin, yaw)
            oa = {r: timedemo(home, demo, r, fov_x) for r in ("opengl1", "opengl2")}
            t = full["timings_ms"]
            f = {"map": game_map, "spawn": spawn, "triangles": full["frame"]["triangles"],
                 "ours_ms": t["wall_median_after_first"], "ours_gpu_ms": t["gpu_median"],
                 "first_frame_ms": t["first_frame_wall"], "renderer_create_ms": t["renderer_create"],
                 "floor_ms": floor["timings_ms"]["wall_median_after_first"],
                 "window_ms": window["timings_ms"]["wall_median_after_first"],
                 "window_frame": window["size"],
                 "opengl1_ms": median_after_first(oa["opengl1"]),
                 "opengl2_ms": median_after_first(oa["opengl2"]),
                 "opengl1_frames": len(oa["opengl1"]), "opengl2_frames": len(oa["opengl2"]),
                 "openarena_view_off_by_units": miss}
            figures.append(f)
            rows.append(
                "| %s | %s (%.0f u) | %d | %.0f | %.0f | %.0f | %.2f | %.0f | %.2f | %.0f (%.1fx) | %.0f | %.1f |" % (
                    game_map, spawn, miss, f["triangles"], f["ours_ms"], f["opengl1_ms"],
                    f["opengl2_ms"], f["ours_ms"] / f["opengl1_ms"], f["floor_ms"],
                    f["ours_ms"] / f["floor_ms"], f["first_frame_ms"],
                    f["first_frame_ms"] / f["ours_ms"], f["renderer_create_ms"],
                    1000.0 / f["window_ms"]))
            log(rows[-1])
    table = "\n".join([
        "| map | view (OpenArena's miss) | triangles drawn | ours ms | OpenArena opengl1 ms | opengl2 ms | ours / opengl1 | "
        "raster floor ms | ours / floor | first frame ms (x steady) | renderer creation ms | "
        "window fps |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|"] + rows)
    with open(os.path.join(args.out, "frame-rate.json"), "w") as f:
        json.dump({"date": time.strftime("%Y-%m-%d"), "loadavg": open("/proc/loadavg").read().split()[:3],
                   "views": figures}, f, indent=2)
    with open(os.path.join(args.out, "frame-rate.md"), "w") as f:
        f.write(table + "\n")
    print(table)


if __name__ == "__main__":
    main()
