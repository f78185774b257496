"""Renders a glTF file with Cycles as Blender 3.4's own glTF importer sets it up, under the
camera penumbra used, for scripts/crosscheck/wild_models.py.

Run by Blender:  blender -b --factory-startup -P cycles_import_render.py -- JOB.json
JOB.json: scene, out_prefix, width, height, spp, seeds, max_depth, threads, env (RGB of a
uniform environment, strength 1), world_to_camera and world_to_ndc (penumbra's EXR header,
rows of OpenEXR's row-vector matrices). Writes OUT_PREFIX-SEED.exr (RGBA, transparent film:
RGB is premultiplied, alpha the coverage) per seed and prints one line
"CROSSCHECK {json}" with the render times, or "CROSSCHECK-ERROR message" and exits 2.
Unlike cycles_render.py the materials stay as the importer built them: that is the
comparison.
"""
import json
import os
import sys
import time
import warnings

import bpy
import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_camera import set_camera  # noqa: E402

# Debian's Blender 3.4 glTF importer still uses numpy.bool, which numpy 1.24 removed.
with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    if not hasattr(numpy, "bool"):
        numpy.bool = bool

job = json.load(open(sys.argv[sys.argv.index("--") + 1]))


def fail(message):
    print("CROSSCHECK-ERROR " + " ".join(str(message).split()))
    sys.stdout.flush()
    sys.exit(2)


bpy.ops.wm.read_factory_settings(use_empty=True)
start = time.time()
try:
    result = bpy.ops.import_scene.gltf(filepath=job["scene"],
                                       convert_lighting_mode=job.get("lighting_mode", "SPEC"))
except Exception as e:  # the importer reports ImportError as a RuntimeError here
    fail("import failed: %s" % e)
if "FINISHED" not in result:
    fail("import cancelled: %s" % result)
if not any(o.type == "MESH" for o in bpy.data.objects):
    fail("import produced no mesh")
import_s = time.time() - start
# glTF's lights are points and a sun of no angular size; Blender's new lights are spheres
# of radius 0.25 and a sun of 0.53 degrees, which the importer keeps.
for light in bpy.data.lights:
    light.shadow_soft_size = 0
    if light.type == "SUN":
        light.angle = 0
# The importer leaves primitives without a material on Blender's grey default surface; the
# glTF spec's default material is white, metallic 1, roughness 1 (as penumbra's).
default = bpy.data.materials.new("glTF default")
default.use_nodes = True
bsdf = default.node_tree.nodes["Principled BSDF"]
bsdf.inputs["Base Color"].default_value = (1, 1, 1, 1)
bsdf.inputs["Metallic"].default_value = 1
bsdf.inputs["Roughness"].default_value = 1
for o in bpy.data.objects:
    if o.type == "MESH":
        if not o.material_slots:
            o.data.materials.append(default)
        for slot in o.material_slots:
            if slot.material is None:
                slot.material = default
if job.get("import_only"):  # penumbra failed: only say whether Blender loads the file
    print("CROSSCHECK " + json.dumps({"import_s": import_s, "render_s": {}}))
    sys.exit(0)

scene = bpy.context.scene
# penumbra plays all of a file's animations together, the first one winning a property
# two animate (docs/conventions.md); the importer makes the first the active action and
# stashes the others in muted NLA tracks, later animations lower. Unmuted, with each strip
# held before its start, every animation shows its first key at frame 0, which is glTF's
# value at t = 0 (key times are >= 0 and sampling clamps before the first), the time
# penumbra renders. Not valid for other times: the strips start at scene.frame_start.
for o in bpy.data.objects:
    if o.animation_data:
        for track in o.animation_data.nla_tracks:
            track.mute = False
            for strip in track.strips:
                strip.extrapolation = "HOLD"
# glTF time t is frame t * fps for the active action (the importer's key times).
scene.frame_set(0)


set_camera(scene, job["world_to_camera"], job["world_to_ndc"])

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.render.threads_mode = "FIXED"
scene.render.threads = job["threads"]
scene.cycles.samples = job["spp"]
scene.cycles.use_denoising = False
scene.cycles.use_adaptive_sampling = False
scene.cycles.sample_clamp_direct = 0
scene.cycles.sample_clamp_indirect = 0
scene.cycles.light_sampling_threshold = 0
# penumbra's --max-depth N ends a path after N scattering events (N - 1 indirect
# bounces); Cycles' limits count indirect bounces (as in cycles_render.py).
depth = max(job["max_depth"] - 1, 0)
for attr in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces",
             "volume_bounces"):
    setattr(scene.cycles, attr, depth)
# penumbra passes up to 256 alpha-masked or blended surfaces without counting a bounce
# (integrators/path_integrator.cpp).
scene.cycles.transparent_max_bounces = 256
scene.cycles.caustics_reflective = True
scene.cycles.caustics_refractive = True
scene.cycles.blur_glossy = 0
# One-pixel box filter, like penumbra --filter box.
scene.cycles.pixel_filter_type = "BOX"
scene.cycles.filter_width = 1.0
world = bpy.data.worlds.new("crosscheck")
world.use_nodes = True
background = world.node_tree.nodes["Background"]
background.inputs["Color"].default_value = list(job["env"]) + [1.0]
background.inputs["Strength"].default_value = 1.0
scene.world = world
scene.render.resolution_x = job["width"]
scene.render.resolution_y = job["height"]
scene.render.resolution_percentage = 100
scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1
# Transparent film: alpha is the model's coverage; the driver adds (1 - alpha) * env,
# which is what an opaque film shows there.
scene.render.film_transparent = True
scene.view_settings.view_transform = "Standard"
scene.view_settings.look = "None"
scene.view_settings.exposure = 0
scene.view_settings.gamma = 1
settings = scene.render.image_settings
settings.file_format = "OPEN_EXR"
settings.color_mode = "RGBA"
settings.color_depth = "32"
settings.exr_codec = "ZIP"

times = {}
for seed in job["seeds"]:
    scene.cycles.seed = seed
    scene.render.filepath = "%s-%d.exr" % (job["out_prefix"], seed)
    start = time.time()
    bpy.ops.render.render(write_still=True)
    times[str(seed)] = time.time() - start
print("CROSSCHECK " + json.dumps({"import_s": import_s, "render_s": times}))
