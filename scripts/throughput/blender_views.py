"""Blender's side of scripts/throughput/vs_blender.py: imports each glTF file in one
Blender process and renders, with Cycles on the CPU, the views that penumbra's
transforms.json describes, with the passes penumbra wrote (depth, normal, object index).

Run by Blender:  blender -b --factory-startup -P blender_views.py -- JOB.json
JOB.json: assets (list of {scene, transforms, out}), spp, max_depth, threads, env (RGB of
a uniform environment). Settings match penumbra's defaults as cycles_import_render.py
does: no clamping, caustics on, no glossy blur, bounces = max_depth - 1, no denoising, no
adaptive sampling. Prints "THROUGHPUT {json}" with the wall seconds per asset (import and
renders), the assets Blender could not import (skipped, with the reason), and in all.
"""
import json
import math
import os
import sys
import time
import warnings

import bpy
import mathutils
import numpy

# Debian's Blender 3.4 glTF importer still uses numpy.bool, which numpy 1.24 removed.
with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    if not hasattr(numpy, "bool"):
        numpy.bool = bool

job = json.load(open(sys.argv[sys.argv.index("--") + 1]))


def setup(scene, width, height):
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.render.threads_mode = "FIXED"
    scene.render.threads = job["threads"]
    scene.cycles.samples = job["spp"]
    scene.cycles.use_denoising = False
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.sample_clamp_direct = 0
    scene.cycles.sample_clamp_indirect = 0
    depth = max(job["max_depth"] - 1, 0)
    for attr in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces",
                 "volume_bounces"):
        setattr(scene.cycles, attr, depth)
    scene.cycles.transparent_max_bounces = 256
    scene.cycles.caustics_reflective = True
    scene.cycles.caustics_refractive = True
    scene.cycles.blur_glossy = 0
    world = bpy.data.worlds.new("white")
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = list(job["env"]) + [1.0]
    background.inputs["Strength"].default_value = 1.0
    scene.world = world
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    layer = scene.view_layers[0]
    layer.use_pass_z = True
    layer.use_pass_normal = True
    layer.use_pass_object_index = True
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR_MULTILAYER"
    settings.color_depth = "32"


def place_camera(scene, frame, angle_x):
    cam_data = bpy.data.cameras.new("view")
    cam_data.sensor_fit = "HORIZONTAL"
    cam_data.angle = angle_x
    cam = bpy.data.objects.new("view", cam_data)
    scene.collection.objects.link(cam)
    # transforms.json: camera to glTF world, OpenGL camera axes (-Z forward, +Y up), as
    # Blender's cameras; the importer turns glTF's Y-up world into Blender's Z-up one,
    # (x, y, z) -> (x, -z, y): a quarter turn about X.
    y_up_to_z_up = mathutils.Matrix.Rotation(math.radians(90), 4, "X")
    cam.matrix_world = y_up_to_z_up @ mathutils.Matrix(frame["transform_matrix"])
    scene.camera = cam


times, skipped = {}, {}
start_all = time.time()
for asset in job["assets"]:
    start = time.time()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    try:
        bpy.ops.import_scene.gltf(filepath=asset["scene"])
    except Exception as e:  # e.g. meshopt or Draco, which Debian's Blender cannot decode
        skipped[os.path.basename(asset["scene"])] = " ".join(str(e).split())[:200]
        continue
    transforms = json.load(open(asset["transforms"]))
    scene = bpy.context.scene
    first = transforms["frames"][0]
    setup(scene, int(transforms.get("w", first.get("w"))), int(transforms.get("h", first.get("h"))))
    for i, o in enumerate(o for o in bpy.data.objects if o.type == "MESH"):
        o.pass_index = i + 1
    os.makedirs(asset["out"], exist_ok=True)
    for k, frame in enumerate(transforms["frames"]):
        place_camera(scene, frame, frame.get("camera_angle_x", transforms.get("camera_angle_x")))
        scene.render.filepath = os.path.join(asset["out"], "%04d.exr" % k)
        bpy.ops.render.render(write_still=True)
    times[os.path.basename(asset["scene"])] = time.time() - start
print("THROUGHPUT " + json.dumps({"seconds": times, "skipped": skipped,
                                  "total_s": time.time() - start_all}))
