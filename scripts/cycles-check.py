#!/usr/bin/env python3
"""The engine's reference path tracer against an outside one, Blender's Cycles (Debian `blender`),
on scenes where the two models agree: Lambert surfaces (textured, alpha-tested), punctual
lights, a uniform sky, and the engine's glossy layer (below: where Cycles' differs, and by how
much).

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

How the materials map. A Lambert material's base colour texture and its alpha test (MASK) are
wired to a Diffuse BSDF and a Transparent BSDF where the alpha is under the cutoff. An untextured
glossy material (roughness under 1, or metallic) is the engine's model
(shaders/lighting.glsl, surfaceReflectance): a Lambert layer of albedo base (1 - metallic),
weighted by the engine's 1 - (f0 A + B) at the view's NoV (its split-sum table, read by a node
from Layer Weight's Facing), beside a GGX layer of alpha roughness^2 and f0 mix(0.04, base,
metallic): Cycles' Principled BSDF at distribution GGX (single scattering), its base black (its
diffuse off) or, for a metal, its base as f0. Cycles' GGX layer is not quite the engine's:
  - its Fresnel is a dielectric's (the index whose f0 it is), normalised to f0 at normal
    incidence, where the engine's is Schlick's: more at mid angles (at v.h 0.7, 0.051 against
    0.042 for f0 0.04), less towards grazing;
  - its Smith masking is separable, G1(v) G1(l), where the engine's is height-correlated:
    less, most at grazing and on rough lobes.
On sky_floor_glossy both are computed in closed form (cycles-render.py closed-form: the layer's
albedo by quadrature, for each model), so that each tracer is checked against its own model and
the models' difference is measured apart from the tracers'.

The scenes:
  sky_floor   a 40 x 40 m floor (albedo 0.5) under a uniform sky of 1000 cd/m^2 and a 100 cd
              point light 2 m up: everything in closed form (rho / pi (pi L + I / d^2 cos)).
  roof_room   the room lit through a roof opening (tests/bake/bake_scenes.hpp): 4 x 3 x 2.5 m,
              Lambert walls 0.6, a 1 x 1 m opening, a block of 0.3, a 20 klx sun through the
              opening and nothing else: every pixel off the sunlit patch has bounced.
  lamp_room   the same room closed, lit only by a 0.6 x 0.6 m ceiling panel of 2000 cd/m^2
              (an emissive Lambert quad, one-sided): the emitters the bake samples as lights.
  sky_floor_glossy  a glossy floor (0.2, roughness 0.2) under a uniform 1000 cd/m^2 sky alone:
              in closed form for each model (above).
  roof_room_glossy  the roof room with a glossy floor (0.6, roughness 0.25) and a gold block
              (metal, 0.3).
  glossy_room the closed room under the panel and a 150 cd lamp: a near-mirror floor (0.3,
              roughness 0.1), semi-glossy walls (0.6, 0.5), a copper block (metal, 0.45).
  textured_room  the closed room under the panel, textured: a checker floor, a striped wall and
              an alpha-tested grate (Lambert, sRGB base colour textures, trilinear, repeating):
              Cycles reads a texture at the ray's hit with linear filtering and no mips, the
              engine at its ray cone's level of detail.
  range_room  the same closed room lit by a 300 cd lamp of range 3 m (KHR_lights_punctual's
              range window, which Blender's importer drops and cycles-render.py puts back with a
              Light Falloff node, light_shape).
  q3:MAP:CAMERA  an installed Quake 3 map from one of its cameras (spawn0, ...): the engine
              traces the map as it imports it, Cycles the glTF `onelight-bake export` writes of
              it (static triangles, textures, lights, sky; items and movers left out, as the
              engine's static reference leaves them out), e.g. --scenes q3:kaos:spawn0.
  spot_room   the same closed room lit by a 2000 cd spot (cone 0.3 to 0.6 rad) aimed at the
              floor: glTF's cone, which cycles-render.py draws itself (light_shape), where
              Blender's own spot ramps by a smoothstep over a wider blend and keeps a cosine
              inside the cone.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

from scenes import SCENES

# Scenes cycles-render.py's closed-form computes: what each tracer should give, with its own
# GGX layer, where the two layers differ.
CLOSED_FORMS = {"sky_floor_glossy"}


def blender(render, *args):
    """Runs scripts/cycles-render.py in Blender; its Python errors end the run. Blender takes its
    Python from the first python3 on PATH: the system's first, whose NumPy it was built with
    (a Python of another install, run first, would lend its own, without NumPy)."""
    env = dict(os.environ, PATH="/usr/bin:/bin:" + os.environ.get("PATH", ""))
    result = subprocess.run(["blender", "-b", "--factory-startup", "--python-exit-code", "1",
                             "-P", render, "--", *args], env=env, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"cycles-check: blender {' '.join(args)} failed:\n{result.stderr[-2000:]}")


def exported_level(bake, name, work):
    """q3:MAP:CAMERA: the installed map MAP, which the engine traces as it imports it, and Cycles
    as `onelight-bake export` writes it back (its static triangles, textures, lights with their
    ranges, sky). Returns the level, the camera, the glTF and the sky as R,G,B."""
    _, level, camera = name.split(":")
    gltf = os.path.join(work, level + ".gltf")
    subprocess.run([bake, "export", level, "-o", gltf], check=True, stdout=subprocess.DEVNULL)
    with open(gltf) as f:
        nodes = json.load(f)["nodes"]
    sky = [0.0, 0.0, 0.0]
    for node in nodes:
        value = node.get("extras", {}).get("onelight", {}).get("sky")
        if isinstance(value, list):
            sky = value
        elif isinstance(value, (int, float)):
            sky = [value] * 3
    return level, camera, gltf, ",".join(f"{v:.9g}" for v in sky)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--bin", default=os.path.join(here, "..", "build", "bin"))
    p.add_argument("--work", default="")
    p.add_argument("--size", default="320x180")
    p.add_argument("--spp", type=int, default=1024, help="the engine reference's paths a pixel")
    p.add_argument("--cycles", type=int, default=1024, help="Cycles' samples a pixel")
    p.add_argument("--scenes", default="sky_floor,roof_room,lamp_room,sky_floor_glossy,"
                   "roof_room_glossy,glossy_room,textured_room,spot_room,range_room")
    args = p.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    work = args.work or tempfile.mkdtemp(prefix="onelight-cycles-")
    os.makedirs(work, exist_ok=True)
    bake = os.path.join(args.bin, "onelight-bake")
    render = os.path.join(here, "cycles-render.py")
    rows, closed_rows = [], []
    for name in args.scenes.split(","):
        ours = os.path.join(work, name.replace(":", "-") + "-onelight.exr")
        if name.startswith("q3:"):
            level, camera, gltf, sky = exported_level(bake, name, work)
        else:
            level, camera = os.path.join(work, name + ".gltf"), "view"
            gltf = level
            sky = SCENES[name](gltf, width / height)
        subprocess.run([bake, "reference", level, "--camera", camera, "--spp", str(args.spp),
                        "--size", args.size, "-o", ours], check=True, stdout=subprocess.DEVNULL)
        cycles = []
        for seed in (0, 1):
            out = os.path.join(work, f"{name.replace(':', '-')}-cycles{seed}.exr")
            blender(render, "render", gltf, camera, out, str(width), str(height),
                    str(args.cycles), sky if isinstance(sky, str) else str(sky), str(seed))
            cycles.append(out)
        stats = []
        for a, b in ((ours, cycles[0]), (cycles[0], cycles[1])):
            out = os.path.join(work, name.replace(":", "-") + "-compare.json")
            blender(render, "compare", a, b, "8", out)
            stats.append(json.load(open(out)))
        rows.append((name, stats[0], stats[1]))
        if name in CLOSED_FORMS:
            engine_model = os.path.join(work, name + "-closed-engine.exr")
            cycles_model = os.path.join(work, name + "-closed-cycles.exr")
            blender(render, "closed-form", gltf, "view", str(width), str(height), str(sky),
                    engine_model, cycles_model)
            closed = []
            for a, b in ((engine_model, ours), (cycles_model, cycles[0]),
                         (engine_model, cycles_model)):
                out = os.path.join(work, name + "-compare.json")
                blender(render, "compare", a, b, "8", out)
                closed.append(json.load(open(out)))
            closed_rows.append((name, closed))
            print(f"cycles-check: {name}: the engine's reference against its model's closed form "
                  f"{closed[0]['mean_relative_error']:.4f}, Cycles against its own "
                  f"{closed[1]['mean_relative_error']:.4f}, the two closed forms "
                  f"{closed[2]['mean_relative_error']:.4f}", file=sys.stderr, flush=True)
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
    if closed_rows:
        print()
        print("| scene | the engine's reference against its model in closed form | Cycles against "
              "its model in closed form | Cycles' model against the engine's (level) |")
        print("|---|---|---|---|")
        for name, (e, c, m) in closed_rows:
            print(f"| {name} | {e['mean_relative_error']:.4f} | {c['mean_relative_error']:.4f} | "
                  f"{m['mean_relative_error']:.4f} ({m['level_ratio']:.4f}) |")


if __name__ == "__main__":
    main()
