"""Renders the silhouette (alpha) of a glTF file posed by Blender 3.4's own glTF importer at
several animation times, each under the camera penumbra used, for skin_pose.py.

Run by Blender:  blender -b --factory-startup -P skin_pose_blender.py -- JOB.json
JOB.json: scene (a file with at most one animation, so the importer makes it the active
action), spp, threads, renders: [{time (glTF seconds), out (EXR path), width, height,
world_to_camera, world_to_ndc}]. Writes each out as RGBA EXR (alpha: the coverage, box
filter of one pixel) and prints "SKINPOSE {json}" or "SKINPOSE-ERROR message" (exit 2).
"""
import json
import math
import os
import sys
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
    print("SKINPOSE-ERROR " + " ".join(str(message).split()))
    sys.stdout.flush()
    sys.exit(2)


bpy.ops.wm.read_factory_settings(use_empty=True)
try:
    result = bpy.ops.import_scene.gltf(filepath=job["scene"])
except Exception as e:  # the importer reports ImportError as a RuntimeError here
    fail("import failed: %s" % e)
if "FINISHED" not in result:
    fail("import cancelled: %s" % result)

scene = bpy.context.scene
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.render.threads_mode = "FIXED"
scene.render.threads = job["threads"]
scene.cycles.samples = job["spp"]
scene.cycles.use_denoising = False
scene.cycles.use_adaptive_sampling = False
# Coverage only: camera rays, no bounces, no lights needed.
scene.cycles.max_bounces = 0
scene.cycles.transparent_max_bounces = 256
scene.cycles.pixel_filter_type = "BOX"
scene.cycles.filter_width = 1.0
scene.render.film_transparent = True
scene.render.resolution_percentage = 100
scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1
scene.view_settings.view_transform = "Standard"
settings = scene.render.image_settings
settings.file_format = "OPEN_EXR"
settings.color_mode = "RGBA"
settings.color_depth = "32"
settings.exr_codec = "ZIP"

# The importer writes glTF key time t at frame t * fps (its animation_node.py).
fps = scene.render.fps / scene.render.fps_base
done = []
for r in job["renders"]:
    frame = r["time"] * fps
    whole = math.floor(frame)
    scene.frame_set(int(whole), subframe=frame - whole)
    set_camera(scene, r["world_to_camera"], r["world_to_ndc"])
    scene.render.resolution_x = r["width"]
    scene.render.resolution_y = r["height"]
    scene.render.filepath = r["out"]
    bpy.ops.render.render(write_still=True)
    done.append(r["out"])
print("SKINPOSE " + json.dumps({"written": done}))
