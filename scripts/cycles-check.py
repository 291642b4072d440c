#!/usr/bin/env python3
"""The engine's reference path tracer against an outside one, Blender's Cycles (Debian `blender`),
on scenes where the two models agree: Lambert surfaces, punctual lights, a uniform sky.

  scripts/cycles-check.py [--bin build/bin] [--work DIR] [--size WxH] [--spp N] [--cycles N]

Each scene is written here as a glTF, rendered by `onelight-bake reference` (linear cd/m^2) and
by Cycles through scripts/cycles-render.py, and the two EXRs are compared by the mean relative
error of 8x8-pixel blocks' luminance and the ratio of their levels (Cycles over the engine).
Cycles renders two seeds, so that its own noise is measured the same way (seed 1 against
seed 0). A benchmark, not a test: minutes on 2 cores.

How the units map. The glTF importer's 'COMPAT' lighting mode reads a light's intensity as is:
a sun of E lux becomes a sun of strength E (W/m^2), a point or spot light of I candela a lamp
of power 4 pi I W, which Cycles spreads as I W/sr. Cycles' radiance is then the engine's cd/m^2
with watts for lumens, and a world of strength L is a sky of L cd/m^2. The lights take the
engine's sizes (a 5 cm sphere, a sun 0.27 degrees in radius). A Lambert material is given
Cycles' Diffuse BSDF at roughness 0 (its Principled BSDF's diffuse is not Lambert).

The scenes:
  sky_floor   a 40 x 40 m floor (albedo 0.5) under a uniform sky of 1000 cd/m^2 and a 100 cd
              point light 2 m up: everything in closed form (rho / pi (pi L + I / d^2 cos)).
  roof_room   the room lit through a roof opening (tests/bake/bake_scenes.hpp): 4 x 3 x 2.5 m,
              Lambert walls 0.6, a 1 x 1 m opening, a block of 0.3, a 20 klx sun through the
              opening and nothing else: every pixel off the sunlit patch has bounced.
  lamp_room   the same room closed, lit only by a 0.6 x 0.6 m ceiling panel of 2000 cd/m^2
              (an emissive Lambert quad, one-sided): the emitters the bake samples as lights.
  spot_room   the same closed room lit by a 2000 cd spot (cone 0.3 to 0.6 rad) aimed at the
              floor: where the models differ, the cone's edge (glTF's falloff, smooth in the
              cosine, against Blender's blend), run by --scenes spot_room.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

from scenes import SCENES


def blender(render, *args):
    """Runs scripts/cycles-render.py in Blender; its Python errors end the run. Blender takes its
    Python from the first python3 on PATH: the system's first, whose NumPy it was built with
    (a Python of another install, run first, would lend its own, without NumPy)."""
    env = dict(os.environ, PATH="/usr/bin:/bin:" + os.environ.get("PATH", ""))
    result = subprocess.run(["blender", "-b", "--factory-startup", "--python-exit-code", "1",
                             "-P", render, "--", *args], env=env, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"cycles-check: blender {' '.join(args)} failed:\n{result.stderr[-2000:]}")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--bin", default=os.path.join(here, "..", "build", "bin"))
    p.add_argument("--work", default="")
    p.add_argument("--size", default="320x180")
    p.add_argument("--spp", type=int, default=1024, help="the engine reference's paths a pixel")
    p.add_argument("--cycles", type=int, default=1024, help="Cycles' samples a pixel")
    p.add_argument("--scenes", default="sky_floor,roof_room,lamp_room")
    args = p.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    work = args.work or tempfile.mkdtemp(prefix="onelight-cycles-")
    os.makedirs(work, exist_ok=True)
    bake = os.path.join(args.bin, "onelight-bake")
    render = os.path.join(here, "cycles-render.py")
    rows = []
    for name in args.scenes.split(","):
        gltf = os.path.join(work, name + ".gltf")
        sky = SCENES[name](gltf, width / height)
        ours = os.path.join(work, name + "-onelight.exr")
        subprocess.run([bake, "reference", gltf, "--camera", "view", "--spp", str(args.spp),
                        "--size", args.size, "-o", ours], check=True, stdout=subprocess.DEVNULL)
        cycles = []
        for seed in (0, 1):
            out = os.path.join(work, f"{name}-cycles{seed}.exr")
            blender(render, "render", gltf, "view", out, str(width), str(height),
                    str(args.cycles), str(sky), str(seed))
            cycles.append(out)
        stats = []
        for a, b in ((ours, cycles[0]), (cycles[0], cycles[1])):
            out = os.path.join(work, name + "-compare.json")
            blender(render, "compare", a, b, "8", out)
            stats.append(json.load(open(out)))
        rows.append((name, stats[0], stats[1]))
        print(f"cycles-check: {name}: Cycles against the engine's reference: mean relative "
              f"block error {stats[0]['mean_relative_error']:.4f}, level {stats[0]['level_ratio']:.4f}; "
              f"Cycles' own noise {stats[1]['mean_relative_error']:.4f} ({stats[0]['blocks']} blocks)",
              file=sys.stderr, flush=True)
    print("| scene | mean relative 8x8 block error, Cycles against the engine | level, Cycles "
          "over the engine | Cycles' own (seed 1 against 0) |")
    print("|---|---|---|---|")
    for name, a, n in rows:
        print(f"| {name} | {a['mean_relative_error']:.4f} | {a['level_ratio']:.4f} | "
              f"{n['mean_relative_error']:.4f} |")


if __name__ == "__main__":
    main()
