#!/usr/bin/env python3
"""A big glTF scene for load and build measurements (docs/performance.md, "Big
scenes"): N meshes of unique triangles (displaced grids, each with its own positions,
normals and UVs, no instancing) and one material with its own PNG base-colour texture
per mesh. Plain Python (no numpy on the build machines); writes scene.gltf, scene.bin
and tex_NNN.png into the output folder. Generate into /tmp, never into the repository.

    scripts/make_big_scene.py /tmp/big                 # 100 x 100k triangles, 1024^2
    scripts/make_big_scene.py /tmp/small --meshes 4 --triangles 2000 --texture-size 64
"""
import argparse
import array
import json
import math
import os
import random
import struct
import sys
import zlib


def grid_shape(triangles):
    """Columns and rows of quads giving at least `triangles` triangles, about 5:4."""
    rows = max(1, int(math.sqrt(triangles / 2 * 0.8)))
    cols = max(1, -(-triangles // (2 * rows)))
    return cols, rows


def grid_indices(cols, rows):
    """Two counter-clockwise triangles (seen from +Y) per quad, uint32."""
    out = array.array("I")
    stride = cols + 1
    for j in range(rows):
        for i in range(cols):
            a = j * stride + i
            b, c, d = a + 1, a + stride, a + stride + 1
            out.extend((a, c, b, b, c, d))
    return out


def grid_vertices(cols, rows, origin, size, amp, fx, fz, phase):
    """Positions, normals and UVs of a height field y = amp sin(fx x + p) cos(fz z + p)."""
    x0, z0 = origin
    xs = [x0 + size[0] * i / cols for i in range(cols + 1)]
    zs = [z0 + size[1] * j / rows for j in range(rows + 1)]
    sx = [math.sin(fx * (x - x0) + phase) for x in xs]
    dsx = [fx * math.cos(fx * (x - x0) + phase) for x in xs]
    us = [i / cols for i in range(cols + 1)]
    pos, nrm, uv = array.array("f"), array.array("f"), array.array("f")
    lo = [math.inf] * 3
    hi = [-math.inf] * 3
    for j, z in enumerate(zs):
        cz = amp * math.cos(fz * (z - z0) + phase)
        dcz = -amp * fz * math.sin(fz * (z - z0) + phase)
        v = 1 - j / rows
        row_pos, row_nrm, row_uv = [], [], []
        for x, s, ds, u in zip(xs, sx, dsx, us):
            y = s * cz
            # Normal of y = h(x, z): (-dh/dx, 1, -dh/dz), normalised.
            gx, gz = -ds * cz, -s * dcz
            inv = 1.0 / math.sqrt(gx * gx + 1.0 + gz * gz)
            row_pos += (x, y, z)
            row_nrm += (gx * inv, inv, gz * inv)
            row_uv += (u, v)
        pos.extend(row_pos)
        nrm.extend(row_nrm)
        uv.extend(row_uv)
        ys = row_pos[1::3]
        lo = [min(lo[0], xs[0]), min(lo[1], min(ys)), min(lo[2], z)]
        hi = [max(hi[0], xs[-1]), max(hi[1], max(ys)), max(hi[2], z)]
    return pos, nrm, uv, lo, hi


def png_bytes(size, seed):
    """An RGB PNG of noise over a per-texture tint and gradient. Noise keeps it from
    compressing to nothing, so decoding costs what a real texture's would."""
    rng = random.Random(seed)
    tint = [rng.randrange(40, 200) for _ in range(3)]
    raw = bytearray()
    for j in range(size):
        base = (tint[j % 3] + 48 * j // size) & 0xFF
        table = bytes((base + (v & 0x3F)) & 0xFF for v in range(256))
        raw += b"\x00" + os.urandom(3 * size).translate(table)

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    ihdr = struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) +
            chunk(b"IDAT", zlib.compress(bytes(raw), 6)) + chunk(b"IEND", b""))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", help="output folder (created)")
    ap.add_argument("--meshes", type=int, default=100)
    ap.add_argument("--triangles", type=int, default=100_000, help="per mesh")
    ap.add_argument("--texture-size", type=int, default=1024)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)

    cols, rows = grid_shape(args.triangles)
    indices = grid_indices(cols, rows).tobytes()
    side = math.ceil(math.sqrt(args.meshes))
    cell = (1.0, 0.8)
    gltf = {"asset": {"version": "2.0", "generator": "penumbra make_big_scene.py"},
            "buffers": [], "bufferViews": [], "accessors": [], "meshes": [],
            "materials": [], "textures": [], "images": [], "samplers": [{}],
            "nodes": [], "scenes": [{"nodes": []}], "scene": 0}
    offset = 0
    with open(os.path.join(args.out, "scene.bin"), "wb") as bin_file:
        def view(data, target, stride=None):
            nonlocal offset
            v = {"buffer": 0, "byteOffset": offset, "byteLength": len(data), "target": target}
            if stride:
                v["byteStride"] = stride
            gltf["bufferViews"].append(v)
            bin_file.write(data)
            offset += len(data)
            return len(gltf["bufferViews"]) - 1

        def accessor(data, count, kind, component, target, bounds=None):
            a = {"bufferView": view(data, target), "componentType": component,
                 "count": count, "type": kind}
            if bounds:
                a["min"], a["max"] = bounds
            gltf["accessors"].append(a)
            return len(gltf["accessors"]) - 1

        for m in range(args.meshes):
            rng = random.Random(m)
            origin = ((m % side) * 1.1 * cell[0], (m // side) * 1.1 * cell[1])
            pos, nrm, uv, lo, hi = grid_vertices(
                cols, rows, origin, cell, amp=0.05 + 0.05 * rng.random(),
                fx=rng.uniform(6, 30), fz=rng.uniform(6, 30), phase=rng.uniform(0, 6.3))
            n = (cols + 1) * (rows + 1)
            attributes = {
                "POSITION": accessor(pos.tobytes(), n, "VEC3", 5126, 34962, (lo, hi)),
                "NORMAL": accessor(nrm.tobytes(), n, "VEC3", 5126, 34962),
                "TEXCOORD_0": accessor(uv.tobytes(), n, "VEC2", 5126, 34962)}
            idx = accessor(indices, 6 * cols * rows, "SCALAR", 5125, 34963)
            gltf["meshes"].append({"name": "grid%03d" % m, "primitives": [
                {"attributes": attributes, "indices": idx, "material": m}]})
            gltf["materials"].append({"name": "mat%03d" % m, "pbrMetallicRoughness": {
                "baseColorTexture": {"index": m}, "metallicFactor": 0.0,
                "roughnessFactor": 0.6}})
            gltf["textures"].append({"source": m, "sampler": 0})
            name = "tex_%03d.png" % m
            gltf["images"].append({"uri": name})
            with open(os.path.join(args.out, name), "wb") as f:
                f.write(png_bytes(args.texture_size, m))
            gltf["nodes"].append({"mesh": m})
            gltf["scenes"][0]["nodes"].append(m)
            print("\rmesh %d/%d" % (m + 1, args.meshes), end="", file=sys.stderr, flush=True)
    print(file=sys.stderr)
    gltf["buffers"].append({"uri": "scene.bin", "byteLength": offset})
    # A camera above the field, looking down at its centre.
    cx, cz = side * 1.1 * cell[0] / 2, side * 1.1 * cell[1] / 2
    tilt = math.atan2(1.4, 0.9)  # below the horizon, towards the centre
    gltf["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.01}}]
    gltf["nodes"].append({"camera": 0, "translation": [cx, 1.4 * side, cz + 0.9 * side],
                          "rotation": [-math.sin(tilt / 2), 0, 0, math.cos(tilt / 2)]})
    gltf["scenes"][0]["nodes"].append(len(gltf["nodes"]) - 1)
    with open(os.path.join(args.out, "scene.gltf"), "w") as f:
        json.dump(gltf, f, indent=1)
    print("%s: %d meshes x %d triangles = %d, %d textures of %d^2, %.0f MB of buffer" %
          (args.out, args.meshes, 2 * cols * rows, args.meshes * 2 * cols * rows,
           args.meshes, args.texture_size, offset / 1e6), file=sys.stderr)


if __name__ == "__main__":
    main()
