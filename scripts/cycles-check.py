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
import base64
import json
import math
import os
import struct
import subprocess
import sys
import tempfile


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def look_at_quaternion(eye, target):
    """The rotation (x, y, z, w) that turns a glTF camera (looking down -Z, +Y up) at target."""
    f = normalize([t - e for t, e in zip(target, eye)])
    r = normalize(cross(f, [0.0, 1.0, 0.0]))
    u = cross(r, f)
    m = [[r[0], u[0], -f[0]], [r[1], u[1], -f[1]], [r[2], u[2], -f[2]]]  # columns r, u, -f
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = 0.5 / math.sqrt(trace + 1.0)
        return [(m[2][1] - m[1][2]) * s, (m[0][2] - m[2][0]) * s, (m[1][0] - m[0][1]) * s,
                0.25 / s]
    i = max(range(3), key=lambda k: m[k][k])
    j, k = (i + 1) % 3, (i + 2) % 3
    s = 2.0 * math.sqrt(1.0 + m[i][i] - m[j][j] - m[k][k])
    q = [0.0, 0.0, 0.0, 0.0]
    q[i] = 0.25 * s
    q[j] = (m[j][i] + m[i][j]) / s
    q[k] = (m[k][i] + m[i][k]) / s
    q[3] = (m[k][j] - m[j][k]) / s
    return q


def direction_quaternion(d):
    """The rotation that turns a glTF light's -Z onto direction d (the way its light travels)."""
    d = normalize(d)
    eye = [0.0, 0.0, 0.0]
    if abs(d[1]) > 0.999:  # straight up or down: look_at's up vector degenerates
        half = math.pi / 4.0 if d[1] < 0 else -math.pi / 4.0
        return [math.sin(half), 0.0, 0.0, math.cos(half)]
    return look_at_quaternion(eye, d)


class Gltf:
    """A glTF 2.0 level: quads as meshes, Lambert materials, lights, cameras, a settings node."""

    def __init__(self):
        self.data = bytearray()
        self.doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": []}],
                    "nodes": [], "meshes": [], "materials": [], "accessors": [],
                    "bufferViews": [], "cameras": [], "extensionsUsed": [],
                    "extensions": {"KHR_lights_punctual": {"lights": []}}}

    def node(self, node):
        self.doc["nodes"].append(node)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def material(self, name, albedo, emission=0.0):
        """A Lambert material; with `emission`, a white emitter of that many cd/m^2."""
        m = {"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": [albedo, albedo, albedo, 1.0], "metallicFactor": 0.0,
            "roughnessFactor": 1.0}}
        if emission > 0.0:
            m["emissiveFactor"] = [1.0, 1.0, 1.0]
            m["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": emission}}
            if "KHR_materials_emissive_strength" not in self.doc["extensionsUsed"]:
                self.doc["extensionsUsed"].append("KHR_materials_emissive_strength")
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def view(self, payload, target):
        while len(self.data) % 4:
            self.data.append(0)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.data),
                                        "byteLength": len(payload), "target": target})
        self.data += payload
        return len(self.doc["bufferViews"]) - 1

    def quads(self, name, quads, material):
        """quads: (corners a b c d, counter-clockwise seen from the side the normal points to)."""
        positions, normals, indices = [], [], []
        for q in quads:
            n = normalize(cross([q[1][i] - q[0][i] for i in range(3)],
                                [q[2][i] - q[0][i] for i in range(3)]))
            base = len(positions)
            positions += q
            normals += [n] * 4
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
        p = self.view(b"".join(struct.pack("<3f", *v) for v in positions), 34962)
        n = self.view(b"".join(struct.pack("<3f", *v) for v in normals), 34962)
        i = self.view(struct.pack(f"<{len(indices)}I", *indices), 34963)
        lo = [min(v[k] for v in positions) for k in range(3)]
        hi = [max(v[k] for v in positions) for k in range(3)]
        accessors = self.doc["accessors"]
        accessors.append({"bufferView": p, "componentType": 5126, "count": len(positions),
                          "type": "VEC3", "min": lo, "max": hi})
        accessors.append({"bufferView": n, "componentType": 5126, "count": len(normals),
                          "type": "VEC3"})
        accessors.append({"bufferView": i, "componentType": 5125, "count": len(indices),
                          "type": "SCALAR"})
        k = len(accessors)
        self.doc["meshes"].append({"name": name, "primitives": [{
            "attributes": {"POSITION": k - 3, "NORMAL": k - 2}, "indices": k - 1,
            "material": material}]})
        self.node({"name": name, "mesh": len(self.doc["meshes"]) - 1})

    def light(self, name, light, translation=None, rotation=None):
        lights = self.doc["extensions"]["KHR_lights_punctual"]["lights"]
        lights.append(dict(light, name=name))
        node = {"name": name, "extensions": {"KHR_lights_punctual": {"light": len(lights) - 1}}}
        if translation:
            node["translation"] = translation
        if rotation:
            node["rotation"] = rotation
        self.node(node)
        if "KHR_lights_punctual" not in self.doc["extensionsUsed"]:
            self.doc["extensionsUsed"].append("KHR_lights_punctual")

    def camera(self, name, eye, target, aspect, yfov=1.0):
        self.doc["cameras"].append({"type": "perspective", "perspective": {
            "yfov": yfov, "aspectRatio": aspect, "znear": 0.05}})
        self.node({"name": name, "camera": len(self.doc["cameras"]) - 1, "translation": eye,
                   "rotation": look_at_quaternion(eye, target)})

    def write(self, path, sky):
        self.node({"name": "settings", "extras": {"onelight": {"sky": sky}}})
        doc = dict(self.doc)
        if not doc["extensions"]["KHR_lights_punctual"]["lights"]:
            del doc["extensions"]
        if not doc["extensionsUsed"]:
            del doc["extensionsUsed"]
        doc["buffers"] = [{"byteLength": len(self.data), "uri": "data:application/octet-stream;"
                           "base64," + base64.b64encode(bytes(self.data)).decode()}]
        with open(path, "w") as f:
            json.dump(doc, f)


def box_inside(x0, x1, y0, y1, z0, z1):
    """The six faces of a box, facing in (a room)."""
    c = lambda x, y, z: [x, y, z]
    return [
        [c(x0, y0, z0), c(x0, y0, z1), c(x1, y0, z1), c(x1, y0, z0)],  # floor, up
        [c(x0, y0, z0), c(x1, y0, z0), c(x1, y1, z0), c(x0, y1, z0)],  # z0 wall, +z
        [c(x0, y0, z1), c(x0, y1, z1), c(x1, y1, z1), c(x1, y0, z1)],  # z1 wall, -z
        [c(x0, y0, z0), c(x0, y1, z0), c(x0, y1, z1), c(x0, y0, z1)],  # x0 wall, +x
        [c(x1, y0, z0), c(x1, y0, z1), c(x1, y1, z1), c(x1, y1, z0)],  # x1 wall, -x
    ]


def box_outside(x0, x1, y0, y1, z0, z1):
    """The five visible faces of a block on the floor, facing out."""
    c = lambda x, y, z: [x, y, z]
    return [
        [c(x0, y1, z0), c(x0, y1, z1), c(x1, y1, z1), c(x1, y1, z0)],  # top, up
        [c(x0, y0, z0), c(x0, y1, z0), c(x1, y1, z0), c(x1, y0, z0)],  # -z
        [c(x0, y0, z1), c(x1, y0, z1), c(x1, y1, z1), c(x0, y1, z1)],  # +z
        [c(x0, y0, z0), c(x0, y0, z1), c(x0, y1, z1), c(x0, y1, z0)],  # -x
        [c(x1, y0, z0), c(x1, y1, z0), c(x1, y1, z1), c(x1, y0, z1)],  # +x
    ]


def sky_floor(path, aspect):
    g = Gltf()
    floor = g.material("floor", 0.5)
    g.quads("floor", [[[-20, 0, -20], [-20, 0, 20], [20, 0, 20], [20, 0, -20]]], floor)
    g.light("lamp", {"type": "point", "intensity": 100.0, "color": [1, 1, 1]}, [0.0, 2.0, 0.0])
    g.camera("view", [0.0, 3.0, 5.0], [0.0, 0.0, 0.0], aspect)
    g.write(path, 1000.0)
    return 1000.0


def roof_room(path, aspect):
    g = Gltf()
    walls = g.material("walls", 0.6)
    block = g.material("block", 0.3)
    x0, x1, y0, y1, z0, z1 = -2.0, 2.0, 0.0, 2.5, -1.5, 1.5
    ox0, ox1, oz0, oz1 = 0.3, 1.3, -0.5, 0.5
    faces = box_inside(x0, x1, y0, y1, z0, z1)
    c = lambda x, z: [x, y1, z]
    # The ceiling around the opening, facing down: four quads.
    for a, b in (((x0, z0), (ox0, z1)), ((ox1, z0), (x1, z1)), ((ox0, z0), (ox1, oz0)),
                 ((ox0, oz1), (ox1, z1))):
        faces.append([c(a[0], a[1]), c(b[0], a[1]), c(b[0], b[1]), c(a[0], b[1])])
    g.quads("room", faces, walls)
    g.quads("block", box_outside(-0.8, 0.0, 0.0, 0.8, -0.4, 0.4), block)
    g.light("sun", {"type": "directional", "intensity": 20000.0, "color": [1, 1, 1]}, None,
            direction_quaternion([-0.25, -1.0, 0.15]))
    g.camera("view", [-1.8, 1.7, 1.3], [0.6, 0.2, -0.3], aspect)
    g.write(path, 0.0)
    return 0.0


def blender(render, *args):
    """Runs scripts/cycles-render.py in Blender; its Python errors end the run. Blender takes its
    Python from the first python3 on PATH: the system's first, whose NumPy it was built with
    (a Python of another install, run first, would lend its own, without NumPy)."""
    env = dict(os.environ, PATH="/usr/bin:/bin:" + os.environ.get("PATH", ""))
    result = subprocess.run(["blender", "-b", "--factory-startup", "--python-exit-code", "1",
                             "-P", render, "--", *args], env=env, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"cycles-check: blender {' '.join(args)} failed:\n{result.stderr[-2000:]}")


def closed_room():
    """The roof-opening room's walls (0.6) and block (0.3), its ceiling whole."""
    g = Gltf()
    walls = g.material("walls", 0.6)
    block = g.material("block", 0.3)
    g.quads("room", box_inside(-2.0, 2.0, 0.0, 2.5, -1.5, 1.5) + [
        [[-2.0, 2.5, -1.5], [2.0, 2.5, -1.5], [2.0, 2.5, 1.5], [-2.0, 2.5, 1.5]]], walls)
    g.quads("block", box_outside(-0.8, 0.0, 0.0, 0.8, -0.4, 0.4), block)
    return g


def lamp_room(path, aspect):
    g = closed_room()
    panel = g.material("panel", 0.0, emission=2000.0)
    y = 2.499
    g.quads("panel", [[[0.2, y, -0.3], [0.8, y, -0.3], [0.8, y, 0.3], [0.2, y, 0.3]]], panel)
    g.camera("view", [-1.8, 1.7, 1.3], [0.6, 0.6, -0.3], aspect)
    g.write(path, 0.0)
    return 0.0


def spot_room(path, aspect):
    g = closed_room()
    g.light("spot", {"type": "spot", "intensity": 2000.0, "color": [1, 1, 1],
                     "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.6}},
            [0.8, 2.3, 0.0], direction_quaternion([-0.2, -1.0, 0.0]))
    g.camera("view", [-1.8, 1.7, 1.3], [0.6, 0.2, -0.3], aspect)
    g.write(path, 0.0)
    return 0.0


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
    scenes = {"sky_floor": sky_floor, "roof_room": roof_room, "lamp_room": lamp_room,
              "spot_room": spot_room}
    rows = []
    for name in args.scenes.split(","):
        gltf = os.path.join(work, name + ".gltf")
        sky = scenes[name](gltf, width / height)
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
