"""Writes scenes/skinned-tubes.gltf: two tubes bent by animated joint chains, for the
skinning rules (docs/conventions.md, "Skins") and scripts/crosscheck/skin_pose.py.

- One tube mesh (radius 0.2, 3 m along +Y, with normals), drawn by two nodes with two
  skins: several nodes referencing one skinned mesh.
- Each vertex blends the two joints nearest along the tube, the first in WEIGHTS_0 and the
  second in WEIGHTS_1, both scaled by 0.9 (weights summing to 0.9, as CesiumMan's do):
  normalised over every set they pose as with sum 1.
- A morph target bulges the tube's middle; its weight is animated 0 -> 1 -> 0 (morph
  before skin).
- Each skin's root joint hangs under a node that moves along X (an animated parent of the
  joints); the mesh nodes sit under a node that moves along Z and carry a translation of
  their own, both of which skinning ignores (glTF 2.0, 3.7.3.3).
- The joints rotate about Z with LINEAR keys 0.5 s apart, 40 degrees at most between keys:
  at a key and half-way between keys, slerp (penumbra) and a renormalised component lerp
  (Blender's f-curves) give the same rotation.
"""
import json
import math
import os
import struct

from gltf_builder import Builder, buffers

RINGS, SEGMENTS, RADIUS, LENGTH = 24, 16, 0.2, 3.0
JOINT_Y = [0.0, 1.0, 2.0]  # bind positions of the three joints along the tube
KEY_TIMES = [0.0, 0.5, 1.0, 1.5, 2.0]


def scalars(b, values):
    data = struct.pack("<%df" % len(values), *values)
    view = b._view(data, None)
    b.accessors.append({"bufferView": view, "componentType": 5126, "count": len(values),
                        "type": "SCALAR", "min": [min(values)], "max": [max(values)]})
    return len(b.accessors) - 1


def plain(b, values, kind, ctype=5126, fmt="f", normalized=False):
    n = {"VEC3": 3, "VEC4": 4, "MAT4": 16}[kind]
    data = b"".join(struct.pack("<%d%s" % (n, fmt), *v) for v in values)
    a = {"bufferView": b._view(data, None), "componentType": ctype, "count": len(values),
         "type": kind}
    if kind == "VEC3":
        a["min"] = [min(v[i] for v in values) for i in range(3)]
        a["max"] = [max(v[i] for v in values) for i in range(3)]
    if normalized:
        a["normalized"] = True
    b.accessors.append(a)
    return len(b.accessors) - 1


def z_quat(deg):
    h = math.radians(deg) / 2
    return [0.0, 0.0, math.sin(h), math.cos(h)]


def tube():
    pos, nrm, idx, joints0, joints1, w0, w1, bulge = [], [], [], [], [], [], [], []
    for r in range(RINGS + 1):
        y = LENGTH * r / RINGS
        # The two joints around y and the blend between them (the last span is joint 2's).
        k = min(int(y), 1)
        t = min(max(y - JOINT_Y[k], 0.0), 1.0)
        a, wa = (k, 1 - t) if y < 2 else (2, 1.0)
        c, wc = (k + 1, t) if y < 2 else (1, 0.0)
        swell = math.exp(-((y - 1.5) / 0.35) ** 2) * 0.15
        for s in range(SEGMENTS + 1):
            phi = 2 * math.pi * s / SEGMENTS
            n = [math.cos(phi), 0.0, -math.sin(phi)]
            pos.append([RADIUS * n[0], y, RADIUS * n[2]])
            nrm.append(n)
            bulge.append([swell * n[0], 0.0, swell * n[2]])
            joints0.append([a, 0, 0, 0])
            joints1.append([c if wc > 0 else 0, 0, 0, 0])
            w0.append([0.9 * wa, 0.0, 0.0, 0.0])
            w1.append([0.9 * wc, 0.0, 0.0, 0.0])
    for r in range(RINGS):
        for s in range(SEGMENTS):
            p = r * (SEGMENTS + 1) + s
            q = p + SEGMENTS + 1
            idx += [p, p + 1, q, p + 1, q + 1, q]
    return pos, nrm, idx, joints0, joints1, w0, w1, bulge


def main():
    b = Builder()
    pos, nrm, idx, joints0, joints1, w0, w1, bulge = tube()
    attributes = {"POSITION": b.vec3(pos), "NORMAL": b.vec3(nrm),
                  "JOINTS_0": plain(b, joints0, "VEC4", 5121, "B"),
                  "JOINTS_1": plain(b, joints1, "VEC4", 5121, "B"),
                  "WEIGHTS_0": plain(b, w0, "VEC4"), "WEIGHTS_1": plain(b, w1, "VEC4")}
    mesh = {"name": "tube", "primitives": [{"attributes": attributes, "indices": b.indices(idx),
                                            "material": 0,
                                            "targets": [{"POSITION": plain(b, bulge, "VEC3")}]}],
            "weights": [0.0]}
    # Inverse bind matrices: joint j sits at world y = JOINT_Y[j] in the bind pose (the
    # joints' parents at the origin), so its inverse is a translation by -y (column-major).
    ibm = plain(b, [[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -y, 0, 1] for y in JOINT_Y], "MAT4")

    times = scalars(b, KEY_TIMES)
    # Node layout: 0 "mesh carrier" (moves along Z, ignored by skinning), 1 and 2 the
    # skinned mesh nodes; then per rig: a mover (along X) and three joints.
    nodes = [{"name": "mesh carrier", "children": [1, 2]},
             {"name": "tube A", "mesh": 0, "skin": 0, "translation": [5.0, 0.0, 0.0]},
             {"name": "tube B", "mesh": 0, "skin": 1, "translation": [0.0, -3.0, 0.0]}]
    channels, samplers = [], []

    def animate(node, path, values, kind):
        samplers.append({"input": times, "output": plain(b, values, kind) if kind != "SCALAR"
                         else scalars(b, values), "interpolation": "LINEAR"})
        channels.append({"sampler": len(samplers) - 1, "target": {"node": node, "path": path}})

    animate(0, "translation", [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 0, 1], [0, 0, 0]], "VEC3")
    animate(1, "weights", [0.0, 0.5, 1.0, 0.5, 0.0], "SCALAR")
    skins = []
    rigs = [("A", -0.8, [0, 30, 60, 30, -10], [0, -40, -20, 20, 40]),
            ("B", 0.8, [0, -30, -50, -20, 0], [0, 40, 0, -40, 0])]
    for name, x, bend1, bend2 in rigs:
        mover = len(nodes)
        j0, j1, j2 = mover + 1, mover + 2, mover + 3
        nodes.append({"name": "mover " + name, "translation": [x, 0, 0], "children": [j0]})
        nodes.append({"name": name + "0", "children": [j1]})
        nodes.append({"name": name + "1", "translation": [0, 1, 0], "children": [j2]})
        nodes.append({"name": name + "2", "translation": [0, 1, 0]})
        animate(mover, "translation", [[x + 0.3 * math.sin(t * 2), 0, 0] for t in KEY_TIMES],
                "VEC3")
        animate(j1, "rotation", [z_quat(d) for d in bend1], "VEC4")
        animate(j2, "rotation", [z_quat(d) for d in bend2], "VEC4")
        skins.append({"name": "rig " + name, "joints": [j0, j1, j2], "skeleton": mover,
                      "inverseBindMatrices": ibm})
    # Node B's mesh reads morph weight 0 (mesh.weights); node A's is animated.
    gltf = {
        "asset": {"version": "2.0", "generator": "scripts/make_skinned_scenes.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 3, 7]}],
        "nodes": nodes,
        "meshes": [mesh],
        "skins": skins,
        "materials": [{"name": "tube", "pbrMetallicRoughness": {
            "baseColorFactor": [0.8, 0.6, 0.3, 1], "metallicFactor": 0, "roughnessFactor": 0.6}}],
        "animations": [{"name": "bend", "samplers": samplers, "channels": channels}],
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": buffers(b),
    }
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes",
                       "skinned-tubes.gltf")
    with open(out, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")
    print("wrote", os.path.normpath(out))


if __name__ == "__main__":
    main()
