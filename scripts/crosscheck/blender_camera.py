"""Blender's camera for penumbra's: rebuilt from the matrices penumbra writes into its EXR
header, for the scripts Blender runs (cycles_import_render.py, skin_pose_blender.py)."""
import math

import bpy
from mathutils import Matrix


def matrix(rows):
    """OpenEXR stores row-vector matrices (p' = p M); mathutils multiplies columns."""
    return Matrix([rows[0:4], rows[4:8], rows[8:12], rows[12:16]]).transposed()


def set_camera(scene, world_to_camera, world_to_ndc, name="crosscheck"):
    """Makes (or updates) the scene's camera `name` from penumbra's header matrices
    (worldToCamera, worldToNDC: rows of OpenEXR's row-vector matrices)."""
    # penumbra's header: worldToCamera maps to a left-handed camera space (+Z forward), so
    # camera-to-world of a glTF/Blender camera (-Z forward, +Y up) is inverse(W) * flip(z).
    # The importer turns glTF's +Y up into Blender's +Z up: (x, y, z) -> (x, -z, y).
    w2c = matrix(world_to_camera)
    proj = matrix(world_to_ndc) @ w2c.inverted()
    flip = Matrix.Diagonal((1, 1, -1, 1))
    y_up_to_z_up = Matrix(((1, 0, 0, 0), (0, 0, -1, 0), (0, 1, 0, 0), (0, 0, 0, 1)))
    obj = bpy.data.objects.get(name)
    if obj is None:
        obj = bpy.data.objects.new(name, bpy.data.cameras.new(name))
        scene.collection.objects.link(obj)
    cam = obj.data
    obj.matrix_world = y_up_to_z_up @ w2c.inverted() @ flip
    cam.sensor_fit = "VERTICAL"  # penumbra keeps the vertical extent (camera_matrices.h)
    cam.dof.use_dof = False
    if abs(proj[3][3]) > 0.5:  # orthographic: y_ndc = 0.5 - 0.5 y / ymag
        cam.type = "ORTHO"
        cam.ortho_scale = 2 * 0.5 / abs(proj[1][1])
        near = -proj[2][3] / proj[2][2]
        far = near + 1 / proj[2][2] if proj[2][2] != 1 else 1e6
    else:  # perspective: y_ndc = 0.5 - 0.5 y / (z tan(yfov / 2))
        cam.type = "PERSP"
        cam.angle_y = 2 * math.atan(0.5 / abs(proj[1][1]))
        if abs(proj[2][2] - 1) < 1e-6:  # infinite far plane: z_ndc = 1 - n / z
            near, far = -proj[2][3], 1e6
        else:
            near = -proj[2][3] / proj[2][2]
            far = proj[2][2] * near / (proj[2][2] - 1)
    cam.clip_start = max(near, 1e-6)
    cam.clip_end = far
    scene.camera = obj
    return obj
