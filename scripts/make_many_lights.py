#!/usr/bin/env python3
"""Writes many-lights.gltf: about 10,000 small emissive triangles (the default 10,000) in a
cloud above a diffuse floor with a few diffuse objects, for many-light sampling (a light
BVH) and the efficiency harness (scripts/crosscheck/efficiency.py).

- Floor: a 12 x 12 m Lambertian quad (albedo 0.6) at y = 0; on it a grey cube, a red and a
  blue sphere (all Lambertian: metallic 0, KHR_materials_specular factor 0).
- Emitters: COUNT triangles of side 4 cm, random positions in the slab
  |x|, |z| < 4.5 m, 2.4 m < y < 3.6 m, random orientations, double-sided (so penumbra and
  Cycles, whose emission is two-sided, agree). Their emission varies over 64 materials:
  8 hues x 8 strengths log-spaced from 0.5 to 50 (KHR_materials_emissive_strength), so
  the triangles' powers span 100x and sampling by power pays.
- Camera "view": from (0, 1.6, 7), looking 8 degrees down, yfov 0.75, square.

Deterministic: Python's random.Random(SEED) (Mersenne Twister, whose output for a given seed
Python keeps stable across versions) and fixed float formatting give byte-identical files.

  python3 scripts/make_many_lights.py OUT.gltf [--count 10000] [--seed 1]
"""
import argparse
import colorsys
import json
import math
import random
import sys

from gltf_builder import Builder, buffers, merge, quad, unit_cube, uv_sphere

HUES = 8
STRENGTHS = 8
SIDE = 0.04  # emitter triangle side, metres


def lambertian(name, color):
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": color + [1.0],
                                                   "metallicFactor": 0.0, "roughnessFactor": 1.0},
            "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}


def emitter_materials():
    out = []
    for h in range(HUES):
        rgb = list(colorsys.hsv_to_rgb(h / HUES, 0.6, 1.0))
        for s in range(STRENGTHS):
            strength = 0.5 * 10.0 ** (2.0 * s / (STRENGTHS - 1))  # 0.5 .. 50
            out.append({"name": "emitter-h%d-s%d" % (h, s),
                        "pbrMetallicRoughness": {"baseColorFactor": [0.0, 0.0, 0.0, 1.0],
                                                 "metallicFactor": 0.0},
                        "emissiveFactor": [round(c, 6) for c in rgb], "doubleSided": True,
                        "extensions": {"KHR_materials_emissive_strength": {
                            "emissiveStrength": round(strength, 6)}}})
    return out


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


def emitter_triangles(count, seed):
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


def build(count, seed):
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
    materials += emitter_materials()
    primitives = []
    for k, (pos, nrm, idx) in enumerate(emitter_triangles(count, seed)):
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


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", help="the .gltf to write")
    ap.add_argument("--count", type=int, default=10000, help="emissive triangles")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    if args.count < 1:
        ap.error("--count must be at least 1")
    with open(args.out, "w") as f:
        json.dump(build(args.count, args.seed), f, indent=1)
        f.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
