#!/usr/bin/env python3
"""Writes a glTF scene of N textured planes, each with its own SIZE x SIZE RGBA PNG
(made by oiiotool), for texture memory and load-time figures (docs/performance.md).
Output goes to the folder given (e.g. /tmp/tex50); never into the repository.

    scripts/make_texture_scene.py /tmp/tex50 --count 50 --size 4096 --distinct 2
    scripts/make_texture_scene.py /tmp/tex50 --count 10 --name ten.gltf
"""
import argparse
import base64
import json
import os
import shutil
import struct
import subprocess


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--count", type=int, default=50)
    ap.add_argument("--size", type=int, default=4096)
    ap.add_argument("--distinct", type=int, default=0,
                    help="make only this many images with oiiotool, the others copies of "
                         "them (each still its own file; oiiotool takes minutes per 4K "
                         "image on a loaded machine)")
    ap.add_argument("--name", default="scene.gltf",
                    help="the .gltf's name (images already there are reused)")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)

    # One quad [-0.5, 0.5]^2 in the XY plane facing +Z, UVs over [0, 1]^2 (v down).
    pos = [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)]
    uv = [(0, 1), (1, 1), (1, 0), (0, 0)]
    idx = [0, 1, 2, 0, 2, 3]
    blob = b"".join(struct.pack("<3f", *p) for p in pos)
    blob += b"".join(struct.pack("<2f", *t) for t in uv)
    blob += struct.pack("<6H", *idx) + b"\0\0"
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
             {"buffer": 0, "byteOffset": 48, "byteLength": 32},
             {"buffer": 0, "byteOffset": 80, "byteLength": 12}]
    accessors = [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                  "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 0]},
                 {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                 {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]

    cols = 10
    nodes, images, textures, materials = [], [], [], []
    for i in range(args.count):
        name = "tex_%02d.png" % i
        path = os.path.join(args.out, name)
        distinct = args.distinct if args.distinct > 0 else args.count
        if not os.path.exists(path) and i >= distinct:
            shutil.copyfile(os.path.join(args.out, "tex_%02d.png" % (i % distinct)), path)
        elif not os.path.exists(path):
            # A checkerboard with its own colours and check size, plus a gradient, so
            # that the PNGs differ and do not compress to nothing.
            c1 = "%.2f,%.2f,%.2f,1" % ((i * 0.37) % 1, (i * 0.61) % 1, (i * 0.13) % 1)
            c2 = "%.2f,%.2f,%.2f,1" % ((i * 0.71) % 1, (i * 0.29) % 1, (i * 0.83) % 1)
            geom = "%dx%d" % (args.size, args.size)
            subprocess.run(["oiiotool", "--pattern",
                            "checker:width=%d:height=%d:color1=%s:color2=%s" % (
                                8 + i, 8 + i, c1, c2), geom, "4",
                            "--pattern", "fill:topleft=0,0,0,0:topright=0.2,0,0,0:"
                            "bottomleft=0,0.2,0,0:bottomright=0,0,0.2,0", geom, "4",
                            "--add", "-d", "uint8", "-o", path], check=True)
        images.append({"uri": name})
        textures.append({"source": i})
        materials.append({"pbrMetallicRoughness": {"baseColorTexture": {"index": i},
                                                   "metallicFactor": 0}})
        nodes.append({"mesh": i, "translation": [i % cols - cols / 2 + 0.5,
                                                 i // cols - args.count / cols / 2 + 0.5, 0]})
    meshes = [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2,
                               "material": i}]} for i in range(args.count)]
    rows = (args.count + cols - 1) // cols
    nodes.append({"camera": 0, "translation": [0, 0, max(cols, rows) * 1.0]})
    gltf = {
        "asset": {"version": "2.0", "generator": "penumbra make_texture_scene.py"},
        "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes, "meshes": meshes, "materials": materials,
        "textures": textures, "images": images,
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.01}}],
        "extensions": {}, "extensionsUsed": ["KHR_lights_punctual"],
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64,"
                     + base64.b64encode(blob).decode()}],
        "bufferViews": views, "accessors": accessors,
    }
    gltf["extensions"]["KHR_lights_punctual"] = {"lights": [
        {"type": "directional", "intensity": 683.0 * 3, "color": [1, 1, 1]}]}
    nodes[-1]["children"] = []
    gltf["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}}})
    gltf["scenes"][0]["nodes"].append(len(gltf["nodes"]) - 1)
    with open(os.path.join(args.out, args.name), "w") as f:
        json.dump(gltf, f, indent=1)


if __name__ == "__main__":
    main()
