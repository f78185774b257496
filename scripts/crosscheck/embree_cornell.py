#!/usr/bin/env python3
"""Writes Embree's own tutorial scene as glTF, so that penumbra and Embree 3's `pathtracer`
tutorial can be timed on the same geometry, materials and light (the equal-spp
comparison): the OBJ that /usr/share/doc/embree3/models/cornell_box.ecs names (Debian's
embree-tools), its point light and its camera.

  python3 scripts/crosscheck/embree_cornell.py /tmp/embree-cornell.gltf

- Geometry: the OBJ's polygons (fan-triangulated), one glTF primitive per `usemtl`, no
  normals (flat, as the tutorial shades them). Millimetres become metres.
- Materials: each `Kd` as an exactly Lambertian glTF material (metallic 0,
  KHR_materials_specular factor 0; the OBJ's Ks are all 0). The tutorial treats the
  "light" material's Ka as nothing (it is an ordinary white quad), and so does this.
- Light: the ecs's `-pointlight x y z I I I` (intensity in the OBJ's units, mm^2 W/sr
  per its 1/d^2 falloff) at I x 1e-6 W/sr in metres, written photometrically.
- Camera: `-vp`, `-vi`, `-vu`, `-fov` (vertical, degrees) as a glTF perspective camera.
The file is generated where asked (into /tmp in the harness); the OBJ stays in Debian's
package (Apache 2.0, Intel's Embree) and is not copied into the repository.
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gltf_builder import Builder, buffers, photometric  # noqa: E402

ECS = "/usr/share/doc/embree3/models/cornell_box.ecs"
MM = 1e-3  # OBJ units (mm) to metres


def parse_ecs(path):
    words = open(path).read().split()
    opts, i = {}, 0
    while i < len(words):
        w = words[i]
        if w == "-i":
            opts["obj"], i = words[i + 1], i + 2
        elif w == "-pointlight":
            opts["light"], i = [float(x) for x in words[i + 1:i + 7]], i + 7
        elif w in ("-vp", "-vi", "-vu"):
            opts[w[1:]], i = [float(x) for x in words[i + 1:i + 4]], i + 4
        elif w == "-fov":
            opts["fov"], i = float(words[i + 1]), i + 2
        else:
            raise ValueError("%s: unknown option %s" % (path, w))
    return opts


def parse_mtl(path):
    kd, name = {}, None
    for line in open(path):
        f = line.split()
        if not f:
            continue
        if f[0] == "newmtl":
            name = f[1]
        elif f[0] == "Kd":
            kd[name] = [float(x) for x in f[1:4]]
    return kd


def parse_obj(path):
    """(Kd per material, {material: list of triangles of 3 positions in metres})."""
    verts, groups, kd, current = [], {}, {}, None
    for line in open(path):
        f = line.split()
        if not f:
            continue
        if f[0] == "mtllib":
            kd = parse_mtl(os.path.join(os.path.dirname(path), f[1]))
        elif f[0] == "v":
            verts.append([float(x) * MM for x in f[1:4]])
        elif f[0] == "usemtl":
            current = f[1]
        elif f[0] == "f":
            idx = [int(x.split("/")[0]) for x in f[1:]]
            idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
            for k in range(1, len(idx) - 1):
                groups.setdefault(current, []).append(
                    [verts[idx[0]], verts[idx[k]], verts[idx[k + 1]]])
    return kd, groups


def look_at_rotation(eye, target, up):
    """Unit quaternion (x, y, z, w) turning glTF's camera (looking down -Z, +Y up) to look
    from eye at target."""
    f = [t - e for t, e in zip(target, eye)]
    n = math.sqrt(sum(c * c for c in f))
    z = [-c / n for c in f]  # the camera's +Z points away from the view
    x = [up[1] * z[2] - up[2] * z[1], up[2] * z[0] - up[0] * z[2], up[0] * z[1] - up[1] * z[0]]
    n = math.sqrt(sum(c * c for c in x))
    x = [c / n for c in x]
    y = [z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]]
    m = [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]
    tr = m[0][0] + m[1][1] + m[2][2]
    if tr > 0:
        s = math.sqrt(tr + 1) * 2
        return [(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, s / 4]
    i = max(range(3), key=lambda k: m[k][k])
    j, k = (i + 1) % 3, (i + 2) % 3
    s = math.sqrt(1 + m[i][i] - m[j][j] - m[k][k]) * 2
    q = [0.0, 0.0, 0.0, (m[k][j] - m[j][k]) / s]
    q[i] = s / 4
    q[j] = (m[j][i] + m[i][j]) / s
    q[k] = (m[k][i] + m[i][k]) / s
    return q


def scene(ecs=ECS):
    opts = parse_ecs(ecs)
    kd, groups = parse_obj(os.path.join(os.path.dirname(ecs), opts["obj"]))
    b = Builder()
    materials, primitives = [], []
    for name, tris in groups.items():
        materials.append({"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": kd.get(name, [1, 1, 1]) + [1.0], "metallicFactor": 0.0,
            "roughnessFactor": 1.0}, "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}})
        pos = [p for t in tris for p in t]
        primitives.append({"attributes": {"POSITION": b.vec3(pos)},
                           "indices": b.indices32(list(range(len(pos)))),
                           "material": len(materials) - 1})
    light = opts["light"]
    eye = [c * MM for c in opts["vp"]]
    return {
        "asset": {"version": "2.0", "generator": "penumbra scripts/crosscheck/embree_cornell.py"},
        "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_specular"],
        "scene": 0,
        "scenes": [{"name": "embree-cornell-box", "nodes": [0, 1, 2]}],
        "nodes": [
            {"name": "camera", "camera": 0, "translation": eye,
             "rotation": look_at_rotation(eye, [c * MM for c in opts["vi"]], opts["vu"])},
            {"name": "cornell_box", "mesh": 0},
            {"name": "point-light", "translation": [c * MM for c in light[:3]],
             "extensions": {"KHR_lights_punctual": {"light": 0}}},
        ],
        "cameras": [{"name": "tutorial", "type": "perspective", "perspective": {
            "yfov": math.radians(opts["fov"]), "aspectRatio": 1.0, "znear": 0.01}}],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "pointlight", "type": "point", "color": [1.0, 1.0, 1.0],
             "intensity": photometric(light[3] * MM * MM)}]}},
        "materials": materials,
        "meshes": [{"name": "cornell_box", "primitives": primitives}],
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": buffers(b),
    }


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: embree_cornell.py OUT.gltf")
    with open(sys.argv[1], "w") as f:
        json.dump(scene(), f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
