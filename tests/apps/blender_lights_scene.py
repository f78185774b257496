"""Blender's own light units against penumbra's reading of them (BlenderLights test).

Run by Blender 3.4:  blender -b --factory-startup --python blender_lights_scene.py -- OUTDIR W H SPP
Builds a scene in Blender (a diffuse floor, two boxes, a point light, a spot light and a
sun, in Blender's units: W and W/m^2), exports it with Blender's glTF add-on in its
default lighting mode ("Standard": candela = W / 4 pi x 683, lux = W/m^2 x 683) as
all.gltf, plus one file per light (point.gltf, spot.gltf, sun.gltf) and all.gltf's scene
in the "Unitless" and "Raw" modes (unitless.gltf, raw.gltf), then imports each Standard
file into an empty scene with the importer's defaults and renders it with Cycles
(cycles_VARIANT_SEED.exr, seeds 1 and 2; SPP samples, 8 x SPP for all.gltf). Prints the
pixel rectangles of the regions the test compares: "REGION name x0 y0 x1 y1" (x right,
y down, half-open), and each imported light's Blender strength: "IMPORTED variant TYPE W".

Two settings keep the models equal (docs/conventions.md, "Light units"): the importer
gives point and spot lights Blender's default radius of 0.25 m, which Cycles renders as a
disk, so the render sets it back to 0 (glTF's lights are points); and the imported
Principled BSDF's diffuse is Disney's, not glTF's Lambertian, so it becomes a Diffuse BSDF
of the same base colour. Cycles renders direct light only (max_bounces 0), as penumbra's
`direct` integrator, with a one-pixel box filter.
"""
import math
import os
import sys
import warnings

import bpy
import numpy
from bpy_extras.object_utils import world_to_camera_view
from mathutils import Vector

# Debian's Blender 3.4 glTF importer still uses numpy.bool, which numpy 1.24 removed.
with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    if not hasattr(numpy, "bool"):
        numpy.bool = bool

out_dir, width, height, spp = sys.argv[sys.argv.index("--") + 1:]
width, height, spp = int(width), int(height), int(spp)

POINT = (2.0, -0.5, 2.5)   # 300 W: 23.9 W/sr, 16305 cd
SPOT = (-2.0, -0.5, 4.0)   # 800 W: 63.7 W/sr, pointing straight down, 60 degree cone
BOX = (0.5, 1.5, 0.5)      # a 1 m cube standing on the floor
# Floor squares (centre, half side) and box faces (centre, two half-axes), in Blender's
# Z-up world. The spot's region stays within 5 degrees of its axis, where Cycles' extra
# cosine falloff inside the cone (see the docs) costs under 0.2%; the others lie outside
# its cone (37 degrees and more from the axis), away from its blend, where Cycles'
# smoothstep and glTF's falloff differ.
REGIONS = {
    "floor-point": [(2.0, -0.5, 0.0), (0.3, 0, 0), (0, 0.3, 0)],
    "floor-spot": [(-2.0, -0.5, 0.0), (0.25, 0, 0), (0, 0.25, 0)],
    "floor-sun": [(0.8, -1.6, 0.0), (0.35, 0, 0), (0, 0.35, 0)],
    "box-top": [(0.5, 1.5, 1.0), (0.35, 0, 0), (0, 0.35, 0)],
    "box-front": [(0.5, 1.0, 0.5), (0.35, 0, 0), (0, 0, 0.35)],
}


def principled(name, rgb):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    p = m.node_tree.nodes["Principled BSDF"]
    p.inputs["Base Color"].default_value = rgb + (1.0,)
    p.inputs["Roughness"].default_value = 1.0
    p.inputs["Specular"].default_value = 0.0  # exported as specularColorFactor 0
    return m


def build(lights):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.mesh.primitive_plane_add(size=8)
    bpy.context.object.data.materials.append(principled("floor", (0.8, 0.8, 0.8)))
    bpy.ops.mesh.primitive_cube_add(size=1, location=BOX)
    bpy.context.object.data.materials.append(principled("box", (0.3, 0.5, 0.7)))
    bpy.ops.mesh.primitive_cube_add(size=0.7, location=(-1.2, 2.2, 0.35))
    bpy.context.object.data.materials.append(principled("box2", (0.7, 0.4, 0.3)))
    if "point" in lights:
        bpy.ops.object.light_add(type="POINT", location=POINT)
        bpy.context.object.data.energy = 300
        bpy.context.object.data.shadow_soft_size = 0
    if "spot" in lights:
        bpy.ops.object.light_add(type="SPOT", location=SPOT)
        spot = bpy.context.object.data
        spot.energy = 800
        spot.shadow_soft_size = 0
        spot.spot_size = math.radians(60)
        spot.spot_blend = 0.15
    if "sun" in lights:
        # Travels towards +Y and down: box shadows fall away from the camera.
        bpy.ops.object.light_add(type="SUN", rotation=(math.radians(35), 0, math.radians(10)))
        bpy.context.object.data.energy = 1.5
        bpy.context.object.data.angle = 0
    bpy.ops.object.camera_add(location=(0, -5.0, 7.0), rotation=(math.radians(36), 0, 0))
    bpy.context.scene.camera = bpy.context.object
    # The exporter writes the render's aspect ratio into the camera.
    render_settings(bpy.context.scene, 0, "")


def render_settings(scene, seed, path, samples=1):
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.seed = seed
    scene.cycles.use_denoising = False
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.sample_clamp_direct = 0
    scene.cycles.sample_clamp_indirect = 0
    scene.cycles.light_sampling_threshold = 0
    scene.cycles.max_bounces = 0
    scene.cycles.pixel_filter_type = "BOX"
    scene.cycles.filter_width = 1.0
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.filepath = path


def print_regions():
    scene = bpy.context.scene
    for name, (c, a, b) in REGIONS.items():
        xs, ys = [], []
        for sa in (-1, 1):
            for sb in (-1, 1):
                p = Vector(c) + sa * Vector(a) + sb * Vector(b)
                v = world_to_camera_view(scene, scene.camera, p)
                xs.append(v.x * width)
                ys.append((1 - v.y) * height)
        # Pixels wholly inside the projected quad's bounding box, one more pixel in.
        print("REGION %s %d %d %d %d" % (name, math.ceil(min(xs)) + 1, math.ceil(min(ys)) + 1,
                                         math.floor(max(xs)) - 1, math.floor(max(ys)) - 1))


def import_and_render(gltf, variant):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=gltf)  # the importer's defaults: lighting "Standard"
    scene = bpy.context.scene
    for obj in scene.objects:
        if obj.type == "LIGHT" and obj.data.type in ("POINT", "SPOT"):
            obj.data.shadow_soft_size = 0
        if obj.type == "LIGHT" and obj.data.type == "SUN":
            obj.data.angle = 0
        if obj.type == "LIGHT":
            print("IMPORTED %s %s %.6g" % (variant, obj.data.type, obj.data.energy))
    for mat in bpy.data.materials:
        if not mat.use_nodes or "Principled BSDF" not in mat.node_tree.nodes:
            continue
        nodes, links = mat.node_tree.nodes, mat.node_tree.links
        color = tuple(nodes["Principled BSDF"].inputs["Base Color"].default_value)
        out = next(n for n in nodes if n.type == "OUTPUT_MATERIAL")
        diffuse = nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = color
        diffuse.inputs["Roughness"].default_value = 0.0
        links.new(diffuse.outputs[0], out.inputs["Surface"])
    scene.world = bpy.data.worlds.new("black")
    scene.world.use_nodes = True
    scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0
    scene.camera = next(o for o in scene.objects if o.type == "CAMERA")
    for seed in (1, 2):
        # Three lights to choose from: eight times the samples for about the same noise.
        render_settings(scene, seed, os.path.join(out_dir, "cycles_%s_%d.exr" % (variant, seed)),
                        8 * spp if variant == "all" else spp)
        bpy.ops.render.render(write_still=True)


VARIANTS = {"all": ("point", "spot", "sun"), "point": ("point",), "spot": ("spot",),
            "sun": ("sun",)}
for variant, lights in VARIANTS.items():
    build(lights)
    if variant == "all":
        print_regions()
    # The add-on's defaults, lighting mode "Standard" (SPEC) among them.
    bpy.ops.export_scene.gltf(filepath=os.path.join(out_dir, variant + ".gltf"),
                              export_format="GLTF_EMBEDDED", export_cameras=True,
                              export_lights=True)
    if variant == "all":
        # The add-on's two other lighting modes, for the loader-level check of the mapping.
        for mode, name in (("COMPAT", "unitless"), ("RAW", "raw")):
            bpy.ops.export_scene.gltf(filepath=os.path.join(out_dir, name + ".gltf"),
                                      export_format="GLTF_EMBEDDED", export_cameras=True,
                                      export_lights=True, convert_lighting_mode=mode)
for variant in VARIANTS:
    import_and_render(os.path.join(out_dir, variant + ".gltf"), variant)
print("DONE")
