#!/usr/bin/env python3
"""Writes a scene lit by many small emissive triangles (default 10,000), for many-light
sampling (the light BVH) and the efficiency harness (scripts/crosscheck/efficiency.py).
No punctual lights, no environment: all light comes from the triangles.

--layout cloud (default; the harness's many-lights):
- Floor: a 12 x 12 m Lambertian quad (albedo 0.6) at y = 0; on it a grey cube, a red and a
  blue sphere (all Lambertian: metallic 0, KHR_materials_specular factor 0).
- Emitters: COUNT triangles of side 4 cm, random positions in the slab
  |x|, |z| < 4.5 m, 2.4 m < y < 3.6 m, random orientations, double-sided (so penumbra and
  Cycles, whose emission is two-sided, agree). Their emission varies over 64 materials:
  8 hues x 8 strengths log-spaced from 0.5 to 50 (KHR_materials_emissive_strength), so
  the triangles' powers span 100x and sampling by power pays.
- Camera "view": from (0, 1.6, 7), looking 8 degrees down, yfov 0.75, square.

--layout dome: a grey room (floor, back and side walls, two boxes; glTF-BRDF albedo 0.7)
under COUNT single-sided triangles of 2-8 cm on a dome of radius 3 m, each facing the
room's centre, with 32 emission levels log-spaced from 0.1 to 50 and slightly varied
tints. Every emitter is about equally far from every point, so choosing by power is
already close to what a light BVH does (docs/performance.md, "Light sampling at scale").

--layout hall: a hall 4 m wide and 32 m long (floor, side walls, an end wall, six pillars)
whose ceiling holds the COUNT triangles (facing down, the same 32 levels), seen looking
down at the floor, so no emitter is in view: each point is lit mostly by the few emitters
above it, the case where choosing by power wastes most samples on lights far away.

Deterministic: Python's random.Random(SEED) (Mersenne Twister, whose output for a given seed
Python keeps stable across versions) and fixed float formatting give byte-identical files.

  python3 scripts/make_many_lights.py OUT.gltf [--layout cloud|dome|hall] [--count 10000]
      [--seed 1]
  build/bin/penumbra render OUT.gltf --width 256 --spp 16
"""
import argparse
import colorsys
import json
import math
import random
import sys

from gltf_builder import Builder, buffers, quad, unit_cube, uv_sphere

HUES = 8
STRENGTHS = 8
SIDE = 0.04  # cloud emitter triangle side, metres
LEVELS = 32  # dome and hall emission levels


def log_level(lo, ratio, k, n):
    """The k-th of n emission strengths log-spaced from lo to lo x ratio."""
    return lo * ratio ** (k / (n - 1))


def emissive(name, rgb, strength, double_sided, int_zeros=False):
    """A black, non-metallic material emitting rgb x strength; the dome and hall have always
    written their zeros as integers, kept so that their files stay byte-identical."""
    black = {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0} if int_zeros else \
        {"baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0}
    m = {"name": name, "pbrMetallicRoughness": black, "emissiveFactor": rgb}
    if double_sided:
        m["doubleSided"] = True
    m["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": strength}}
    return m


def random_unit(rng):
    z = 2 * rng.random() - 1
    phi = 2 * math.pi * rng.random()
    r = math.sqrt(max(0.0, 1 - z * z))
    return [r * math.cos(phi), r * math.sin(phi), z]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


# The cloud: indexed triangles with normals, double-sided, Lambertian receivers.

def lambertian(name, color):
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": color + [1.0],
                                                   "metallicFactor": 0.0, "roughnessFactor": 1.0},
            "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}


def cloud_materials():
    out = []
    for h in range(HUES):
        rgb = list(colorsys.hsv_to_rgb(h / HUES, 0.6, 1.0))
        for s in range(STRENGTHS):
            strength = log_level(0.5, 100.0, s, STRENGTHS)  # 0.5 .. 50
            out.append(emissive("emitter-h%d-s%d" % (h, s), [round(c, 6) for c in rgb],
                                round(strength, 6), True))
    return out


def cloud_triangles(count, seed):
    """Per material, (positions, normals, indices) of its triangles: equilateral of side
    SIDE around a random centre in the slab, in a random plane."""
    rng = random.Random(seed)
    groups = [([], [], []) for _ in range(HUES * STRENGTHS)]
    for _ in range(count):
        c = [rng.uniform(-4.5, 4.5), rng.uniform(2.4, 3.6), rng.uniform(-4.5, 4.5)]
        n = random_unit(rng)
        helper = [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0]
        t = normalize(cross(n, helper))
        b = cross(n, t)
        spin = 2 * math.pi * rng.random()
        radius = SIDE / math.sqrt(3)  # circumradius of an equilateral triangle
        pos, nrm, idx = groups[rng.randrange(HUES * STRENGTHS)]
        base = len(pos)
        for k in range(3):
            a = spin + 2 * math.pi * k / 3
            pos.append([round(c[i] + radius * (math.cos(a) * t[i] + math.sin(a) * b[i]), 6)
                        for i in range(3)])
            nrm.append([round(v, 6) for v in n])
        idx += [base, base + 1, base + 2]
    return groups


def build_cloud(count, seed):
    b = Builder()
    materials = [lambertian("floor", [0.6, 0.6, 0.6]), lambertian("grey", [0.5, 0.5, 0.5]),
                 lambertian("red", [0.7, 0.12, 0.1]), lambertian("blue", [0.1, 0.2, 0.7])]
    fp, fn, fi = quad([[-6, 0, 6], [6, 0, 6], [6, 0, -6], [-6, 0, -6]], [0, 1, 0])
    cp, cn, ci = unit_cube()
    sp, sn, si = uv_sphere(16, 32)
    meshes = [{"name": "floor", "primitives": [b.primitive(fp, fn, fi, 0)]},
              {"name": "cube", "primitives": [b.primitive(cp, cn, ci, 1)]},
              {"name": "sphere-red", "primitives": [b.primitive(sp, sn, si, 2)]},
              {"name": "sphere-blue", "primitives": [b.primitive(sp, sn, si, 3)]}]
    nodes = [{"name": "floor", "mesh": 0},
             {"name": "cube", "mesh": 1, "translation": [-1.5, 0.5, 0.0],
              "rotation": [0.0, 0.2588, 0.0, 0.9659]},
             {"name": "sphere-red", "mesh": 2, "translation": [0.6, 0.7, 0.8],
              "scale": [0.7, 0.7, 0.7]},
             {"name": "sphere-blue", "mesh": 3, "translation": [2.0, 0.5, -1.2],
              "scale": [0.5, 0.5, 0.5]}]
    first = len(materials)
    materials += cloud_materials()
    primitives = []
    for k, (pos, nrm, idx) in enumerate(cloud_triangles(count, seed)):
        if idx:
            primitives.append(b.primitive(pos, nrm, idx, first + k))
    meshes.append({"name": "emitters", "primitives": primitives})
    nodes.append({"name": "emitters", "mesh": len(meshes) - 1})
    # 8 degrees down about +X: q = (sin(-4 deg), 0, 0, cos(4 deg)).
    h = math.radians(-8) / 2
    nodes.append({"name": "view", "camera": 0, "translation": [0.0, 1.6, 7.0],
                  "rotation": [round(math.sin(h), 6), 0.0, 0.0, round(math.cos(h), 6)]})
    return {
        "asset": {"version": "2.0", "generator": "penumbra scripts/make_many_lights.py"},
        "extensionsUsed": ["KHR_materials_emissive_strength", "KHR_materials_specular"],
        "scene": 0,
        "scenes": [{"name": "many-lights", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"name": "view", "type": "perspective",
                     "perspective": {"yfov": 0.75, "aspectRatio": 1.0, "znear": 0.05}}],
        "materials": materials,
        "meshes": meshes,
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": buffers(b),
    }


# The dome and the hall: unindexed triangle soups without normals, single-sided emitters
# (their front, counter-clockwise face towards the receivers).

def quads_to_triangles(quads):
    tris = []
    for q in quads:
        tris += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
    return tris


def box(cx, cz, sx, sy, sz):
    """Outward-wound triangles of an axis-aligned box standing on y = 0."""
    x0, x1, y0, y1, z0, z1 = cx - sx, cx + sx, 0.0, sy, cz - sz, cz + sz
    c = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 4, 7, 3), (1, 2, 6, 5), (3, 7, 6, 2), (0, 1, 5, 4)]
    return quads_to_triangles([[c[i] for i in f] for f in faces])


def room():
    s = 2.0
    tris = quads_to_triangles([
        [(-s, 0, -s), (-s, 0, s), (s, 0, s), (s, 0, -s)],        # floor, facing +y
        [(-s, 0, -s), (s, 0, -s), (s, 2 * s, -s), (-s, 2 * s, -s)],  # back wall, +z
        [(-s, 0, -s), (-s, 2 * s, -s), (-s, 2 * s, s), (-s, 0, s)],  # left wall, +x
        [(s, 0, -s), (s, 0, s), (s, 2 * s, s), (s, 2 * s, -s)],    # right wall, -x
    ])
    return tris + box(-0.7, -0.3, 0.45, 1.2, 0.45) + box(0.8, 0.6, 0.4, 0.6, 0.4)


def hall():
    """Floor, side walls and an end wall of a 4 x 3 x 32 m hall along -z, facing inwards."""
    x0, x1, y1, z0, z1 = -2.0, 2.0, 3.0, -30.0, 2.0
    tris = quads_to_triangles([
        [(x0, 0, z0), (x0, 0, z1), (x1, 0, z1), (x1, 0, z0)],      # floor, +y
        [(x0, 0, z0), (x0, y1, z0), (x0, y1, z1), (x0, 0, z1)],    # left wall, +x
        [(x1, 0, z0), (x1, 0, z1), (x1, y1, z1), (x1, y1, z0)],    # right wall, -x
        [(x0, 0, z0), (x1, 0, z0), (x1, y1, z0), (x0, y1, z0)],    # end wall, +z
    ])
    for k in range(6):  # pillars of boxes down the hall
        tris += box(-1.2 if k % 2 else 1.2, -3.0 - 4.5 * k, 0.25, 1.5, 0.25)
    return tris


def face_towards(verts, d):
    """verts with the winding flipped where needed so that the front face looks along d."""
    n = cross([verts[1][j] - verts[0][j] for j in range(3)],
              [verts[2][j] - verts[0][j] for j in range(3)])
    if sum(n[j] * d[j] for j in range(3)) < 0:
        verts[1], verts[2] = verts[2], verts[1]
    return tuple(verts)


def dome_emitters(count, rng):
    """count small triangles on a dome of radius 3 around (0, 1, 0), facing its centre."""
    centre = (0.0, 1.0, 0.0)
    per_level = [[] for _ in range(LEVELS)]
    for _ in range(count):
        # Uniform over the upper part of the sphere (y above the room's mid-height).
        z = rng.uniform(0.15, 1.0)
        phi = rng.uniform(0, 2 * math.pi)
        r = math.sqrt(1 - z * z)
        d = (r * math.cos(phi), z, r * math.sin(phi))
        p = tuple(centre[k] + 3.0 * d[k] for k in range(3))
        # A tangent frame and a random triangle of about 0.02 to 0.08 in size.
        t = normalize((-d[2], 0.0, d[0]) if abs(d[1]) < 0.99 else (1.0, 0.0, 0.0))
        b = cross(d, t)
        size = rng.uniform(0.02, 0.08)
        verts = []
        for k in range(3):
            a = rng.uniform(0, 2 * math.pi / 3) + k * 2 * math.pi / 3
            verts.append(tuple(p[j] + size * (math.cos(a) * t[j] + math.sin(a) * b[j])
                               for j in range(3)))
        per_level[rng.randrange(LEVELS)].append(face_towards(verts, [-x for x in d]))
    return per_level


def hall_emitters(count, rng):
    """count small triangles just under the hall's ceiling, facing down."""
    per_level = [[] for _ in range(LEVELS)]
    for _ in range(count):
        cx, cz = rng.uniform(-1.9, 1.9), rng.uniform(-29.9, 1.9)
        size = rng.uniform(0.02, 0.06)
        a0 = rng.uniform(0, 2 * math.pi)
        verts = [(cx + size * math.cos(a0 + k * 2.1), 2.95, cz + size * math.sin(a0 + k * 2.1))
                 for k in range(3)]
        per_level[rng.randrange(LEVELS)].append(face_towards(verts, [0.0, -1.0, 0.0]))
    return per_level


def build_dome_or_hall(count, seed, is_hall):
    rng = random.Random(seed)
    b = Builder()
    primitives = []

    def add_triangles(tris, material):
        primitives.append({"attributes": {"POSITION": b.vec3([v for tri in tris for v in tri])},
                           "material": material})

    materials = [{"name": "grey", "pbrMetallicRoughness": {
        "baseColorFactor": [0.7, 0.7, 0.7, 1], "metallicFactor": 0, "roughnessFactor": 1}}]
    add_triangles(hall() if is_hall else room(), 0)
    for level, tris in enumerate((hall_emitters if is_hall else dome_emitters)(count, rng)):
        if not tris:
            continue
        tint = [0.8 + 0.2 * rng.random(), 0.8 + 0.2 * rng.random(), 0.8 + 0.2 * rng.random()]
        materials.append(emissive("emitter-%d" % level, tint,
                                  log_level(0.1, 500, level, LEVELS), False, int_zeros=True))
        add_triangles(tris, len(materials) - 1)
    return {
        # A fixed generator string, so that the files stay byte-identical to those
        # docs/performance.md measured.
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
        "meshes": [{"name": "room-and-emitters", "primitives": primitives}],
        "materials": materials,
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": buffers(b),
    }


def build(layout, count, seed):
    if layout == "cloud":
        return build_cloud(count, seed)
    return build_dome_or_hall(count, seed, layout == "hall")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", help="the .gltf to write")
    ap.add_argument("--layout", choices=["cloud", "dome", "hall"], default="cloud")
    ap.add_argument("--count", type=int, default=10000, help="emissive triangles")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    if args.count < 1:
        ap.error("--count must be at least 1")
    doc = build(args.layout, args.count, args.seed)
    with open(args.out, "w") as f:
        # The two layouts' original writers differed in layout; kept for byte identity.
        if args.layout == "cloud":
            json.dump(doc, f, indent=1)
            f.write("\n")
        else:
            json.dump(doc, f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
