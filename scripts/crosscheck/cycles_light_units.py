"""What Cycles' light strengths mean: renders a white Lambertian floor, seen from straight
above by an orthographic camera, under one Blender light at a time (direct light only) and
prints the floor's radiance at points 0 to 3 m from below the light against the
prediction for a point source of radiant intensity P / (4 pi) W/sr (point, spot) or an
irradiance of S W/m^2 (sun). The figures are in docs/conventions.md, "Light units".

  blender -b --factory-startup --python scripts/crosscheck/cycles_light_units.py
"""
import math

import bpy
import numpy

SIZE, HEIGHT, POWER, SUN = 81, 2.0, 100.0, 3.0  # pixels, light height (m), W, W/m^2


def render(kind, radius):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    mat = bpy.data.materials.new("white")
    mat.use_nodes = True
    nodes = mat.node_tree.nodes
    nodes.clear()
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (1, 1, 1, 1)
    diffuse.inputs["Roughness"].default_value = 0
    mat.node_tree.links.new(diffuse.outputs[0],
                            nodes.new("ShaderNodeOutputMaterial").inputs["Surface"])
    bpy.ops.mesh.primitive_plane_add(size=20)
    bpy.context.object.data.materials.append(mat)
    if kind == "SUN":
        bpy.ops.object.light_add(type="SUN")
        bpy.context.object.data.energy = SUN
        bpy.context.object.data.angle = 0
    else:
        bpy.ops.object.light_add(type=kind, location=(0, 0, HEIGHT))
        light = bpy.context.object.data
        light.energy = POWER
        light.shadow_soft_size = radius
        if kind == "SPOT":
            light.spot_size = math.radians(120)
            light.spot_blend = 0
    bpy.ops.object.camera_add(location=(0, 0, 10))
    scene.camera = bpy.context.object
    scene.camera.data.type = "ORTHO"
    scene.camera.data.ortho_scale = 8
    scene.render.engine = "CYCLES"
    scene.cycles.samples = 256 if radius > 0 else 16
    scene.cycles.max_bounces = 0
    scene.cycles.use_denoising = False
    scene.cycles.pixel_filter_type = "BOX"
    scene.cycles.filter_width = 1.0
    scene.world = bpy.data.worlds.new("black")
    scene.world.use_nodes = True
    scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0
    scene.render.resolution_x = scene.render.resolution_y = SIZE
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.filepath = "/tmp/cycles_light_units_%s.exr" % kind.lower()
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(scene.render.filepath)
    px = numpy.array(img.pixels[:]).reshape(SIZE, SIZE, 4)
    for i in (40, 50, 60, 70):
        x = (i - 40) * 8 / SIZE
        d = math.hypot(x, HEIGHT)
        predicted = SUN / math.pi if kind == "SUN" else \
            POWER / (4 * math.pi) * (HEIGHT / d) / d ** 2 / math.pi
        print("%-5s radius %.2f  x %.3f m  cos %.4f  cycles %.5f  predicted %.5f  ratio %.4f" % (
            kind, radius, x, HEIGHT / d, px[40, i, 0], predicted, px[40, i, 0] / predicted))


for kind, radius in (("POINT", 0.0), ("POINT", 0.25), ("SPOT", 0.0), ("SUN", 0.0)):
    render(kind, radius)
