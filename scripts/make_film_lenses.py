#!/usr/bin/env python3
"""Writes scenes/film-lenses.gltf: two thin-walled, transmissive lenses under a thin film
(KHR_materials_transmission without KHR_materials_volume, KHR_materials_iridescence 1,
iridescenceIor 1.8, 300 nm), in front of a white emissive backdrop, seen by a camera on
+Z. Left: a sunglasses lens as in the Khronos SunglassesKhronos sample (IOR 1, base
colour 0.009: all its reflection is the film's, and it passes almost nothing). Right: a
clear lens (IOR 1.5, white), which passes what its film does not reflect.

See scenes/README.md for what the renders show.
Run from the repository root:  python3 scripts/make_film_lenses.py
"""
import json
import math

from gltf_builder import Builder, buffers, quad


def spherical_cap(radius, half_angle_deg, rings=16, segments=48):
    """The cap of a sphere of the given radius around +Z, apex at the origin, normals out."""
    pos, nrm, idx = [], [], []
    top = math.radians(half_angle_deg)
    for r in range(rings + 1):
        theta = top * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            n = [math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta)]
            pos.append([radius * n[0], radius * n[1], radius * (n[2] - 1)])
            nrm.append(n)
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b = a + segments + 1
            if r != 0:  # the apex row's first triangle is degenerate
                idx += [a, b, a + 1]
            idx += [a + 1, b, b + 1]
    return pos, nrm, idx


def lens_material(name, ior, base):
    return {"name": name, "doubleSided": True,
            "pbrMetallicRoughness": {"baseColorFactor": [base, base, base, 1.0],
                                     "metallicFactor": 0.0, "roughnessFactor": 0.0},
            "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                           "KHR_materials_ior": {"ior": ior},
                           "KHR_materials_iridescence": {"iridescenceFactor": 1.0,
                                                         "iridescenceIor": 1.8,
                                                         "iridescenceThicknessMaximum": 300.0}}}


def main():
    b = Builder()
    pos, nrm, idx = spherical_cap(1.0, 40.0)
    cap = b.primitive(pos, nrm, idx, 0)
    meshes = [{"name": "sunglasses-lens", "primitives": [cap]},
              {"name": "clear-lens", "primitives": [dict(cap, material=1)]}]
    h = 6.0
    p, n, i = quad([[-h, -h, -2.0], [h, -h, -2.0], [h, h, -2.0], [-h, h, -2.0]], [0.0, 0.0, 1.0])
    meshes.append({"name": "backdrop", "primitives": [b.primitive(p, n, i, 2)]})
    materials = [
        lens_material("sunglasses-lens", 1.0, 0.009),
        lens_material("clear-lens", 1.5, 1.0),
        # Emits 1, reflects nothing (exactly Lambertian, black).
        {"name": "white-light", "emissiveFactor": [1.0, 1.0, 1.0],
         "pbrMetallicRoughness": {"baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0},
         "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}},
    ]
    nodes = [{"name": "sunglasses-lens", "mesh": 0, "translation": [-0.75, 0.0, 0.0]},
             {"name": "clear-lens", "mesh": 1, "translation": [0.75, 0.0, 0.0]},
             {"name": "backdrop", "mesh": 2},
             {"name": "camera", "camera": 0, "translation": [0.0, 0.0, 4.0]}]
    gltf = {
        "asset": {"version": "2.0", "generator": "penumbra scripts/make_film_lenses.py"},
        "extensionsUsed": ["KHR_materials_transmission", "KHR_materials_ior",
                           "KHR_materials_iridescence", "KHR_materials_specular"],
        "scene": 0,
        "scenes": [{"name": "film-lenses", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"name": "front", "type": "perspective",
                     "perspective": {"yfov": 0.4, "aspectRatio": 2.0, "znear": 0.1}}],
        "materials": materials,
        "meshes": meshes,
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": buffers(b),
    }
    with open("scenes/film-lenses.gltf", "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
