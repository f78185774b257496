#!/usr/bin/env python3
"""Writes the distribution-ray-tracing showcase scenes:

  scenes/dof.gltf           five spheres at depths 2 to 10 m, a thin lens of aperture
                            radius 5 cm focused on the third (6 m) with a 6-bladed
                            aperture, a bright back wall: depth of field.
  scenes/soft-shadows.gltf  three posts on a floor, each lit from the side by its own square
                            emissive panel of side 0.1, 0.4 or 1.2 m (same power): penumbrae
                            growing with the light's size.
  scenes/glossy.gltf        gold and silver spheres sweeping roughness 0.05 to 0.6 over a
                            checker floor, an emissive strip reflected in them: glossy
                            reflection. glTF has no Beckmann, so the distribution is chosen
                            on the command line (--microfacet ggx|beckmann).

Run from the repository root:  python3 scripts/make_effect_scenes.py
"""
import json

from gltf_builder import Builder, buffers, merge, photometric, quad, unit_cube, uv_sphere


def write(path, gltf):
    with open(path, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


def document(b, name, nodes, meshes, materials, cameras, lights=None):
    gltf = {
        "asset": {"version": "2.0", "generator": "penumbra scripts/make_effect_scenes.py"},
        "scene": 0,
        "scenes": [{"name": name, "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": cameras,
        "materials": materials,
        "meshes": meshes,
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": buffers(b),
    }
    if lights:
        gltf["extensionsUsed"] = ["KHR_lights_punctual"]
        gltf["extensions"] = {"KHR_lights_punctual": {"lights": lights}}
    return gltf


def diffuse(name, color):
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": color + [1.0],
                                                   "metallicFactor": 0.0, "roughnessFactor": 1.0}}


def floor_quad(half):
    return quad([[-half, 0, half], [half, 0, half], [half, 0, -half], [-half, 0, -half]], [0, 1, 0])


def dof():
    b = Builder()
    sp, sn, si = uv_sphere(16, 32)
    sphere = b.primitive(sp, sn, si, 1)
    fp, fn, fi = floor_quad(20)
    wp, wn, wi = quad([[-20, 0, -12], [20, 0, -12], [20, 12, -12], [-20, 12, -12]], [0, 0, 1])
    materials = [diffuse("floor", [0.5, 0.5, 0.5]), diffuse("sphere", [0.8, 0.3, 0.1]),
                 diffuse("wall", [0.9, 0.9, 0.9])]
    meshes = [{"name": "floor", "primitives": [b.primitive(fp, fn, fi, 0),
                                               b.primitive(wp, wn, wi, 2)]},
              {"name": "sphere", "primitives": [sphere]}]
    nodes = [{"name": "floor", "mesh": 0}]
    for k, depth in enumerate([2, 4, 6, 8, 10]):
        nodes.append({"name": "sphere-at-%dm" % depth, "mesh": 1, "scale": [0.4] * 3,
                      "translation": [-0.9 + 0.45 * k, 0.4, 1.0 - depth]})
    nodes.append({"name": "camera", "camera": 0, "translation": [0.0, 0.6, 1.0]})
    nodes.append({"name": "sun", "rotation": [-0.35, 0.35, 0.0, 0.87],
                  "extensions": {"KHR_lights_punctual": {"light": 0}}})
    cameras = [{"name": "thin-lens", "type": "perspective",
                "perspective": {"yfov": 0.5, "aspectRatio": 1.5, "znear": 0.05},
                # A wide lens, to make the blur obvious: 5 cm aperture radius (f/0.5
                # for this field of view), focused on the middle sphere, 6 m away.
                "extras": {"aperture_radius": 0.05, "focus_distance": 6.0, "blades": 6}}]
    lights = [{"name": "sun", "type": "directional",
               "intensity": photometric(3.0)}]
    write("scenes/dof.gltf", document(b, "dof", nodes, meshes, materials, cameras, lights))


def soft_shadows():
    b = Builder()
    fp, fn, fi = floor_quad(8)
    cp, cn, ci = unit_cube()
    materials = [diffuse("floor", [0.7, 0.7, 0.7]), diffuse("post", [0.3, 0.4, 0.7])]
    meshes = [{"name": "floor", "primitives": [b.primitive(fp, fn, fi, 0)]},
              {"name": "post", "primitives": [b.primitive(cp, cn, ci, 1)]}]
    nodes = [{"name": "floor", "mesh": 0}]
    # Each post stands under its own light; the lights emit the same power, so the
    # smaller ones are brighter per area.
    for k, side in enumerate([0.1, 0.4, 1.2]):
        x = -3.0 + 3.0 * k
        nodes.append({"name": "post-%d" % k, "mesh": 1, "translation": [x, 0.5, 0.0],
                      "scale": [0.25, 1.0, 0.25]})
        h = side / 2
        lp, ln, li = quad([[-h, 0, -h], [h, 0, -h], [h, 0, h], [-h, 0, h]], [0, -1, 0])
        materials.append({"name": "panel-%.1fm" % side,
                          "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1],
                                                   "metallicFactor": 0.0},
                          "emissiveFactor": [1.0, 1.0, 1.0],
                          "extensions": {"KHR_materials_emissive_strength": {
                              "emissiveStrength": 3.0 / (side * side)}}})
        meshes.append({"name": "panel-%d" % k,
                       "primitives": [b.primitive(lp, ln, li, len(materials) - 1)]})
        # Beside and above the post: its shadow falls away from the light, across the floor.
        nodes.append({"name": "light-%.1fm" % side, "mesh": len(meshes) - 1,
                      "translation": [x + 0.9, 2.2, 0.6]})
    nodes.append({"name": "camera", "camera": 0, "translation": [0.0, 5.0, 6.0],
                  "rotation": [-0.3420, 0.0, 0.0, 0.9397]})
    cameras = [{"name": "above", "type": "perspective",
                "perspective": {"yfov": 0.8, "aspectRatio": 1.6, "znear": 0.05}}]
    gltf = document(b, "soft-shadows", nodes, meshes, materials, cameras)
    gltf["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    write("scenes/soft-shadows.gltf", gltf)


def glossy():
    b = Builder()
    sp, sn, si = uv_sphere(24, 48)
    p_acc, n_acc, i_acc = b.vec3(sp), b.vec3(sn), b.indices(si)
    # A checker floor: alternating quads in two materials, so reflections show blur.
    tiles = [[], []]
    for i in range(-8, 8):
        for j in range(-8, 8):
            x0, z0 = i * 0.5, j * 0.5
            tiles[(i + j) % 2].append(quad([[x0, 0, z0 + 0.5], [x0 + 0.5, 0, z0 + 0.5],
                                           [x0 + 0.5, 0, z0], [x0, 0, z0]], [0, 1, 0]))
    materials = [diffuse("tile-light", [0.8, 0.8, 0.8]), diffuse("tile-dark", [0.1, 0.1, 0.1])]
    meshes = [{"name": "floor", "primitives": [b.primitive(*merge(tiles[0]), 0),
                                               b.primitive(*merge(tiles[1]), 1)]}]
    nodes = [{"name": "floor", "mesh": 0}]
    roughness = [0.05, 0.15, 0.3, 0.45, 0.6]
    for row, (metal, color) in enumerate([("gold", [1.0, 0.78, 0.34]),
                                          ("silver", [0.97, 0.96, 0.91])]):
        for col, r in enumerate(roughness):
            materials.append({"name": "%s-r%.2f" % (metal, r),
                              "pbrMetallicRoughness": {"baseColorFactor": color + [1.0],
                                                       "metallicFactor": 1.0,
                                                       "roughnessFactor": r}})
            meshes.append({"name": "sphere-%s-%d" % (metal, col), "primitives": [
                {"attributes": {"POSITION": p_acc, "NORMAL": n_acc}, "indices": i_acc,
                 "material": len(materials) - 1}]})
            nodes.append({"name": materials[-1]["name"], "mesh": len(meshes) - 1,
                          "scale": [0.35] * 3,
                          "translation": [-1.6 + 0.8 * col, 0.35, -0.4 - 1.0 * row]})
    nodes.append({"name": "camera", "camera": 0, "translation": [0.0, 1.3, 2.6],
                  "rotation": [-0.2164, 0.0, 0.0, 0.9763]})
    # An emissive strip above and behind: its reflection shows the lobe's width.
    lp, ln, li = quad([[-2.5, 2.0, -2.5], [2.5, 2.0, -2.5], [2.5, 2.6, -2.6], [-2.5, 2.6, -2.6]],
                      [0, -0.16, 0.99])
    materials.append({"name": "strip", "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1],
                                                                "metallicFactor": 0.0},
                      "emissiveFactor": [1.0, 1.0, 1.0],
                      "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 8.0}}})
    meshes.append({"name": "strip", "primitives": [b.primitive(lp, ln, li, len(materials) - 1)]})
    nodes.append({"name": "strip", "mesh": len(meshes) - 1})
    cameras = [{"name": "front", "type": "perspective",
                "perspective": {"yfov": 0.7, "aspectRatio": 1.6, "znear": 0.05}}]
    gltf = document(b, "glossy", nodes, meshes, materials, cameras)
    gltf["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    write("scenes/glossy.gltf", gltf)


if __name__ == "__main__":
    dof()
    soft_shadows()
    glossy()
