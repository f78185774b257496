"""Renders a glTF scene with Blender's Cycles as an independent reference for penumbra.

Run by Blender:  blender -b --factory-startup -P cycles_render.py -- SCENE.gltf OUT.exr SIZE SPP SEED DEPTH
Materials are rebuilt from the glTF JSON so both renderers see the same models:
  metallic 0 and KHR_materials_specular factor 0 -> Diffuse BSDF (Lambertian),
  emissive -> Emission with emissiveFactor * emissiveStrength, from the front face only
    unless doubleSided (penumbra's rule, docs/conventions.md; Cycles' Emission is two-sided),
  metallic 1, roughness 0 -> sharp Glossy BSDF with the base colour.
Clamping and the light threshold are off and every bounce limit is DEPTH - 1, the same
longest paths as penumbra's --max-depth DEPTH, so the two estimate the same integral.
"""
import json
import sys

import warnings

import bpy
import numpy

# Debian's Blender 3.4 glTF importer still uses numpy.bool, which numpy 1.24 removed.
with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    if not hasattr(numpy, "bool"):
        numpy.bool = bool

scene_path, out_path, size, spp, seed, depth = sys.argv[sys.argv.index("--") + 1:]
size, spp, seed, depth = int(size), int(spp), int(seed), int(depth)

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=scene_path)
gltf = json.load(open(scene_path))


def rebuild(mat, desc):
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    pbr = desc.get("pbrMetallicRoughness", {})
    color = pbr.get("baseColorFactor", [1, 1, 1, 1])
    ext = desc.get("extensions", {})
    emissive = desc.get("emissiveFactor", [0, 0, 0])
    strength = ext.get("KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
    if max(emissive) > 0:
        node = nodes.new("ShaderNodeEmission")
        node.inputs["Color"].default_value = list(emissive) + [1.0]
        node.inputs["Strength"].default_value = strength
        if not desc.get("doubleSided", False):
            # Back faces (Backfacing = 1) get the mix's empty second input: black.
            mix = nodes.new("ShaderNodeMixShader")
            links.new(nodes.new("ShaderNodeNewGeometry").outputs["Backfacing"], mix.inputs[0])
            links.new(node.outputs[0], mix.inputs[1])
            node = mix
    elif pbr.get("metallicFactor", 1.0) == 1.0 and pbr.get("roughnessFactor", 1.0) == 0.0:
        node = nodes.new("ShaderNodeBsdfGlossy")
        node.distribution = "SHARP"
        node.inputs["Color"].default_value = color
    elif pbr.get("metallicFactor", 1.0) == 0.0 and \
            ext.get("KHR_materials_specular", {}).get("specularFactor", 1.0) == 0.0:
        node = nodes.new("ShaderNodeBsdfDiffuse")
        node.inputs["Color"].default_value = color
        node.inputs["Roughness"].default_value = 0.0
    else:
        raise SystemExit("cycles_render.py: material '%s' has no exact Cycles equivalent"
                         % desc.get("name"))
    links.new(node.outputs[0], out.inputs["Surface"])


by_name = {m.get("name"): m for m in gltf.get("materials", [])}
for mat in bpy.data.materials:
    if mat.name in by_name:
        rebuild(mat, by_name[mat.name])

scene = bpy.context.scene
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = spp
scene.cycles.seed = seed
scene.cycles.use_denoising = False
scene.cycles.use_adaptive_sampling = False
scene.cycles.sample_clamp_direct = 0
scene.cycles.sample_clamp_indirect = 0
scene.cycles.light_sampling_threshold = 0
# penumbra's --max-depth N ends a path after N scattering events, so its longest paths
# have N - 1 indirect bounces; Cycles' bounce limits count indirect bounces (0: direct
# light only). Measured: penumbra at depth 1 leaves the ceiling black (lit only
# indirectly), Cycles at 1 does not; penumbra at 2 matches Cycles at 1.
bounces = max(depth - 1, 0)
scene.cycles.max_bounces = bounces
scene.cycles.diffuse_bounces = bounces
scene.cycles.glossy_bounces = bounces
scene.cycles.transmission_bounces = bounces
scene.cycles.caustics_reflective = True
scene.cycles.caustics_refractive = True
scene.cycles.blur_glossy = 0
# One-pixel box filter, like penumbra --filter box, so edges match too.
scene.cycles.pixel_filter_type = "BOX"
scene.cycles.filter_width = 1.0
scene.world = bpy.data.worlds.new("black")
scene.world.use_nodes = True
scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0
scene.render.resolution_x = size
scene.render.resolution_y = size
scene.render.resolution_percentage = 100
scene.render.film_transparent = False
scene.view_settings.view_transform = "Standard"
scene.camera = next(o for o in scene.objects if o.type == "CAMERA")
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.filepath = out_path
bpy.ops.render.render(write_still=True)
