#!/usr/bin/env python3
"""Writes scenes/material-spheres.gltf: a 5 x 5 grid of spheres sweeping the glTF
metallic factor (rows, 0 at the top to 1 at the bottom) and roughness (columns, 0 on the
left to 1 on the right), in the style of the Khronos MetalRoughSpheres sample. Base
colour is a warm white; a directional key light and a camera looking down -Z.

Render it under a uniform sky for the white furnace view:
  penumbra render scenes/material-spheres.gltf --env-color 1 1 1 --no-default-light
(tests/integrators/furnace_test.cpp checks the same sweep numerically.)

Run from the repository root:  python3 scripts/make_material_spheres.py
"""
import json

from gltf_builder import Builder, buffers, photometric, uv_sphere

N = 5
SPACING = 2.5


def main():
    b = Builder()
    pos, nrm, idx = uv_sphere()
    materials, meshes, nodes = [], [], []
    for row in range(N):
        for col in range(N):
            metallic, roughness = row / (N - 1), col / (N - 1)
            materials.append({"name": "m%.2f-r%.2f" % (metallic, roughness),
                              "pbrMetallicRoughness": {"baseColorFactor": [0.95, 0.9, 0.8, 1.0],
                                                       "metallicFactor": metallic,
                                                       "roughnessFactor": roughness}})
    # One position/normal/index set shared by every primitive: each material needs its
    # own mesh, but the accessors are written once.
    p_acc, n_acc, i_acc = b.vec3(pos), b.vec3(nrm), b.indices(idx)
    for k in range(N * N):
        meshes.append({"name": "sphere-%d" % k, "primitives": [
            {"attributes": {"POSITION": p_acc, "NORMAL": n_acc}, "indices": i_acc,
             "material": k}]})
        row, col = divmod(k, N)
        nodes.append({"name": materials[k]["name"], "mesh": k,
                      "translation": [SPACING * (col - (N - 1) / 2),
                                      SPACING * ((N - 1) / 2 - row), 0.0]})
    nodes.append({"name": "camera", "camera": 0, "translation": [0.0, 0.0, 22.0]})
    nodes.append({"name": "key-light", "rotation": [-0.28, 0.28, 0.0, 0.92],
                  "extensions": {"KHR_lights_punctual": {"light": 0}}})
    gltf = {
        "asset": {"version": "2.0", "generator": "penumbra scripts/make_material_spheres.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "scene": 0,
        "scenes": [{"name": "material-spheres", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"name": "front", "type": "perspective",
                     "perspective": {"yfov": 0.6, "aspectRatio": 1.0, "znear": 0.1}}],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "key", "type": "directional", "intensity": photometric(3.0)}]}},
        "materials": materials,
        "meshes": meshes,
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": buffers(b),
    }
    with open("scenes/material-spheres.gltf", "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
