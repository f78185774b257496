#!/usr/bin/env python3
"""Writes scenes/cornell-box.gltf (the default scene, lit by an emissive ceiling panel)
and scenes/cornell-box-point.gltf (the same room lit by a point light instead, for the
analytic tests of the classic ray tracer). See scenes/README.md.

The room is the cube [-1, 1]^3 (metres, glTF's +Y up), open towards the camera at +Z.
Walls are exactly Lambertian (metallic 0 with KHR_materials_specular factor 0) so that
direct lighting has a closed form. One unit-cube mesh is instanced twice with different
non-uniform scales and rotations (the two blocks); a smooth mirror sphere (metallic 1,
roughness 0) sits on the short block.

The panel is single-sided (doubleSided false, glTF's default): it emits downwards from
its front face only, so the 1 mm gap above it stays dark, as in the classic scene.

Run from the repository root:  python3 scripts/make_cornell_box.py
A variant with the panel hung lower, for the cross-checks of single-sided emission:
  python3 scripts/make_cornell_box.py --light-y 0.9 --out build/cornell-box-hung.gltf
  (--double-sided makes its panel emit from both faces)
"""
import argparse
import json

from gltf_builder import (Builder, buffers, merge, photometric, quad, unit_cube, uv_sphere,
                          y_rotation)

WHITE = [0.75, 0.75, 0.75, 1.0]
RED = [0.63, 0.065, 0.05, 1.0]
GREEN = [0.14, 0.45, 0.091, 1.0]
LIGHT_INTENSITY = 8.0  # W/sr
LIGHT_POSITION = [0.0, 0.95, 0.0]
PANEL_RADIANCE = 30.0


def lambertian(name, color):
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": color, "metallicFactor": 0.0,
                                                   "roughnessFactor": 1.0},
            "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}


def scene(point_light, light_y=0.999, double_sided=False):
    b = Builder()
    materials = [
        lambertian("white", WHITE),
        lambertian("red", RED),
        lambertian("green", GREEN),
        {"name": "mirror", "pbrMetallicRoughness": {"baseColorFactor": [0.95, 0.95, 0.95, 1.0],
                                                    "metallicFactor": 1.0, "roughnessFactor": 0.0}},
        {"name": "light", "pbrMetallicRoughness": {"baseColorFactor": [0.0, 0.0, 0.0, 1.0],
                                                   "metallicFactor": 0.0},
         "emissiveFactor": [1.0, 1.0, 1.0], "doubleSided": double_sided,
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": PANEL_RADIANCE},
                        "KHR_materials_specular": {"specularFactor": 0.0}}},
    ]
    # Walls, each facing into the room.
    white_walls = merge([
        quad([[-1, -1, -1], [-1, -1, 1], [1, -1, 1], [1, -1, -1]], [0, 1, 0]),    # floor
        quad([[-1, 1, -1], [1, 1, -1], [1, 1, 1], [-1, 1, 1]], [0, -1, 0]),       # ceiling
        quad([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1]], [0, 0, 1]),    # back
    ])
    red_wall = quad([[-1, -1, -1], [-1, 1, -1], [-1, 1, 1], [-1, -1, 1]], [1, 0, 0])
    green_wall = quad([[1, -1, -1], [1, -1, 1], [1, 1, 1], [1, 1, -1]], [-1, 0, 0])
    y = light_y
    # Counter-clockwise seen from below: the front face looks down into the room.
    light_panel = quad([[-0.25, y, -0.2], [0.25, y, -0.2], [0.25, y, 0.2], [-0.25, y, 0.2]],
                       [0, -1, 0])
    meshes = [
        {"name": "room", "primitives": [b.primitive(*white_walls, 0), b.primitive(*red_wall, 1),
                                        b.primitive(*green_wall, 2)]},
        {"name": "block", "primitives": [b.primitive(*unit_cube(), 0)]},
        {"name": "sphere", "primitives": [b.primitive(*uv_sphere(), 3)]},
    ]
    if point_light:
        light_node = {"name": "point-light", "translation": LIGHT_POSITION,
                      "extensions": {"KHR_lights_punctual": {"light": 0}}}
    else:
        meshes.append({"name": "light-panel", "primitives": [b.primitive(*light_panel, 4)]})
        light_node = {"name": "light-panel", "mesh": 3}
    nodes = [
        {"name": "camera", "camera": 0, "translation": [0.0, 0.0, 3.9]},
        {"name": "room", "mesh": 0},
        light_node,
        {"name": "short-block", "mesh": 1, "translation": [0.35, -0.7, 0.3],
         "rotation": y_rotation(-18.0), "scale": [0.6, 0.6, 0.6]},
        {"name": "tall-block", "mesh": 1, "translation": [-0.35, -0.4, -0.35],
         "rotation": y_rotation(20.0), "scale": [0.6, 1.2, 0.6]},
        {"name": "mirror-sphere", "mesh": 2, "translation": [0.35, -0.1, 0.3],
         "scale": [0.3, 0.3, 0.3]},
    ]
    if point_light:
        materials = materials[:4]  # no emissive material
    gltf = {
        "asset": {"version": "2.0", "generator": "penumbra scripts/make_cornell_box.py"},
        "extensionsUsed": (["KHR_lights_punctual"] if point_light else
                           ["KHR_materials_emissive_strength"]) + ["KHR_materials_specular"],
        "scene": 0,
        "scenes": [{"name": "cornell-box", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"name": "front", "type": "perspective",
                     "perspective": {"yfov": 0.69, "aspectRatio": 1.0, "znear": 0.01}}],
        "materials": materials,
        "meshes": meshes,
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": buffers(b),
    }
    if point_light:
        gltf["extensions"] = {"KHR_lights_punctual": {"lights": [
            {"name": "ceiling-point", "type": "point", "color": [1.0, 1.0, 1.0],
             "intensity": photometric(LIGHT_INTENSITY)}]}}
    return gltf


def write(path, gltf):
    with open(path, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--light-y", type=float, help="panel height (a variant; needs --out)")
    ap.add_argument("--double-sided", action="store_true", help="the variant's panel emits both ways")
    ap.add_argument("--out", help="where to write the variant")
    args = ap.parse_args()
    if args.out:
        write(args.out, scene(False, args.light_y if args.light_y is not None else 0.999,
                              args.double_sided))
        return
    for name, point_light in (("cornell-box", False), ("cornell-box-point", True)):
        write("scenes/%s.gltf" % name, scene(point_light))


if __name__ == "__main__":
    main()
