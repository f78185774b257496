"""Writes scenes/motion-blur.gltf: objects animated in glTF for motion blur. Over the
2 s animation a red cube translates along X (LINEAR), a blue bar spins once about Y
(LINEAR rotation keys 90 degrees apart, slerped), a green sphere squashes and recovers
through a morph target (animated weights), and the camera dollies in with an ease
(CUBICSPLINE, zero tangents). A grey floor and a directional light stay still."""
import json
import math
import struct

from gltf_builder import Builder, buffers, photometric, quad, unit_cube, uv_sphere


def scalars(b, values):
    data = struct.pack("<%df" % len(values), *values)
    view = b._view(data, None)
    b.accessors.append({"bufferView": view, "componentType": 5126, "count": len(values),
                        "type": "SCALAR", "min": [min(values)], "max": [max(values)]})
    return len(b.accessors) - 1


def vec3_plain(b, values):
    """VEC3 floats without a vertex-buffer target (animation outputs, morph offsets)."""
    data = b"".join(struct.pack("<3f", *v) for v in values)
    view = b._view(data, None)
    b.accessors.append({"bufferView": view, "componentType": 5126, "count": len(values),
                        "type": "VEC3", "min": [min(v[i] for v in values) for i in range(3)],
                        "max": [max(v[i] for v in values) for i in range(3)]})
    return len(b.accessors) - 1


def y_quat(deg):
    h = math.radians(deg) / 2
    return [0.0, math.sin(h), 0.0, math.cos(h)]


def sun_rotation():
    ax, ay = math.radians(-50.0) / 2, math.radians(30.0) / 2
    qx = [math.sin(ax), 0.0, 0.0, math.cos(ax)]
    qy = [0.0, math.sin(ay), 0.0, math.cos(ay)]
    # Hamilton product qy * qx (x, y, z, w).
    x1, y1, z1, w1 = qy
    x2, y2, z2, w2 = qx
    return [w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2, w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
            w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2, w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2]


def scene():
    b = Builder()
    floor = quad([[-6, 0, -6], [-6, 0, 6], [6, 0, 6], [6, 0, -6]], [0, 1, 0])
    cube = unit_cube()
    sphere_pos, sphere_nrm, sphere_idx = uv_sphere(16, 32)
    # Morph target: squash to half height and widen by 30 %, sitting on the floor
    # (the sphere's centre is at y = 1, its bottom at 0 stays put).
    squash = [[0.3 * p[0], -0.5 * (p[1] + 1.0), 0.3 * p[2]] for p in sphere_pos]
    sphere_prim = b.primitive(sphere_pos, sphere_nrm, sphere_idx, 3)
    sphere_prim["targets"] = [{"POSITION": vec3_plain(b, squash)}]

    meshes = [
        {"name": "floor", "primitives": [b.primitive(*floor, 0)]},
        {"name": "cube", "primitives": [b.primitive(*cube, 1)]},
        {"name": "bar", "primitives": [b.primitive(*cube, 2)]},
        {"name": "sphere", "primitives": [sphere_prim], "weights": [0.0]},
    ]

    times = scalars(b, [0.0, 2.0])
    quarter_times = scalars(b, [0.0, 0.5, 1.0, 1.5, 2.0])
    morph_times = scalars(b, [0.0, 1.0, 2.0])
    cube_path = vec3_plain(b, [[-2.0, 0.5, 0.8], [2.0, 0.5, 0.8]])
    spin = b.vec4([y_quat(90.0 * k) for k in range(5)])
    squash_weights = scalars(b, [0.0, 1.0, 0.0])
    # CUBICSPLINE keys: (in-tangent, value, out-tangent); zero tangents ease in and out.
    dolly = vec3_plain(b, [[0, 0, 0], [0.0, 2.2, 7.5], [0, 0, 0],
                           [0, 0, 0], [0.6, 2.0, 6.5], [0, 0, 0]])

    samplers = [
        {"input": times, "output": cube_path, "interpolation": "LINEAR"},
        {"input": quarter_times, "output": spin, "interpolation": "LINEAR"},
        {"input": morph_times, "output": squash_weights, "interpolation": "LINEAR"},
        {"input": times, "output": dolly, "interpolation": "CUBICSPLINE"},
    ]
    channels = [
        {"sampler": 0, "target": {"node": 2, "path": "translation"}},
        {"sampler": 1, "target": {"node": 3, "path": "rotation"}},
        {"sampler": 2, "target": {"node": 4, "path": "weights"}},
        {"sampler": 3, "target": {"node": 0, "path": "translation"}},
    ]
    tilt = -math.radians(12.0) / 2
    nodes = [
        {"name": "camera", "camera": 0, "translation": [0.0, 2.2, 7.5],
         "rotation": [math.sin(tilt), 0.0, 0.0, math.cos(tilt)]},
        {"name": "floor", "mesh": 0},
        {"name": "sliding-cube", "mesh": 1, "translation": [-2.0, 0.5, 0.8]},
        {"name": "spinning-bar", "mesh": 2, "translation": [-2.4, 0.25, -2.0],
         "scale": [2.0, 0.3, 0.3]},
        # uv_sphere is centred at the origin: lift it by its scaled radius onto the floor.
        {"name": "squashing-sphere", "mesh": 3, "translation": [1.6, 0.8, -1.0],
         "scale": [0.8, 0.8, 0.8]},
        # Light along -Z turned 50 degrees down about X, then 30 degrees about Y.
        {"name": "sun", "rotation": sun_rotation(),
         "extensions": {"KHR_lights_punctual": {"light": 0}}},
    ]
    materials = [
        {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1],
                                                   "metallicFactor": 0, "roughnessFactor": 0.8}},
        {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.08, 1],
                                                 "metallicFactor": 0, "roughnessFactor": 0.5}},
        {"name": "blue", "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.2, 0.8, 1],
                                                  "metallicFactor": 0, "roughnessFactor": 0.5}},
        {"name": "green", "pbrMetallicRoughness": {"baseColorFactor": [0.15, 0.7, 0.2, 1],
                                                   "metallicFactor": 0, "roughnessFactor": 0.4}},
    ]
    return {
        "asset": {"version": "2.0", "generator": "penumbra scripts/make_motion_blur.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "sun", "type": "directional", "intensity": photometric(3.0)}]}},
        "scene": 0,
        "scenes": [{"name": "motion-blur", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"name": "dolly", "type": "perspective",
                     "perspective": {"yfov": 0.7, "aspectRatio": 1.5, "znear": 0.05}}],
        "materials": materials,
        "meshes": meshes,
        "animations": [{"name": "motion", "samplers": samplers, "channels": channels}],
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": buffers(b),
    }


def main():
    with open("scenes/motion-blur.gltf", "w") as f:
        json.dump(scene(), f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
