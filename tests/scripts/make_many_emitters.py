#!/usr/bin/env python3
"""Writes many-emitters.gltf: a grey room (floor, back and side walls, two boxes) lit only
by N small emissive triangles (default 10,000) scattered over a dome above it, each facing
the room's centre (single-sided), with 32 emission levels from 0.1 to 50 (log-uniform,
KHR_materials_emissive_strength) and slightly varied colours. No punctual lights, no
environment: every pixel's light comes through next-event estimation of the triangles or
BSDF rays hitting them, the case a light BVH exists for (issue 14, light sampling).

What to expect: a softly lit room; every emitter is about equally far from every point, so
choosing by power is already close to what a light BVH does (docs/performance.md).

With --layout hall it writes many-emitters-hall.gltf instead: a hall 4 m wide and 32 m
long whose ceiling holds the N triangles (facing down), seen along its length, where each
point is lit mostly by the few emitters above it: the case where choosing by power wastes
most samples on lights far away.

Usage: tests/scripts/make_many_emitters.py OUT_DIR [--count N] [--seed S] [--layout hall], then
       build/bin/penumbra render OUT_DIR/many-emitters.gltf --width 256 --height 256 --spp 16
The output is deterministic for a given count and seed.
"""
import base64
import json
import math
import os
import random
import struct
import sys

LEVELS = 32


def box(cx, cz, sx, sy, sz):
    """Outward-wound triangles of an axis-aligned box standing on y = 0."""
    x0, x1, y0, y1, z0, z1 = cx - sx, cx + sx, 0.0, sy, cz - sz, cz + sz
    c = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 4, 7, 3), (1, 2, 6, 5), (3, 7, 6, 2), (0, 1, 5, 4)]
    tris = []
    for a, b, d, e in faces:
        tris += [(c[a], c[b], c[d]), (c[a], c[d], c[e])]
    return tris


def room():
    s = 2.0
    quads = [
        [(-s, 0, -s), (-s, 0, s), (s, 0, s), (s, 0, -s)],        # floor, facing +y
        [(-s, 0, -s), (s, 0, -s), (s, 2 * s, -s), (-s, 2 * s, -s)],  # back wall, +z
        [(-s, 0, -s), (-s, 2 * s, -s), (-s, 2 * s, s), (-s, 0, s)],  # left wall, +x
        [(s, 0, -s), (s, 0, s), (s, 2 * s, s), (s, 2 * s, -s)],    # right wall, -x
    ]
    tris = []
    for q in quads:
        tris += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
    tris += box(-0.7, -0.3, 0.45, 1.2, 0.45) + box(0.8, 0.6, 0.4, 0.6, 0.4)
    return tris


def emitters(count, rng):
    """count small triangles on a dome of radius 3 around (0, 1, 0), facing its centre."""
    centre = (0.0, 1.0, 0.0)
    per_level = [[] for _ in range(LEVELS)]
    for i in range(count):
        # Uniform over the upper part of the sphere (y above the room's mid-height).
        z = rng.uniform(0.15, 1.0)
        phi = rng.uniform(0, 2 * math.pi)
        r = math.sqrt(1 - z * z)
        d = (r * math.cos(phi), z, r * math.sin(phi))
        p = tuple(centre[k] + 3.0 * d[k] for k in range(3))
        # A tangent frame and a random triangle of about 0.02 to 0.08 in size.
        t = (-d[2], 0.0, d[0]) if abs(d[1]) < 0.99 else (1.0, 0.0, 0.0)
        tl = math.sqrt(sum(x * x for x in t))
        t = tuple(x / tl for x in t)
        b = (d[1] * t[2] - d[2] * t[1], d[2] * t[0] - d[0] * t[2], d[0] * t[1] - d[1] * t[0])
        size = rng.uniform(0.02, 0.08)
        verts = []
        for k in range(3):
            a = rng.uniform(0, 2 * math.pi / 3) + k * 2 * math.pi / 3
            verts.append(tuple(p[j] + size * (math.cos(a) * t[j] + math.sin(a) * b[j])
                               for j in range(3)))
        # Front face (counter-clockwise) towards the centre, i.e. along -d.
        e1 = [verts[1][j] - verts[0][j] for j in range(3)]
        e2 = [verts[2][j] - verts[0][j] for j in range(3)]
        n = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
             e1[0] * e2[1] - e1[1] * e2[0])
        if sum(n[j] * d[j] for j in range(3)) > 0:
            verts[1], verts[2] = verts[2], verts[1]
        per_level[rng.randrange(LEVELS)].append(tuple(verts))
    return per_level


def hall():
    """Floor, side walls and an end wall of a 4 x 3 x 32 m hall along -z, facing inwards."""
    x0, x1, y1, z0, z1 = -2.0, 2.0, 3.0, -30.0, 2.0
    quads = [
        [(x0, 0, z0), (x0, 0, z1), (x1, 0, z1), (x1, 0, z0)],      # floor, +y
        [(x0, 0, z0), (x0, y1, z0), (x0, y1, z1), (x0, 0, z1)],    # left wall, +x
        [(x1, 0, z0), (x1, 0, z1), (x1, y1, z1), (x1, y1, z0)],    # right wall, -x
        [(x0, 0, z0), (x1, 0, z0), (x1, y1, z0), (x0, y1, z0)],    # end wall, +z
    ]
    tris = []
    for q in quads:
        tris += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
    for k in range(6):  # pillars of boxes down the hall
        tris += box(-1.2 if k % 2 else 1.2, -3.0 - 4.5 * k, 0.25, 1.5, 0.25)
    return tris


def hall_emitters(count, rng):
    """count small triangles just under the hall's ceiling, facing down."""
    per_level = [[] for _ in range(LEVELS)]
    for i in range(count):
        cx, cz = rng.uniform(-1.9, 1.9), rng.uniform(-29.9, 1.9)
        size = rng.uniform(0.02, 0.06)
        a0 = rng.uniform(0, 2 * math.pi)
        verts = [(cx + size * math.cos(a0 + k * 2.1), 2.95, cz + size * math.sin(a0 + k * 2.1))
                 for k in range(3)]
        # Front face (counter-clockwise seen from below) towards -y.
        e1 = [verts[1][j] - verts[0][j] for j in range(3)]
        e2 = [verts[2][j] - verts[0][j] for j in range(3)]
        if e1[2] * e2[0] - e1[0] * e2[2] > 0:
            verts[1], verts[2] = verts[2], verts[1]
        per_level[rng.randrange(LEVELS)].append(tuple(verts))
    return per_level


def main():
    args = sys.argv[1:]
    if not args or args[0].startswith("-"):
        sys.exit(__doc__)
    out_dir = args[0]
    count = int(args[args.index("--count") + 1]) if "--count" in args else 10000
    seed = int(args[args.index("--seed") + 1]) if "--seed" in args else 1
    is_hall = "--layout" in args and args[args.index("--layout") + 1] == "hall"
    rng = random.Random(seed)

    blob = bytearray()
    accessors, views, meshes_prims = [], [], []

    def add_triangles(tris, material):
        pos = [v for tri in tris for v in tri]
        lo = [min(p[k] for p in pos) for k in range(3)]
        hi = [max(p[k] for p in pos) for k in range(3)]
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": 12 * len(pos),
                      "target": 34962})
        for p in pos:
            blob.extend(struct.pack("<3f", *p))
        accessors.append({"bufferView": len(views) - 1, "componentType": 5126,
                          "count": len(pos), "type": "VEC3", "min": lo, "max": hi})
        meshes_prims.append({"attributes": {"POSITION": len(accessors) - 1},
                             "material": material})

    materials = [{"name": "grey", "pbrMetallicRoughness": {
        "baseColorFactor": [0.7, 0.7, 0.7, 1], "metallicFactor": 0, "roughnessFactor": 1}}]
    add_triangles(hall() if is_hall else room(), 0)
    for level, tris in enumerate((hall_emitters if is_hall else emitters)(count, rng)):
        if not tris:
            continue
        strength = 0.1 * (500 ** (level / (LEVELS - 1)))
        tint = [0.8 + 0.2 * rng.random(), 0.8 + 0.2 * rng.random(), 0.8 + 0.2 * rng.random()]
        materials.append({
            "name": "emitter-%d" % level,
            "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0},
            "emissiveFactor": tint,
            "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": strength}}})
        add_triangles(tris, len(materials) - 1)

    gltf = {
        "asset": {"version": "2.0", "generator": "tests/scripts/make_many_emitters.py"},
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0},
                  {"camera": 0, "translation": [0, 1.5, 1.8] if is_hall else [0, 1.6, 5.2],
                   # The hall looks down at the floor: no emitter in view, so the error
                   # is that of the light they cast.
                   "rotation": [-0.2588, 0, 0, 0.9659] if is_hall else [-0.06, 0, 0, 0.998]}],
        "cameras": [{"type": "perspective", "perspective": {
            "yfov": 0.75, "aspectRatio": 1.0, "znear": 0.01, "zfar": 100}}],
        "meshes": [{"name": "room-and-emitters", "primitives": meshes_prims}],
        "materials": materials,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64," +
                     base64.b64encode(bytes(blob)).decode()}],
    }
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, "many-emitters-hall.gltf" if is_hall else "many-emitters.gltf")
    with open(path, "w") as f:
        json.dump(gltf, f)
    print("%s: %d emissive triangles in %d levels" % (path, count, len(materials) - 1))


if __name__ == "__main__":
    main()
