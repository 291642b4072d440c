"""Run inside Blender (blender -b --factory-startup -P scripts/cycles-render.py -- ...), for
scripts/cycles-check.py, which says why and how the units map.

  render GLTF CAMERA OUT.exr WIDTH HEIGHT SAMPLES SKY_CD_PER_M2 SEED
      (SKY: one radiance, or R,G,B)
      imports the glTF with its lights in glTF's own units ('COMPAT': lux and candela read as
      W/m^2 and W/sr, so that Cycles' radiance is the engine's cd/m^2), gives every Lambert
      material (roughness 1, metallic 0: the engine's MATERIAL_LAMBERT) a Diffuse BSDF of its
      base colour or texture, cut out by its alpha under a MASK cutoff, every untextured glossy
      one the engine's layers (layered), the lights the engine's sizes, ranges and spot cones (light_shape),
      a uniform world of SKY, materials with extras.onelight.casts_shadows false no shadow
      (onelight-bake export's Quake 3 translucent surfaces), and renders the camera's view
      with Cycles: no clamping, no denoising, a box pixel filter, 64 bounces.
  closed-form GLTF CAMERA WIDTH HEIGHT SKY ENGINE.exr CYCLES.exr
      a glossy floor under a uniform sky alone in closed form, for the engine's GGX layer and for
      Cycles' (closed_form): what each tracer should give where the two layers differ.
  compare A.exr B.exr BLOCK OUT.json
      the mean relative error of B against A over BLOCK x BLOCK pixel blocks' luminance, and
      the ratio of their mean levels, as JSON.
"""
import json
import math
import os
import re
import sys

import bpy
import numpy as np

# Debian 12's Blender 3.4 glTF importer still names np.bool, which its NumPy 1.24 removed.
if not hasattr(np, "bool") or np.bool is not bool:
    try:
        np.bool = bool
    except AttributeError:
        pass

POINT_RADIUS = 0.05  # metres: bake/lighting/lights.hpp, LightSizes::pointRadius
SUN_ANGULAR_RADIUS = 0.00465  # radians: LightSizes::sunAngularRadius


ENV_BRDF_TABLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "shaders",
                              "env_brdf_table.inc")
ENV_BRDF_TABLE_SIZE = 32  # shaders/lighting.glsl
MIN_NOV = 1e-4  # shaders/brdf.glsl
DIELECTRIC_F0 = 0.04  # glTF 2.0, Appendix B (world/compiled_level.hpp's default)
WEIGHT_TABLE_SIZE = 1024  # the diffuse weight's lookup, texels over sqrt(NoV) in [0, 1]


def principled(material):
    """The importer's Principled BSDF of a material without a metallic-roughness texture (the
    scenes' materials), or None."""
    node = material.node_tree.nodes.get("Principled BSDF") if material.node_tree else None
    if node is None or node.inputs["Roughness"].is_linked or node.inputs["Metallic"].is_linked:
        return None
    return node


def linked_or_value(tree, socket, target):
    """Gives `target` what feeds `socket`: its link's source, else its value. Blender 3.4's
    importer links an emissive texture times its factor from the Mix node's float result, which
    is not the one its colour mode computes: the node's enabled output is taken."""
    if socket.is_linked:
        source = socket.links[0].from_socket
        if not source.enabled:
            source = next(o for o in socket.links[0].from_node.outputs if o.enabled)
        tree.links.new(source, target)
    else:
        target.default_value = socket.default_value


def alpha_tested(material, node, surface):
    """`surface` cut out where the base colour's alpha is under the material's cutoff (glTF's
    MASK, which the importer marks blend mode CLIP): the engine's alpha test, a Transparent BSDF
    there; or, for BLEND, mixed with a Transparent BSDF by its alpha. The importer links the
    alpha to Principled's Alpha, which Cycles would blend."""
    alpha = node.inputs["Alpha"]
    tree = material.node_tree
    if material.blend_method == "BLEND" and (alpha.is_linked or alpha.default_value < 1.0):
        # glTF's BLEND: the engine's reference passes a path through with probability 1 - alpha
        # (bake/embree/bake_scene.cpp, alphaFilter), a mix of Transparent and the surface here.
        kept = None
    elif alpha.is_linked and material.blend_method == "CLIP":
        kept = tree.nodes.new("ShaderNodeMath")
        kept.operation = "GREATER_THAN"
        tree.links.new(alpha.links[0].from_socket, kept.inputs[0])
        kept.inputs[1].default_value = material.alpha_threshold
    else:
        return surface
    transparent = tree.nodes.new("ShaderNodeBsdfTransparent")
    mix = tree.nodes.new("ShaderNodeMixShader")
    if kept is not None:
        tree.links.new(kept.outputs["Value"], mix.inputs["Fac"])
    else:
        linked_or_value(tree, alpha, mix.inputs["Fac"])
    tree.links.new(transparent.outputs["BSDF"], mix.inputs[1])
    tree.links.new(surface, mix.inputs[2])
    return mix.outputs["Shader"]


def is_lambert(node):
    """Metallic 0 and roughness 1: the engine's MATERIAL_LAMBERT, no specular layer."""
    return node.inputs["Roughness"].default_value >= 1.0 and node.inputs["Metallic"].default_value <= 0


def gloss_from_roughness(roughness):
    """shaders/material.glsl, gloss_fromRoughness."""
    r4 = max(roughness ** 4, 1e-12)
    return min(max(math.log2(max(2.0 / r4 - 1.0, 1.0)) / 18.0, 0.0), 1.0)


def env_brdf(sqrt_nov, gloss):
    """The split-sum table's (scale, bias) at sqrt(NoV) and gloss: shaders/env_brdf_table.hpp's
    bilinear, clamp-to-edge lookup of the numbers the runtime uploads."""
    text = open(ENV_BRDF_TABLE).read()
    values = [float(v) for v in re.findall(r"([-+0-9.eE]+)f", text)]
    n = ENV_BRDF_TABLE_SIZE
    table = np.array(values, dtype=np.float64).reshape(n, n, 2)  # [gloss row][sqrt(NoV)][2]
    fx = np.clip(sqrt_nov * (n - 1), 0.0, n - 1)
    fy = min(max(gloss * (n - 1), 0.0), n - 1)
    x0 = np.minimum(fx.astype(int), n - 2)
    y0 = min(int(fy), n - 2)
    tx, ty = (fx - x0)[:, None], fy - y0
    top = table[y0, x0] * (1 - tx) + table[y0, x0 + 1] * tx
    bottom = table[y0 + 1, x0] * (1 - tx) + table[y0 + 1, x0 + 1] * tx
    return top * (1 - ty) + bottom * ty


def diffuse_weight_image(name, f0, gloss):
    """The engine's diffuse weight, 1 - (f0 A + B) of the split-sum table at the view's NoV
    (diffuseEnergyWeight, shaders/lighting.glsl), per channel, as a one-row float image over
    sqrt(NoV): texel i at sqrt(NoV) = (i + 0.5) / size, read with linear interpolation."""
    s = (np.arange(WEIGHT_TABLE_SIZE) + 0.5) / WEIGHT_TABLE_SIZE
    nov = np.maximum(s * s, MIN_NOV)
    ab = env_brdf(np.sqrt(nov), gloss)
    weight = np.clip(1.0 - (np.outer(ab[:, 0], f0) + ab[:, 1:2]), 0.0, 1.0)
    image = bpy.data.images.new(name, WEIGHT_TABLE_SIZE, 1, float_buffer=True)
    image.colorspace_settings.name = "Non-Color"
    rgba = np.ones((WEIGHT_TABLE_SIZE, 4))
    rgba[:, :3] = weight
    image.pixels[:] = rgba.ravel().tolist()
    return image


def layered(material, node):
    """The engine's model of a metallic-roughness material (shaders/lighting.glsl,
    surfaceReflectance): a Lambert layer of albedo base (1 - metallic), weighted by
    1 - (f0 A + B) of the view's NoV, under a single-scattering GGX layer of alpha roughness^2
    and f0 mix(0.04, base, metallic). The GGX layer is Cycles' Principled BSDF with a black base
    (its diffuse off) or, for a metal, the base as its f0; where it differs from the engine's
    (its Fresnel normalised from a dielectric's rather than Schlick's, its Smith masking
    separable rather than height-correlated) is said in cycles-check.py."""
    tree = material.node_tree
    base = np.array(node.inputs["Base Color"].default_value[:3], dtype=np.float64)
    metallic = node.inputs["Metallic"].default_value
    roughness = node.inputs["Roughness"].default_value
    f0 = DIELECTRIC_F0 * (1.0 - metallic) + base * metallic
    albedo = base * (1.0 - metallic)
    specular = tree.nodes.new("ShaderNodeBsdfPrincipled")
    specular.distribution = "GGX"
    specular.inputs["Roughness"].default_value = roughness
    specular.inputs["Metallic"].default_value = 1.0 if metallic >= 1.0 else 0.0
    if metallic >= 1.0:
        specular.inputs["Base Color"].default_value = list(base) + [1.0]
    else:
        specular.inputs["Base Color"].default_value = (0.0, 0.0, 0.0, 1.0)
        specular.inputs["Specular"].default_value = DIELECTRIC_F0 / 0.08  # f0 = 0.08 specular
    specular.inputs["Specular Tint"].default_value = 0.0
    specular.inputs["Sheen"].default_value = 0.0
    specular.inputs["Clearcoat"].default_value = 0.0
    if metallic >= 1.0:
        return specular.outputs["BSDF"]
    # sqrt(NoV) from Layer Weight's Facing, 1 - |N.I| at blend 0.5, into the weight's image.
    facing = tree.nodes.new("ShaderNodeLayerWeight")
    facing.inputs["Blend"].default_value = 0.5
    nov = tree.nodes.new("ShaderNodeMath")
    nov.operation = "SUBTRACT"
    nov.inputs[0].default_value = 1.0
    tree.links.new(facing.outputs["Facing"], nov.inputs[1])
    root = tree.nodes.new("ShaderNodeMath")
    root.operation = "SQRT"
    tree.links.new(nov.outputs["Value"], root.inputs[0])
    coordinate = tree.nodes.new("ShaderNodeCombineXYZ")
    coordinate.inputs["Y"].default_value = 0.5
    tree.links.new(root.outputs["Value"], coordinate.inputs["X"])
    lookup = tree.nodes.new("ShaderNodeTexImage")
    lookup.image = diffuse_weight_image(material.name + "-weight", f0,
                                        gloss_from_roughness(roughness))
    lookup.interpolation = "Linear"
    lookup.extension = "EXTEND"
    tree.links.new(coordinate.outputs["Vector"], lookup.inputs["Vector"])
    colour = tree.nodes.new("ShaderNodeMixRGB")
    colour.blend_type = "MULTIPLY"
    colour.inputs["Fac"].default_value = 1.0
    colour.inputs["Color1"].default_value = list(albedo) + [1.0]
    tree.links.new(lookup.outputs["Color"], colour.inputs["Color2"])
    diffuse = tree.nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Roughness"].default_value = 0.0  # Lambert
    tree.links.new(colour.outputs["Color"], diffuse.inputs["Color"])
    add = tree.nodes.new("ShaderNodeAddShader")
    tree.links.new(diffuse.outputs["BSDF"], add.inputs[0])
    tree.links.new(specular.outputs["BSDF"], add.inputs[1])
    return add.outputs["Shader"]


def light_shape(light, reach, cone):
    """What the engine does to a punctual light's emission and Blender's importer does not
    (shaders/lighting.glsl), as the light's node tree:
      - KHR_lights_punctual's range (reach > 0), rangeWindow: saturate(1 - (d / range)^4)^2 of
        the distance d, which the importer drops; Cycles' Light Falloff node gives d as its
        Linear output at strength 1 (the ray's length);
      - a spot's cone (cone = (inner, outer) radians), spotCone: saturate((cos a - cos outer) /
        (cos inner - cos outer))^2 of the angle a off its axis, where Blender's spot ramps by a
        smoothstep over its blend and keeps a further cos a inside the cone (the spot room read
        1.23x bright for them): the light made a point light (Blender gives both the same
        intensity for one power), masked by the cone computed from Texture Coordinate's Normal,
        the direction from the light in its own space, whose axis is -Z."""
    if cone is not None:
        light.type = "POINT"
    light.use_nodes = True
    tree = light.node_tree
    emission = next(n for n in tree.nodes if n.type == "EMISSION")

    def math_node(operation, a, b, clamp=False):
        node = tree.nodes.new("ShaderNodeMath")
        node.operation = operation
        node.use_clamp = clamp
        for socket, value in ((node.inputs[0], a), (node.inputs[1], b)):
            if isinstance(value, float):
                socket.default_value = value
            else:
                tree.links.new(value, socket)
        return node.outputs[0]

    strength = 1.0
    if reach > 0.0:
        falloff = tree.nodes.new("ShaderNodeLightFalloff")
        falloff.inputs["Strength"].default_value = 1.0
        falloff.inputs["Smooth"].default_value = 0.0
        fourth = math_node("POWER", math_node("DIVIDE", falloff.outputs["Linear"], float(reach)),
                           4.0)
        strength = math_node("POWER", math_node("SUBTRACT", 1.0, fourth, clamp=True), 2.0)
    if cone is not None:
        inner, outer = cone
        coordinate = tree.nodes.new("ShaderNodeTexCoord")
        unit = tree.nodes.new("ShaderNodeVectorMath")
        unit.operation = "NORMALIZE"
        tree.links.new(coordinate.outputs["Normal"], unit.inputs[0])
        axis = tree.nodes.new("ShaderNodeVectorMath")
        axis.operation = "DOT_PRODUCT"
        tree.links.new(unit.outputs["Vector"], axis.inputs[0])
        axis.inputs[1].default_value = (0.0, 0.0, -1.0)
        cos_outer = math.cos(outer)
        scale = 1.0 / max(0.001, math.cos(inner) - cos_outer)
        t = math_node("MULTIPLY", math_node("SUBTRACT", axis.outputs["Value"], cos_outer), scale,
                      clamp=True)
        mask = math_node("MULTIPLY", t, t)
        strength = mask if isinstance(strength, float) else math_node("MULTIPLY", strength, mask)
    if not isinstance(strength, float):
        tree.links.new(strength, emission.inputs["Strength"])


def render(gltf, camera, out, width, height, samples, sky, seed):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=gltf, convert_lighting_mode="COMPAT")
    scene = bpy.context.scene
    cameras = [o for o in scene.objects if o.type == "CAMERA" and o.name == camera]
    if not cameras:
        sys.exit(f"cycles-render: {gltf}: no camera '{camera}'")
    scene.camera = cameras[0]
    for light in bpy.data.lights:
        if light.type == "SUN":
            light.angle = 2.0 * SUN_ANGULAR_RADIUS
        else:
            light.shadow_soft_size = POINT_RADIUS
    with open(gltf) as f:
        document = json.load(f)
    for source in document.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", []):
        light = bpy.data.lights.get(source.get("name", ""))
        if light is None or source.get("type") == "directional":
            continue
        spot = source.get("spot") if source.get("type") == "spot" else None
        cone = None
        if spot is not None:
            cone = (spot.get("innerConeAngle", 0.0), spot.get("outerConeAngle", math.pi / 4))
        if source.get("range", 0.0) > 0.0 or cone is not None:
            light_shape(light, source.get("range", 0.0), cone)
    shadowless = {m.get("name") for m in document.get("materials", [])
                  if m.get("extras", {}).get("onelight", {}).get("casts_shadows") is False}
    for o in scene.objects:
        if o.type == "MESH" and any(s.material and s.material.name in shadowless
                                    for s in o.material_slots):
            o.visible_shadow = False  # a Quake 3 translucent surface: light passes it
    for material in bpy.data.materials:
        node = principled(material)
        if node is None:
            continue
        tree = material.node_tree
        if is_lambert(node):
            # The base colour texture (sRGB, times its factor, as the importer wired it) or value.
            diffuse = tree.nodes.new("ShaderNodeBsdfDiffuse")
            linked_or_value(tree, node.inputs["Base Color"], diffuse.inputs["Color"])
            diffuse.inputs["Roughness"].default_value = 0.0  # Lambert
            surface = alpha_tested(material, node, diffuse.outputs["BSDF"])
        elif node.inputs["Base Color"].is_linked:
            continue  # a textured glossy material: not modelled here
        else:
            surface = layered(material, node)
        strength = node.inputs["Emission Strength"].default_value
        colour = node.inputs["Emission"]
        if strength > 0.0 and (colour.is_linked or max(colour.default_value[:3]) > 0.0):
            # Emission from the front face only, as the engine's single-sided emitters; its
            # colour the importer's (an emissive texture times its factor) or value.
            emission = tree.nodes.new("ShaderNodeEmission")
            linked_or_value(tree, colour, emission.inputs["Color"])
            emission.inputs["Strength"].default_value = strength
            geometry = tree.nodes.new("ShaderNodeNewGeometry")
            black = tree.nodes.new("ShaderNodeEmission")
            black.inputs["Strength"].default_value = 0.0
            front = tree.nodes.new("ShaderNodeMixShader")
            tree.links.new(geometry.outputs["Backfacing"], front.inputs["Fac"])
            tree.links.new(emission.outputs["Emission"], front.inputs[1])
            tree.links.new(black.outputs["Emission"], front.inputs[2])
            add = tree.nodes.new("ShaderNodeAddShader")
            tree.links.new(surface, add.inputs[0])
            tree.links.new(front.outputs["Shader"], add.inputs[1])
            surface = add.outputs["Shader"]
        output = tree.nodes["Material Output"]
        tree.links.new(surface, output.inputs["Surface"])
    world = bpy.data.worlds.new("sky")
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (sky[0], sky[1], sky[2], 1.0)
    background.inputs["Strength"].default_value = 1.0
    scene.world = world
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = samples
    cycles.seed = seed
    cycles.use_denoising = False
    cycles.use_adaptive_sampling = False
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.max_bounces = cycles.diffuse_bounces = cycles.glossy_bounces = 64
    cycles.transparent_max_bounces = cycles.transmission_bounces = 64
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    cycles.blur_glossy = 0.0
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    scene.view_settings.view_transform = "Standard"
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_depth = "32"
    scene.render.filepath = out
    bpy.ops.render.render(write_still=True)


def fresnel_dielectric(c, eta):
    """Unpolarised Fresnel reflectance of a dielectric of relative index eta at cosine c."""
    g = np.sqrt(np.maximum(eta * eta - 1.0 + c * c, 0.0))
    a = (g - c) / (g + c)
    b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0)
    return 0.5 * a * a * (1.0 + b * b)


def ggx_albedo(nov, alpha, f0, cycles, steps=256):
    """The directional albedo of a GGX layer at each cosine in `nov`, by a midpoint quadrature
    over the half vector sampled by D (steps^2 points): the engine's (Schlick's Fresnel,
    height-correlated Smith; shaders/brdf.glsl) or, with `cycles`, Cycles 3.4 Principled's
    (the Fresnel of a dielectric of f0's index, normalised to f0 at normal incidence:
    interpolate_fresnel_color; separable Smith: bsdf_microfacet_ggx_eval_reflect)."""
    u = (np.arange(steps) + 0.5) / steps
    u1, u2 = np.meshgrid(u, u)
    a2 = alpha * alpha
    cos_h = np.sqrt((1.0 - u1) / (1.0 + (a2 - 1.0) * u1)).ravel()
    sin_h = np.sqrt(1.0 - cos_h * cos_h)
    phi = 2.0 * np.pi * u2.ravel()
    eta = (1.0 + math.sqrt(f0)) / (1.0 - math.sqrt(f0))
    albedo = []
    for c in nov:
        s = math.sqrt(max(1.0 - c * c, 0.0))
        voh = sin_h * np.cos(phi) * s + cos_h * c  # v = (s, 0, c)
        nol = 2.0 * voh * cos_h - c
        ok = (nol > 0.0) & (voh > 0.0)
        nol = np.where(ok, nol, 1.0)
        lam = lambda x: np.sqrt(a2 + (1.0 - a2) * x * x)
        if cycles:
            fresnel = f0 + (1.0 - f0) * (fresnel_dielectric(voh, eta) - f0) / (1.0 - f0)
            g = (2.0 * c / (c + lam(c))) * (2.0 * nol / (nol + lam(nol)))
            weight = g * voh / (c * cos_h)  # f cos / pdf, pdf = D cos_h / (4 voh)
        else:
            fresnel = f0 + (1.0 - f0) * (1.0 - voh) ** 5
            vis = 0.5 / (nol * lam(c) + c * lam(nol))
            weight = vis * nol * 4.0 * voh / cos_h
        albedo.append(float(np.where(ok, weight * fresnel, 0.0).mean()))
    return np.array(albedo)


def closed_form(gltf, camera, width, height, sky, out_engine, out_cycles):
    """A glossy floor under a uniform sky alone (sky_floor_glossy), in closed form for the
    engine's model and for Cycles': a pixel that sees the floor at cosine NoV is
    sky (albedo w(NoV) + E(NoV)), w the engine's diffuse weight and E the GGX layer's albedo
    (ggx_albedo), and sky elsewhere. Written as two EXRs of the camera's view."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=gltf, convert_lighting_mode="COMPAT")
    scene = bpy.context.scene
    scene.render.resolution_x, scene.render.resolution_y = width, height
    cam = next(o for o in scene.objects if o.type == "CAMERA" and o.name == camera)
    floors = [o for o in scene.objects if o.type == "MESH"]
    if len(floors) != 1:
        sys.exit(f"cycles-render: {gltf}: closed-form wants one floor, found {len(floors)} meshes")
    floor = floors[0]
    node = principled(floor.active_material)
    corners = [floor.matrix_world @ v.co for v in floor.data.vertices]
    if node is None or max(abs(c.z) for c in corners) > 1e-6:
        sys.exit(f"cycles-render: {gltf}: closed-form wants one untextured floor at height 0")
    x0, x1 = min(c.x for c in corners), max(c.x for c in corners)
    y0, y1 = min(c.y for c in corners), max(c.y for c in corners)
    base = np.array(node.inputs["Base Color"].default_value[:3])
    roughness = node.inputs["Roughness"].default_value
    gloss = gloss_from_roughness(roughness)
    # Rays through a 4 x 4 grid in each pixel (the box filter both tracers use), from the
    # camera's frame (camera space: -z ahead).
    n = 4
    frame = cam.data.view_frame(scene=scene)  # top right, bottom right, bottom left, top left
    top_right, bottom_left = np.array(frame[0]), np.array(frame[2])
    u = (np.arange(width * n) + 0.5) / (width * n)
    v = (np.arange(height * n) + 0.5) / (height * n)  # from the top
    local = np.zeros((height * n, width * n, 3))
    local[..., 0] = bottom_left[0] + u[None, :] * (top_right[0] - bottom_left[0])
    local[..., 1] = top_right[1] - v[:, None] * (top_right[1] - bottom_left[1])
    local[..., 2] = top_right[2]
    rotation = np.array(cam.matrix_world.to_3x3())
    d = local @ rotation.T
    d /= np.linalg.norm(d, axis=2, keepdims=True)
    eye = np.array(cam.matrix_world.translation)
    t = np.where(d[..., 2] < 0.0, -eye[2] / np.minimum(d[..., 2], -1e-12), -1.0)
    hit = eye[None, None, :] + t[..., None] * d
    on_floor = (t > 0.0) & (hit[..., 0] >= x0) & (hit[..., 0] <= x1) & (hit[..., 1] >= y0) & \
        (hit[..., 1] <= y1)
    nov = np.clip(-d[..., 2], MIN_NOV, 1.0)
    grid = np.linspace(MIN_NOV, 1.0, 257)
    ab = env_brdf(np.sqrt(nov.ravel()), gloss).reshape(nov.shape + (2,))
    weight = np.clip(1.0 - (DIELECTRIC_F0 * ab[..., 0] + ab[..., 1]), 0.0, 1.0)
    for out, cycles in ((out_engine, False), (out_cycles, True)):
        specular = np.interp(nov, grid, ggx_albedo(grid, roughness ** 2, DIELECTRIC_F0, cycles))
        radiance = sky * (base[None, None, :] * weight[..., None] + specular[..., None])
        radiance = np.where(on_floor[..., None], radiance, sky)
        radiance = radiance.reshape(height, n, width, n, 3).mean(axis=(1, 3))
        image = bpy.data.images.new(os.path.basename(out), width, height, float_buffer=True)
        rgba = np.ones((height, width, 4))
        rgba[..., :3] = radiance
        image.pixels[:] = rgba[::-1].ravel().tolist()  # Blender's rows from the bottom
        settings = scene.render.image_settings
        settings.file_format = "OPEN_EXR"
        settings.color_depth = "32"
        image.save_render(out, scene=scene)


def luminance_blocks(path, block):
    image = bpy.data.images.load(path)
    width, height = image.size
    rgba = np.array(image.pixels[:], dtype=np.float64).reshape(height, width, 4)
    y = 0.2126 * rgba[:, :, 0] + 0.7152 * rgba[:, :, 1] + 0.0722 * rgba[:, :, 2]
    rows, columns = height // block, width // block
    y = y[: rows * block, : columns * block]
    return y.reshape(rows, block, columns, block).mean(axis=(1, 3)), (width, height)


def compare(a_path, b_path, block, out):
    a, a_size = luminance_blocks(a_path, block)
    b, b_size = luminance_blocks(b_path, block)
    if a_size != b_size:
        sys.exit(f"cycles-render: {a_path} is {a_size}, {b_path} is {b_size}")
    lit = a > 1e-3 * max(a.mean(), 1e-12)
    rel = np.abs(b[lit] - a[lit]) / a[lit]
    result = {"blocks": int(lit.sum()), "mean_relative_error": float(rel.mean()),
              "level_ratio": float(b[lit].sum() / a[lit].sum()),
              "worst_block": float(rel.max()) if rel.size else 0.0}
    with open(out, "w") as f:
        json.dump(result, f)


def main():
    argv = sys.argv[sys.argv.index("--") + 1:]
    if argv and argv[0] == "render" and len(argv) == 9:
        sky = [float(x) for x in argv[7].split(",")]
        render(argv[1], argv[2], argv[3], int(argv[4]), int(argv[5]), int(argv[6]),
               sky * 3 if len(sky) == 1 else sky, int(argv[8]))
    elif argv and argv[0] == "closed-form" and len(argv) == 8:
        closed_form(argv[1], argv[2], int(argv[3]), int(argv[4]), float(argv[5]), argv[6],
                    argv[7])
    elif argv and argv[0] == "compare" and len(argv) == 5:
        compare(argv[1], argv[2], int(argv[3]), argv[4])
    else:
        sys.exit("cycles-render: usage: render GLTF CAMERA OUT WIDTH HEIGHT SAMPLES SKY SEED | "
                 "closed-form GLTF CAMERA WIDTH HEIGHT SKY ENGINE.exr CYCLES.exr | "
                 "compare A.exr B.exr BLOCK OUT.json")


main()
