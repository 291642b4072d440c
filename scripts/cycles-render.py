"""Run inside Blender (blender -b --factory-startup -P scripts/cycles-render.py -- ...), for
scripts/cycles-check.py, which says why and how the units map.

  render GLTF CAMERA OUT.exr WIDTH HEIGHT SAMPLES SKY_CD_PER_M2 SEED
      imports the glTF with its lights in glTF's own units ('COMPAT': lux and candela read as
      W/m^2 and W/sr, so that Cycles' radiance is the engine's cd/m^2), gives every Lambert
      material (roughness 1, metallic 0, no texture: the engine's MATERIAL_LAMBERT) a plain
      Diffuse BSDF, the lights the engine's sizes, a uniform world of SKY, and renders the
      camera's view with Cycles: no clamping, no denoising, a box pixel filter, 64 bounces.
  compare A.exr B.exr BLOCK OUT.json
      the mean relative error of B against A over BLOCK x BLOCK pixel blocks' luminance, and
      the ratio of their mean levels, as JSON.
"""
import json
import math
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


def lambert(material):
    node = material.node_tree.nodes.get("Principled BSDF") if material.node_tree else None
    if node is None:
        return None
    if node.inputs["Base Color"].is_linked or node.inputs["Roughness"].is_linked:
        return None
    if node.inputs["Roughness"].default_value < 1.0 or node.inputs["Metallic"].default_value > 0:
        return None
    return node


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
        if light.type == "SPOT":
            # The importer's blend, 1 - inner / outer, ramps Cycles' cone over that share of
            # 1 - cos(outer), wider than glTF's ramp from cos(outer) to cos(inner) (the spot room
            # read 1.5x bright for it): the ramp put over glTF's span (its shape, a smoothstep
            # against glTF's square, still differs).
            outer = 0.5 * light.spot_size
            inner = outer * (1.0 - light.spot_blend)
            light.spot_blend = (math.cos(inner) - math.cos(outer)) / (1.0 - math.cos(outer))
    for material in bpy.data.materials:
        node = lambert(material)
        if node is None:
            continue
        tree = material.node_tree
        diffuse = tree.nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = node.inputs["Base Color"].default_value
        diffuse.inputs["Roughness"].default_value = 0.0  # Lambert
        surface = diffuse.outputs["BSDF"]
        strength = node.inputs["Emission Strength"].default_value
        colour = node.inputs["Emission"].default_value
        if strength > 0.0 and max(colour[:3]) > 0.0:
            # Emission from the front face only, as the engine's single-sided emitters.
            emission = tree.nodes.new("ShaderNodeEmission")
            emission.inputs["Color"].default_value = colour
            emission.inputs["Strength"].default_value = strength
            geometry = tree.nodes.new("ShaderNodeNewGeometry")
            black = tree.nodes.new("ShaderNodeEmission")
            black.inputs["Strength"].default_value = 0.0
            front = tree.nodes.new("ShaderNodeMixShader")
            tree.links.new(geometry.outputs["Backfacing"], front.inputs["Fac"])
            tree.links.new(emission.outputs["Emission"], front.inputs[1])
            tree.links.new(black.outputs["Emission"], front.inputs[2])
            add = tree.nodes.new("ShaderNodeAddShader")
            tree.links.new(diffuse.outputs["BSDF"], add.inputs[0])
            tree.links.new(front.outputs["Shader"], add.inputs[1])
            surface = add.outputs["Shader"]
        output = tree.nodes["Material Output"]
        tree.links.new(surface, output.inputs["Surface"])
    world = bpy.data.worlds.new("sky")
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    background.inputs["Strength"].default_value = sky
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
        render(argv[1], argv[2], argv[3], int(argv[4]), int(argv[5]), int(argv[6]),
               float(argv[7]), int(argv[8]))
    elif argv and argv[0] == "compare" and len(argv) == 5:
        compare(argv[1], argv[2], int(argv[3]), argv[4])
    else:
        sys.exit("cycles-render: usage: render GLTF CAMERA OUT WIDTH HEIGHT SAMPLES SKY SEED | "
                 "compare A.exr B.exr BLOCK OUT.json")


main()
