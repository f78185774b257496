#!/usr/bin/env python3
"""Writes a scene of many instances of one mesh with EXT_mesh_gpu_instancing.

  python3 scripts/make_instances.py          # scenes/instances.gltf: 400 x 528 triangles
  python3 scripts/make_instances.py --count 1000000 --rings 50 --segments 100 \
      --out build/instances-1m.glb          # the scale test: 1M x 9,800 triangles

Each instance has its own translation, rotation and scale (some non-uniform, some
mirrored: a negative scale). The mesh is a UV sphere of --rings x --segments.
Large counts are written as .glb (binary) and are not committed: generate them.
"""
import argparse
import json
import math
import random
import struct

from gltf_builder import Builder, buffers, photometric, uv_sphere


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--count", type=int, default=400)
    ap.add_argument("--rings", type=int, default=12)
    ap.add_argument("--segments", type=int, default=24)
    ap.add_argument("--out", default="scenes/instances.gltf")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    rng = random.Random(args.seed)

    b = Builder()
    pos, nrm, idx = uv_sphere(args.rings, args.segments)
    prim = {"attributes": {"POSITION": b.vec3(pos), "NORMAL": b.vec3(nrm)},
            "indices": b.indices32(idx) if len(pos) > 65535 else b.indices(idx), "material": 0}
    side = math.ceil(math.sqrt(args.count))
    t, r, s = [], [], []
    for i in range(args.count):
        gx, gz = i % side, i // side
        t.append([3.0 * (gx - side / 2), 0.0, 3.0 * (gz - side / 2)])
        axis = [rng.uniform(-1, 1) for _ in range(3)]
        n = math.sqrt(sum(a * a for a in axis)) or 1.0
        half = rng.uniform(0, math.pi)
        r.append([a / n * math.sin(half) for a in axis] + [math.cos(half)])
        scale = [rng.uniform(0.4, 1.2)] * 3
        if i % 7 == 3:  # non-uniform
            scale = [rng.uniform(0.3, 1.2) for _ in range(3)]
        if i % 11 == 5:  # mirrored
            scale[0] = -scale[0]
        s.append(scale)
    ext = {"attributes": {"TRANSLATION": b.vec3(t), "ROTATION": b.vec4(r), "SCALE": b.vec3(s)}}
    extent = 3.0 * side / 2
    gltf = {
        "asset": {"version": "2.0", "generator": "penumbra scripts/make_instances.py"},
        "extensionsUsed": ["EXT_mesh_gpu_instancing", "KHR_lights_punctual"],
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [
            {"name": "spheres", "mesh": 0, "extensions": {"EXT_mesh_gpu_instancing": ext}},
            {"name": "camera", "camera": 0, "translation": [0.0, extent * 0.9, extent * 1.6],
             "rotation": [-0.2588, 0.0, 0.0, 0.9659]},
            {"name": "sun", "rotation": [-0.5, 0.3, 0.1, 0.8],
             "extensions": {"KHR_lights_punctual": {"light": 0}}},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "directional", "intensity": photometric(3.0)}]}},
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.5, 0.3, 1.0],
                                                "metallicFactor": 0.0, "roughnessFactor": 0.5}}],
        "meshes": [{"name": "sphere", "primitives": [prim]}],
        "accessors": b.accessors,
        "bufferViews": b.views,
    }
    if args.out.endswith(".glb"):
        gltf["buffers"] = [{"byteLength": len(b.blob)}]
        body = json.dumps(gltf, separators=(",", ":")).encode()
        body += b" " * (-len(body) % 4)
        blob = bytes(b.blob) + b"\0" * (-len(b.blob) % 4)
        with open(args.out, "wb") as f:
            f.write(struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(body) + 8 + len(blob)))
            f.write(struct.pack("<I4s", len(body), b"JSON") + body)
            f.write(struct.pack("<I4s", len(blob), b"BIN\0") + blob)
    else:
        gltf["buffers"] = buffers(b)
        with open(args.out, "w") as f:
            json.dump(gltf, f, indent=1)
            f.write("\n")


if __name__ == "__main__":
    main()
