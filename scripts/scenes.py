"""The project's measured scenes, written as glTF levels: one home for the rooms and floors that
scripts/cycles-check.py (the reference against Blender's Cycles) and scripts/accuracy.py (the
frame against the reference) render. A module, not a command.

Every scene is a function scene(path, aspect) that writes PATH (a self-contained .gltf: buffers
and images as data URIs) with one camera named "view" and returns the uniform sky's radiance in
cd/m^2 (0: none). Units are the engine's: metres, lux for a sun, candela for a point or spot
light, cd/m^2 for emission and the sky.
"""
import base64
import json
import math
import os
import struct
import zlib


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


def png(width, height, pixels):
    """An 8-bit RGBA PNG of `pixels` (rows top first, each a list of (r, g, b, a) in 0..255)."""
    raw = b"".join(b"\0" + bytes(c for p in row for c in p) for row in pixels)

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    return (b"\x89PNG\r\n\x1a\n" +
            chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


class Gltf:
    """A glTF 2.0 level: quads as meshes, metal-rough materials (textures optional), lights,
    cameras and a settings node."""

    def __init__(self):
        self.data = bytearray()
        self.doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": []}],
                    "nodes": [], "meshes": [], "materials": [], "accessors": [],
                    "bufferViews": [], "cameras": [], "extensionsUsed": [],
                    "extensions": {"KHR_lights_punctual": {"lights": []}}}

    def node(self, node):
        self.doc["nodes"].append(node)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def uses(self, extension):
        if extension not in self.doc["extensionsUsed"]:
            self.doc["extensionsUsed"].append(extension)

    def texture(self, image_png):
        """A repeating, trilinear texture of a PNG; returns its index."""
        doc = self.doc
        doc.setdefault("images", []).append(
            {"uri": "data:image/png;base64," + base64.b64encode(image_png).decode()})
        doc.setdefault("samplers", [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497,
                                     "wrapT": 10497}])
        doc.setdefault("textures", []).append({"source": len(doc["images"]) - 1, "sampler": 0})
        return len(doc["textures"]) - 1

    def material(self, name, albedo, emission=0.0, metallic=0.0, roughness=1.0,
                 base_texture=None, normal_texture=None, alpha_cutoff=None):
        """albedo: a grey level or an RGB base colour. Metallic 0 and roughness 1 (the defaults)
        is the rough dielectric cycles-check calls Lambert; with `emission`, a white emitter of
        that many cd/m^2. alpha_cutoff: alpha-tested (MASK) by the base texture's alpha."""
        rgb = [albedo] * 3 if isinstance(albedo, (int, float)) else list(albedo)
        pbr = {"baseColorFactor": rgb + [1.0], "metallicFactor": metallic,
               "roughnessFactor": roughness}
        if base_texture is not None:
            pbr["baseColorTexture"] = {"index": base_texture}
        m = {"name": name, "pbrMetallicRoughness": pbr}
        if normal_texture is not None:
            m["normalTexture"] = {"index": normal_texture}
        if alpha_cutoff is not None:
            m["alphaMode"] = "MASK"
            m["alphaCutoff"] = alpha_cutoff
            m["doubleSided"] = True
        if emission > 0.0:
            m["emissiveFactor"] = [1.0, 1.0, 1.0]
            m["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": emission}}
            self.uses("KHR_materials_emissive_strength")
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def view(self, payload, target):
        while len(self.data) % 4:
            self.data.append(0)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.data),
                                        "byteLength": len(payload), "target": target})
        self.data += payload
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, values, kind):
        width = {"VEC2": 2, "VEC3": 3, "VEC4": 4}[kind]
        view = self.view(b"".join(struct.pack(f"<{width}f", *v) for v in values), 34962)
        a = {"bufferView": view, "componentType": 5126, "count": len(values), "type": kind}
        if kind == "VEC3":
            a["min"] = [min(v[k] for v in values) for k in range(3)]
            a["max"] = [max(v[k] for v in values) for k in range(3)]
        self.doc["accessors"].append(a)
        return len(self.doc["accessors"]) - 1

    def quads(self, name, quads, material, uv_scale=None):
        """quads: (corners a b c d, counter-clockwise seen from the side the normal points to).
        uv_scale: texture repeats a metre; then each quad gets TEXCOORD_0 along its edges a->b
        (u) and a->d (v) and a matching TANGENT."""
        positions, normals, uvs, tangents, indices = [], [], [], [], []
        for q in quads:
            e1 = [q[1][i] - q[0][i] for i in range(3)]
            e3 = [q[3][i] - q[0][i] for i in range(3)]
            n = normalize(cross(e1, [q[2][i] - q[0][i] for i in range(3)]))
            base = len(positions)
            positions += q
            normals += [n] * 4
            if uv_scale is not None:
                lu = math.sqrt(sum(c * c for c in e1)) * uv_scale
                lv = math.sqrt(sum(c * c for c in e3)) * uv_scale
                uvs += [[0.0, 0.0], [lu, 0.0], [lu, lv], [0.0, lv]]
                # u grows along e1, v along e3; glTF's bitangent is cross(n, t) * w.
                t = normalize(e1)
                b = cross(n, t)
                w = 1.0 if sum(b[i] * e3[i] for i in range(3)) > 0 else -1.0
                tangents += [t + [w]] * 4
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
        attributes = {"POSITION": self.accessor(positions, "VEC3"),
                      "NORMAL": self.accessor(normals, "VEC3")}
        if uv_scale is not None:
            attributes["TEXCOORD_0"] = self.accessor(uvs, "VEC2")
            attributes["TANGENT"] = self.accessor(tangents, "VEC4")
        i = self.view(struct.pack(f"<{len(indices)}I", *indices), 34963)
        self.doc["accessors"].append({"bufferView": i, "componentType": 5125,
                                      "count": len(indices), "type": "SCALAR"})
        self.doc["meshes"].append({"name": name, "primitives": [{
            "attributes": attributes, "indices": len(self.doc["accessors"]) - 1,
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
        self.uses("KHR_lights_punctual")

    def camera(self, name, eye, target, aspect, yfov=1.0):
        self.doc["cameras"].append({"type": "perspective", "perspective": {
            "yfov": yfov, "aspectRatio": aspect, "znear": 0.05}})
        self.node({"name": name, "camera": len(self.doc["cameras"]) - 1, "translation": eye,
                   "rotation": look_at_quaternion(eye, target)})

    def write(self, path, sky, settings=None):
        self.node({"name": "settings", "extras": {"onelight": dict(settings or {}, sky=sky)}})
        doc = dict(self.doc)
        if not doc["extensions"]["KHR_lights_punctual"]["lights"]:
            del doc["extensions"]
        if not doc["extensionsUsed"]:
            del doc["extensionsUsed"]
        doc["buffers"] = [{"byteLength": len(self.data), "uri": "data:application/octet-stream;"
                           "base64," + base64.b64encode(bytes(self.data)).decode()}]
        with open(path + ".tmp", "w") as f:
            json.dump(doc, f)
        os.replace(path + ".tmp", path)


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


def sky_floor_glossy(path, aspect):
    """A glossy floor (dielectric 0.2, roughness 0.2) 40 m across under a uniform 1000 cd/m^2
    sky, with one authored probe 1.5 m above it: the probes' normalisation in the open (an
    up-facing floor sees the sky, the probe's mean over normals a fifth of it below)."""
    g = Gltf()
    floor = g.material("floor", 0.2, roughness=0.2)
    g.quads("floor", [[[-20, 0, -20], [-20, 0, 20], [20, 0, 20], [20, 0, -20]]], floor)
    g.node({"name": "probe", "translation": [0.0, 1.5, 0.0],
            "extras": {"onelight": {"probe": True}}})
    g.camera("view", [0.0, 1.7, 4.0], [0.0, 0.0, -4.0], aspect)
    g.write(path, 1000.0)
    return 1000.0


# The rooms: 4 x 3 x 2.5 m (tests/bake/bake_scenes.hpp's roof-opening room), a block of
# 0.8 x 0.8 x 0.8 m on the floor, the camera in a corner looking across.
ROOM = (-2.0, 2.0, 0.0, 2.5, -1.5, 1.5)
BLOCK = (-0.8, 0.0, 0.0, 0.8, -0.4, 0.4)
CORNER = [-1.8, 1.7, 1.3]


def open_ceiling():
    """The ceiling around a 1 x 1 m roof opening, facing down: four quads."""
    x0, x1, _, y1, z0, z1 = ROOM
    ox0, ox1, oz0, oz1 = 0.3, 1.3, -0.5, 0.5
    c = lambda x, z: [x, y1, z]
    return [[c(a[0], a[1]), c(b[0], a[1]), c(b[0], b[1]), c(a[0], b[1])]
            for a, b in (((x0, z0), (ox0, z1)), ((ox1, z0), (x1, z1)), ((ox0, z0), (ox1, oz0)),
                         ((ox0, oz1), (ox1, z1)))]


def whole_ceiling():
    x0, x1, _, y1, z0, z1 = ROOM
    return [[[x0, y1, z0], [x1, y1, z0], [x1, y1, z1], [x0, y1, z1]]]


def ceiling_panel(g, emission=2000.0):
    """A 0.6 x 0.6 m emissive quad just under the whole ceiling, facing down."""
    panel = g.material("panel", 0.0, emission=emission)
    y = ROOM[3] - 0.001
    g.quads("panel", [[[0.2, y, -0.3], [0.8, y, -0.3], [0.8, y, 0.3], [0.2, y, 0.3]]], panel)


def roof_sun(g):
    """A 20 klx sun through the roof opening onto the floor beside the block."""
    g.light("sun", {"type": "directional", "intensity": 20000.0, "color": [1, 1, 1]}, None,
            direction_quaternion([-0.25, -1.0, 0.15]))


def roof_room(path, aspect):
    g = Gltf()
    walls = g.material("walls", 0.6)
    block = g.material("block", 0.3)
    g.quads("room", box_inside(*ROOM) + open_ceiling(), walls)
    g.quads("block", box_outside(*BLOCK), block)
    roof_sun(g)
    g.camera("view", CORNER, [0.6, 0.2, -0.3], aspect)
    g.write(path, 0.0)
    return 0.0


def closed_room():
    """The roof-opening room's walls (0.6) and block (0.3), its ceiling whole."""
    g = Gltf()
    walls = g.material("walls", 0.6)
    block = g.material("block", 0.3)
    g.quads("room", box_inside(*ROOM) + whole_ceiling(), walls)
    g.quads("block", box_outside(*BLOCK), block)
    return g


def lamp_room(path, aspect):
    g = closed_room()
    ceiling_panel(g)
    g.camera("view", CORNER, [0.6, 0.6, -0.3], aspect)
    g.write(path, 0.0)
    return 0.0


def spot_room(path, aspect):
    g = closed_room()
    g.light("spot", {"type": "spot", "intensity": 2000.0, "color": [1, 1, 1],
                     "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.6}},
            [0.8, 2.3, 0.0], direction_quaternion([-0.2, -1.0, 0.0]))
    g.camera("view", CORNER, [0.6, 0.2, -0.3], aspect)
    g.write(path, 0.0)
    return 0.0


def range_room(path, aspect):
    """The closed room lit by a 300 cd lamp whose range, 3 m, ends its light inside the room
    (KHR_lights_punctual's range window, which the engine applies and Blender's importer
    drops): the far walls lit by bounces only."""
    g = closed_room()
    g.light("lamp", {"type": "point", "intensity": 300.0, "color": [1, 1, 1], "range": 3.0},
            [1.2, 1.8, 0.5])
    g.camera("view", CORNER, [0.6, 0.6, -0.3], aspect)
    g.write(path, 0.0)
    return 0.0


def image(size, colour):
    """A size x size RGBA PNG, colour(x, y) -> (r, g, b, a) in 0..255 for each pixel."""
    return png(size, size, [[colour(x, y) for x in range(size)] for y in range(size)])


def room_with_floor(g, walls, floor, block, ceiling):
    """The room with its own floor material, the block on it, and a ceiling (open or whole)."""
    faces = box_inside(*ROOM)
    g.quads("floor", faces[:1], floor)
    g.quads("room", faces[1:] + ceiling, walls)
    g.quads("block", box_outside(*BLOCK), block)


def roof_room_glossy(path, aspect):
    """The roof-opening room with a glossy dielectric floor (roughness 0.25) and a gold block
    (metal, roughness 0.3): a sunlit patch, and bounced light seen in a mirror-like floor."""
    g = Gltf()
    walls = g.material("walls", 0.6)
    floor = g.material("floor", 0.6, roughness=0.25)
    gold = g.material("gold", [1.0, 0.766, 0.336], metallic=1.0, roughness=0.3)
    room_with_floor(g, walls, floor, gold, open_ceiling())
    roof_sun(g)
    g.camera("view", CORNER, [0.6, 0.2, -0.3], aspect)
    g.write(path, 0.0)
    return 0.0


def glossy_room(path, aspect):
    """The closed room lit by the 2000 cd/m^2 ceiling panel and a 150 cd lamp: a near-mirror
    floor (dielectric, roughness 0.1), semi-glossy walls (0.5) and a copper block (metal, 0.45)."""
    g = Gltf()
    walls = g.material("walls", 0.6, roughness=0.5)
    floor = g.material("floor", 0.3, roughness=0.1)
    copper = g.material("copper", [0.955, 0.638, 0.538], metallic=1.0, roughness=0.45)
    room_with_floor(g, walls, floor, copper, whole_ceiling())
    ceiling_panel(g)
    g.light("lamp", {"type": "point", "intensity": 150.0, "color": [1.0, 0.9, 0.8]},
            [-1.2, 1.8, -0.9])
    g.camera("view", CORNER, [0.6, 0.3, -0.3], aspect)
    g.write(path, 0.0)
    return 0.0


def textured_room(path, aspect):
    """The closed room with textures, lit by the ceiling panel (2000 cd/m^2): a checker floor
    (0.25 m squares), a striped back wall, and a cut-out grate (alpha-tested, two-sided)
    standing between the camera and the block."""
    g = Gltf()
    checker = g.texture(image(64, lambda x, y: (220, 220, 220, 255) if (x // 32 + y // 32) % 2
                              else (60, 60, 60, 255)))
    stripes = g.texture(image(64, lambda x, y: (200, 60, 40, 255) if (x // 16) % 2
                              else (230, 230, 210, 255)))
    grate = g.texture(image(64, lambda x, y: (150, 150, 160, 255) if x % 32 < 8 or y % 32 < 8
                            else (0, 0, 0, 0)))
    walls = g.material("walls", 0.6)
    floor = g.material("floor", 1.0, base_texture=checker)
    back = g.material("back", 1.0, base_texture=stripes)
    bars = g.material("grate", 1.0, base_texture=grate, alpha_cutoff=0.5)
    block = g.material("block", 0.3)
    faces = box_inside(*ROOM)
    g.quads("floor", faces[:1], floor, uv_scale=2.0)
    g.quads("back", faces[1:2], back, uv_scale=2.0)
    g.quads("room", faces[2:] + whole_ceiling(), walls)
    g.quads("grate", [[[-1.2, 0.0, 0.6], [0.2, 0.0, 0.6], [0.2, 1.4, 0.6], [-1.2, 1.4, 0.6]]],
            bars, uv_scale=4.0)
    g.quads("block", box_outside(*BLOCK), block)
    ceiling_panel(g)
    g.camera("view", [-1.8, 1.5, 1.4], [0.4, 0.5, -0.6], aspect)
    g.write(path, 0.0)
    return 0.0


def bump_normal(x, y, size):
    """An egg-crate height field h = A sin(2 pi u) sin(2 pi v) over one tile, as a tangent-space
    normal (slopes up to 0.6) in 0..255."""
    u, v = (x + 0.5) / size, (y + 0.5) / size
    a = 0.6 / (2.0 * math.pi)
    dhdu = a * 2.0 * math.pi * math.cos(2.0 * math.pi * u) * math.sin(2.0 * math.pi * v)
    dhdv = a * 2.0 * math.pi * math.sin(2.0 * math.pi * u) * math.cos(2.0 * math.pi * v)
    n = normalize([-dhdu, dhdv, 1.0])  # image rows run down: v up is -y
    return tuple(int(round((c * 0.5 + 0.5) * 255.0)) for c in n) + (255,)


def glossy_floor(path, aspect, bumps=True, sun=True, sky=2000.0):
    """A glossy floor (dielectric 0.4, roughness 0.15) 400 m across, to the horizon, under a
    sky and a 50 klx sun 15 degrees up ahead; with `bumps`, normal-mapped with 0.25 m bumps:
    the sun's glint runs from under the camera to the horizon, where the bumps are far below a
    pixel."""
    g = Gltf()
    normals = g.texture(image(32, lambda x, y: bump_normal(x, y, 32))) if bumps else None
    floor = g.material("floor", 0.4, roughness=0.15, normal_texture=normals)
    h = 200.0
    g.quads("floor", [[[-h, 0, -h], [-h, 0, h], [h, 0, h], [h, 0, -h]]], floor, uv_scale=4.0)
    if sun:
        g.light("sun", {"type": "directional", "intensity": 50000.0, "color": [1, 1, 1]}, None,
                direction_quaternion([0.0, -math.sin(math.radians(15)),
                                      math.cos(math.radians(15))]))
    g.camera("view", [0.0, 1.7, 0.0], [0.0, 1.0, -10.0], aspect)
    g.write(path, sky)
    return sky


def normal_floor(path, aspect):
    return glossy_floor(path, aspect)


def normal_floor_sky(path, aspect):
    """The normal-mapped floor under its sky alone."""
    return glossy_floor(path, aspect, sun=False)


def normal_floor_sun(path, aspect):
    """The normal-mapped floor under its sun alone."""
    return glossy_floor(path, aspect, sky=0.0)


def flat_floor(path, aspect):
    """The same floor without its normal map: the control."""
    return glossy_floor(path, aspect, bumps=False)


def shadow_edge(path, aspect):
    """A sun's straight shadow edge on a floor, diagonal to the lightmap's texels: a wall 12 m
    long, 3 m high and 0.2 m thick, turned 30 degrees about the vertical, on a 40 m floor (Lambert
    0.5) under a 10 klx sun 45 degrees up, square to the wall, and a 300 cd/m^2 sky; the camera
    8 m straight above the shadow's far edge (3.1 m from the wall's centre line). accuracy.py
    draws it twice: with the runtime shadow map (shadow_edge) and with only the baked mask
    (shadow_edge_baked, --shadow-distance 1)."""
    g = Gltf()
    floor = g.material("floor", 0.5)
    wall = g.material("wall", 0.5)
    h = 20.0
    g.quads("floor", [[[-h, 0, -h], [-h, 0, h], [h, 0, h], [h, 0, -h]]], floor)
    angle = math.radians(30.0)
    along, across = [math.cos(angle), 0.0, math.sin(angle)], [-math.sin(angle), 0.0, math.cos(angle)]
    turn = lambda p: [p[0] * along[0] + p[2] * across[0], p[1], p[0] * along[2] + p[2] * across[2]]
    g.quads("wall", [[turn(p) for p in q] for q in box_outside(-6.0, 6.0, 0.0, 3.0, -0.1, 0.1)],
            wall)
    g.light("sun", {"type": "directional", "intensity": 10000.0, "color": [1, 1, 1]}, None,
            direction_quaternion([across[0], -1.0, across[2]]))
    edge = [3.1 * across[0], 0.0, 3.1 * across[2]]
    # Straight down, its image's x along the wall (a target a centimetre off, so that look_at
    # has a side).
    g.camera("view", [edge[0], 8.0, edge[2]],
             [edge[0] + 0.01 * across[0], 0.0, edge[2] + 0.01 * across[2]], aspect, yfov=0.6)
    g.write(path, 300.0)
    return 300.0


shadow_edge_baked = shadow_edge
# Drawn with the probes normalised per normal (--probes-per-normal).
sky_floor_glossy_per_normal = sky_floor_glossy
glossy_room_per_normal = glossy_room
roof_room_glossy_per_normal = roof_room_glossy


# The scenes by name, for the scripts' --scenes.
SCENES = {"sky_floor": sky_floor, "sky_floor_glossy": sky_floor_glossy, "roof_room": roof_room, "lamp_room": lamp_room,
          "spot_room": spot_room, "range_room": range_room, "roof_room_glossy": roof_room_glossy,
          "glossy_room": glossy_room, "textured_room": textured_room,
          "normal_floor": normal_floor, "normal_floor_sky": normal_floor_sky,
          "normal_floor_sun": normal_floor_sun, "flat_floor": flat_floor,
          "shadow_edge": shadow_edge, "shadow_edge_baked": shadow_edge_baked,
          "sky_floor_glossy_per_normal": sky_floor_glossy_per_normal,
          "glossy_room_per_normal": glossy_room_per_normal,
          "roof_room_glossy_per_normal": roof_room_glossy_per_normal}
