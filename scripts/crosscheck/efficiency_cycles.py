"""Cycles' side of scripts/crosscheck/efficiency.py: imports a glTF once and renders it at each
(spp, seed) of a job, timing each render without the scene load and sync.

Run by Blender:  blender -b --factory-startup -P efficiency_cycles.py -- JOB.json
JOB.json: scene, width, height, world_to_camera, world_to_ndc (penumbra's EXR header, as in
cycles_import_render.py), max_depth, threads, materials ("exact": Lambertian, emission and
sharp mirror rebuilt as cycles_render.py does, else the importer's Principled BSDF), world
(null: black; [r, g, b]: uniform; a path: an equirectangular image), renders
[{spp, seed, out}], paced (optional: before each render print "EFFICIENCY-READY" and wait
for a line "go" on stdin, after it print "EFFICIENCY-RENDERED"; efficiency.py
--interleave). Prints "EFFICIENCY {json}" with the times, or "EFFICIENCY-ERROR ..." and
exits 2.
Timing: the wall time of each render here includes Cycles' scene sync (BVH, images); the
driver takes the path-tracing time alone from Cycles' status lines (efficiency_render.py).
Persistent data is off: Blender 3.4 in background mode skips re-renders with it on.
"""
import json
import math
import sys
import time
import warnings

import bpy
import numpy

# The cache key of these renders (efficiency_render.py): raise it when a change here alters
# Cycles' images or times, not for comments or reporting.
SETUP_VERSION = 1
from mathutils import Matrix

# Debian's Blender 3.4 glTF importer still uses numpy.bool, which numpy 1.24 removed.
with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    if not hasattr(numpy, "bool"):
        numpy.bool = bool

process_start = time.time()
job = json.load(open(sys.argv[sys.argv.index("--") + 1]))


def fail(message):
    print("EFFICIENCY-ERROR " + " ".join(str(message).split()))
    sys.stdout.flush()
    sys.exit(2)


def exact_material(mat, desc):
    """cycles_render.py's rebuild: the glTF materials that have an exact Cycles node."""
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    pbr = desc.get("pbrMetallicRoughness", {})
    ext = desc.get("extensions", {})
    emissive = desc.get("emissiveFactor", [0, 0, 0])
    if max(emissive) > 0:
        node = nodes.new("ShaderNodeEmission")
        node.inputs["Color"].default_value = list(emissive) + [1.0]
        node.inputs["Strength"].default_value = ext.get(
            "KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
        if not desc.get("doubleSided", False):  # penumbra emits from the front only
            mix = nodes.new("ShaderNodeMixShader")
            links.new(nodes.new("ShaderNodeNewGeometry").outputs["Backfacing"], mix.inputs[0])
            links.new(node.outputs[0], mix.inputs[1])
            node = mix
    elif pbr.get("metallicFactor", 1.0) == 1.0 and pbr.get("roughnessFactor", 1.0) == 0.0:
        node = nodes.new("ShaderNodeBsdfGlossy")
        node.distribution = "SHARP"
        node.inputs["Color"].default_value = pbr.get("baseColorFactor", [1, 1, 1, 1])
    elif pbr.get("metallicFactor", 1.0) == 0.0 and \
            ext.get("KHR_materials_specular", {}).get("specularFactor", 1.0) == 0.0:
        node = nodes.new("ShaderNodeBsdfDiffuse")
        node.inputs["Color"].default_value = pbr.get("baseColorFactor", [1, 1, 1, 1])
        node.inputs["Roughness"].default_value = 0.0
    else:
        fail("material '%s' has no exact Cycles equivalent" % desc.get("name"))
    links.new(node.outputs[0], out.inputs["Surface"])


def matrix(rows):
    """OpenEXR stores row-vector matrices (p' = p M); mathutils multiplies columns."""
    return Matrix([rows[0:4], rows[4:8], rows[8:12], rows[12:16]]).transposed()


def camera_from_header(scene):
    """penumbra's camera from its EXR header (derivation in cycles_import_render.py)."""
    w2c = matrix(job["world_to_camera"])
    proj = matrix(job["world_to_ndc"]) @ w2c.inverted()
    flip = Matrix.Diagonal((1, 1, -1, 1))
    y_up_to_z_up = Matrix(((1, 0, 0, 0), (0, 0, -1, 0), (0, 1, 0, 0), (0, 0, 0, 1)))
    cam = bpy.data.cameras.new("efficiency")
    obj = bpy.data.objects.new("efficiency", cam)
    scene.collection.objects.link(obj)
    obj.matrix_world = y_up_to_z_up @ w2c.inverted() @ flip
    cam.sensor_fit = "VERTICAL"
    cam.dof.use_dof = False
    if abs(proj[3][3]) > 0.5:
        fail("orthographic cameras are not supported here")
    cam.type = "PERSP"
    cam.angle_y = 2 * math.atan(0.5 / abs(proj[1][1]))
    cam.clip_start = 1e-3
    cam.clip_end = 1e6
    scene.camera = obj


def world(scene):
    w = bpy.data.worlds.new("efficiency")
    w.use_nodes = True
    background = w.node_tree.nodes["Background"]
    spec = job.get("world")
    if spec is None:
        background.inputs["Strength"].default_value = 0
    elif isinstance(spec, list):
        background.inputs["Color"].default_value = list(spec) + [1.0]
    else:
        # Blender's equirectangular mapping of a Z-up direction d, u = atan2(d.y, -d.x) /
        # 2 pi + 0.5, is penumbra's atan2(-z, -x) / 2 pi + 0.5 of the glTF direction after
        # the importer's (x, y, z) -> (x, -z, y); v (elevation) agrees too. Closest texel,
        # as penumbra's piecewise-constant environment.
        tex = w.node_tree.nodes.new("ShaderNodeTexEnvironment")
        tex.image = bpy.data.images.load(spec)
        tex.interpolation = "Closest"
        w.node_tree.links.new(tex.outputs["Color"], background.inputs["Color"])
        background.inputs["Strength"].default_value = 1.0
    scene.world = w


bpy.ops.wm.read_factory_settings(use_empty=True)
try:
    result = bpy.ops.import_scene.gltf(filepath=job["scene"])
except Exception as e:
    fail("import failed: %s" % e)
if "FINISHED" not in result:
    fail("import cancelled: %s" % result)
# glTF's point lights have no size; Blender's default radius of 0.25 m would soften them.
for light in bpy.data.lights:
    light.shadow_soft_size = 0
if job["materials"] == "exact":
    by_name = {m.get("name"): m for m in json.load(open(job["scene"])).get("materials", [])}
    for mat in bpy.data.materials:
        if mat.name in by_name:
            exact_material(mat, by_name[mat.name])

scene = bpy.context.scene
camera_from_header(scene)
world(scene)
scene.render.engine = "CYCLES"
c = scene.cycles
c.device = "CPU"
scene.render.threads_mode = "FIXED"
scene.render.threads = job["threads"]
c.use_denoising = False
c.use_adaptive_sampling = False
c.sample_clamp_direct = 0
c.sample_clamp_indirect = 0
c.light_sampling_threshold = 0
# penumbra's --max-depth N is N - 1 indirect bounces (cycles_render.py).
bounces = max(job["max_depth"] - 1, 0)
for attr in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces",
             "volume_bounces"):
    setattr(c, attr, bounces)
c.transparent_max_bounces = 256
c.caustics_reflective = True
c.caustics_refractive = True
c.blur_glossy = 0
c.pixel_filter_type = "BOX"
c.filter_width = 1.0
scene.render.resolution_x = job["width"]
scene.render.resolution_y = job["height"]
scene.render.resolution_percentage = 100
scene.render.film_transparent = False
scene.view_settings.view_transform = "Standard"
scene.view_settings.look = "None"
settings = scene.render.image_settings
settings.file_format = "OPEN_EXR"
settings.color_mode = "RGB"
settings.color_depth = "32"
settings.exr_codec = "ZIP"

setup_s = time.time() - process_start


def render(spp, seed):
    """Wall and CPU seconds of one render (process_time counts every thread of Blender's
    process, so Cycles' workers too)."""
    c.samples = spp
    c.seed = seed
    wall, cpu = time.time(), time.process_time()
    bpy.ops.render.render(write_still=False)
    return time.time() - wall, time.process_time() - cpu


# A 1-spp render first: its CPU time (sync and one sample) is what the driver subtracts to
# get the CPU cost of the samples alone, as it does with penumbra's 1-spp render.
_, cpu_1spp = render(1, 0)
walls, cpus = [], []
for r in job["renders"]:
    if job.get("paced"):
        # efficiency.py --interleave: penumbra renders while this process waits here.
        print("EFFICIENCY-READY")
        sys.stdout.flush()
        if sys.stdin.readline().strip() != "go":
            fail("the driver stopped before the render of %d spp, seed %d"
                 % (r["spp"], r["seed"]))
    wall, cpu = render(r["spp"], r["seed"])
    walls.append(wall)
    cpus.append(cpu)
    bpy.data.images["Render Result"].save_render(r["out"])
    if job.get("paced"):
        print("EFFICIENCY-RENDERED")
        sys.stdout.flush()
print("EFFICIENCY " + json.dumps({
    "setup_s": setup_s, "render_wall_s": walls, "render_cpu_s": cpus, "cpu_1spp_s": cpu_1spp,
    "sampling_pattern": c.sampling_pattern, "version": bpy.app.version_string}))
