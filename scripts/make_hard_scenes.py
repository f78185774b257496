#!/usr/bin/env python3
"""Writes the numerical hard cases in scenes/hard/ (see scenes/hard/README.md). Each is a
small scene the tests load and then vary (move, scale, relight) in code:

  acne-plane.gltf         a tessellated, tilted white plane and a directional light
  thin-sheets.gltf        two parallel white sheets 1e-4 apart, lit from above
  terminator-sphere.gltf  a coarse UV sphere (8 x 16) with smooth normals, lit from the side
  scale.gltf              a floor, a box and a coarse sphere under a directional light
  lights.gltf             a closed box around a point light, a zero-area emitter, a
                          zero-intensity spot light and a tiny, very bright emitter
  bad-geometry.gltf       degenerate triangles, duplicate vertices, zero-length normals,
                          a mirrored and a non-uniformly scaled instance
  bump-plane.gltf         a plane whose normal map tilts every normal 40 degrees along +u

All materials are exactly Lambertian (metallic 0, KHR_materials_specular factor 0), so
direct light has a closed form.

Run from the repository root:  python3 scripts/make_hard_scenes.py
"""
import base64
import json
import math
import struct
import zlib

from gltf_builder import Builder, buffers, merge, photometric, quad, unit_cube, uv_sphere

OUT = "scenes/hard/"


def lambertian(name, color=(0.8, 0.8, 0.8)):
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(color) + [1.0],
                                                   "metallicFactor": 0.0, "roughnessFactor": 1.0},
            "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}


def emitter(name, strength):
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [0.0, 0.0, 0.0, 1.0],
                                                   "metallicFactor": 0.0},
            "emissiveFactor": [1.0, 1.0, 1.0],
            "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": strength},
                           "KHR_materials_specular": {"specularFactor": 0.0}}}


def grid(n, size, y=0.0):
    """An n x n grid of quads over [-size, size]^2 at height y, facing +y."""
    pos, nrm, idx = [], [], []
    for j in range(n + 1):
        for i in range(n + 1):
            pos.append([-size + 2 * size * i / n, y, -size + 2 * size * j / n])
            nrm.append([0.0, 1.0, 0.0])
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            idx += [a, a + n + 1, a + 1, a + 1, a + n + 1, a + n + 2]
    return pos, nrm, idx


def down_quaternion():
    """Rotation taking the node's -Z to world -Y (a light or camera looking down)."""
    h = -math.pi / 4
    return [math.sin(h), 0.0, 0.0, math.cos(h)]


def write(name, b, gltf):
    gltf["asset"] = {"version": "2.0", "generator": "penumbra scripts/make_hard_scenes.py"}
    gltf["accessors"] = b.accessors
    gltf["bufferViews"] = b.views
    gltf["buffers"] = buffers(b)
    gltf.setdefault("scene", 0)
    with open(OUT + name, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


def sun(intensity=1.0):
    return {"extensionsUsed": ["KHR_lights_punctual", "KHR_materials_specular"],
            "extensions": {"KHR_lights_punctual": {"lights": [
                {"name": "sun", "type": "directional",
                 "intensity": photometric(intensity)}]}}}


def acne_plane():
    b = Builder()
    # The tilt puts every vertex off the float grid, so neighbouring triangles are not
    # exactly coplanar after transformation: the case that shows acne at grazing light.
    gltf = sun()
    gltf.update({
        "materials": [lambertian("white")],
        "meshes": [{"name": "plane", "primitives": [b.primitive(*grid(16, 1.0), 0)]}],
        "nodes": [{"name": "plane", "mesh": 0,
                   "rotation": [0.0987, 0.0, 0.0743, 0.9923]},
                  {"name": "sun", "rotation": down_quaternion(),
                   "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "scenes": [{"nodes": [0, 1]}]})
    write("acne-plane.gltf", b, gltf)


def thin_sheets():
    b = Builder()
    gltf = sun()
    gltf.update({
        "materials": [lambertian("white")],
        "meshes": [{"name": "sheets", "primitives": [
            b.primitive(*grid(4, 2.0, 0.0), 0), b.primitive(*grid(4, 2.0, 1e-4), 0)]}],
        "nodes": [{"name": "sheets", "mesh": 0},
                  {"name": "sun", "rotation": down_quaternion(),
                   "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "scenes": [{"nodes": [0, 1]}]})
    write("thin-sheets.gltf", b, gltf)


def terminator_sphere():
    b = Builder()
    gltf = sun()
    # The light travels along +X (node -Z turned to +X): the terminator is the great
    # circle x = 0, seen edge-on from a camera on +Z.
    h = -math.pi / 4
    gltf.update({
        "materials": [lambertian("white")],
        "meshes": [{"name": "sphere", "primitives": [b.primitive(*uv_sphere(8, 16), 0)]}],
        "nodes": [{"name": "sphere", "mesh": 0},
                  {"name": "sun", "rotation": [0.0, math.sin(h), 0.0, math.cos(h)],
                   "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "scenes": [{"nodes": [0, 1]}]})
    write("terminator-sphere.gltf", b, gltf)


def scale_scene():
    b = Builder()
    gltf = sun(2.0)
    gltf.update({
        "materials": [lambertian("white"), lambertian("red", (0.7, 0.2, 0.1))],
        "meshes": [{"name": "floor", "primitives": [b.primitive(*grid(4, 2.0, -0.5), 0)]},
                   {"name": "box", "primitives": [b.primitive(*unit_cube(), 1)]},
                   {"name": "ball", "primitives": [b.primitive(*uv_sphere(8, 16), 0)]}],
        "cameras": [{"name": "view", "type": "perspective",
                     "perspective": {"yfov": 0.9, "aspectRatio": 1.0, "znear": 0.01}}],
        "nodes": [{"name": "floor", "mesh": 0},
                  {"name": "box", "mesh": 1, "translation": [-0.6, 0.0, 0.0],
                   "rotation": [0.0, 0.3827, 0.0, 0.9239]},
                  {"name": "ball", "mesh": 2, "translation": [0.7, 0.0, 0.2],
                   "scale": [0.5, 0.5, 0.5]},
                  {"name": "camera", "camera": 0, "translation": [0.0, 1.2, 3.5],
                   "rotation": [-0.1305, 0.0, 0.0, 0.9914]},
                  {"name": "sun", "rotation": [-0.3320, 0.3320, 0.1375, 0.8717],
                   "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "scenes": [{"nodes": [0, 1, 2, 3, 4]}]})
    write("scale.gltf", b, gltf)


def lights_scene():
    b = Builder()
    # A closed box (outward winding) around a point light: nothing may get out.
    cube = unit_cube()
    zero_area = ([[0.0, 0.5, 0.0], [0.5, 0.5, 0.0], [1.0, 0.5, 0.0]], [[0.0, -1.0, 0.0]] * 3,
                 [0, 1, 2])
    s = 1e-4  # a 1e-4 m triangle of 1e8 nits: tiny and very bright
    # Wound counter-clockwise seen from below, as its normals say: a single-sided emitter
    # lights the floor from its front face only.
    tiny = ([[-0.8, 0.6, 0.0], [-0.8 + s, 0.6, 0.0], [-0.8, 0.6, s]], [[0.0, -1.0, 0.0]] * 3,
            [0, 1, 2])
    gltf = {
        "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_specular",
                           "KHR_materials_emissive_strength"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "boxed", "type": "point", "intensity": photometric(100.0)},
            {"name": "dark", "type": "spot", "intensity": 0.0, "spot": {}}]}},
        "materials": [lambertian("white"), emitter("zero-area", 10.0), emitter("tiny", 1e8)],
        "meshes": [{"name": "floor", "primitives": [b.primitive(*grid(2, 2.0, -0.5), 0)]},
                   {"name": "box", "primitives": [b.primitive(*cube, 0)]},
                   {"name": "zero-area", "primitives": [b.primitive(*zero_area, 1)]},
                   {"name": "tiny", "primitives": [b.primitive(*tiny, 2)]}],
        "nodes": [{"name": "floor", "mesh": 0},
                  {"name": "box", "mesh": 1, "translation": [0.8, 0.0, 0.0],
                   "scale": [0.4, 0.4, 0.4]},
                  {"name": "boxed", "translation": [0.8, 0.0, 0.0],
                   "extensions": {"KHR_lights_punctual": {"light": 0}}},
                  {"name": "zero-area", "mesh": 2},
                  {"name": "tiny", "mesh": 3},
                  {"name": "dark", "translation": [0.0, 1.0, 0.0], "rotation": down_quaternion(),
                   "extensions": {"KHR_lights_punctual": {"light": 1}}}],
        "scenes": [{"nodes": [0, 1, 2, 3, 4, 5]}]}
    write("lights.gltf", b, gltf)


def bad_geometry():
    b = Builder()
    # One primitive with a zero-area triangle (repeated index), a collinear one, duplicate
    # vertices (the same corner twice) and a vertex whose normal is zero.
    pos = [[-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1], [1, 0, 1], [0, 0, 0], [2, 0, 0]]
    nrm = [[0, 1, 0], [0, 1, 0], [0, 0, 0], [0, 1, 0], [0, 1, 0], [0, 1, 0], [0, 1, 0]]
    idx = [0, 1, 2, 0, 4, 3, 0, 0, 1, 5, 6, 4]
    pos = [[float(c) for c in p] for p in pos]
    nrm = [[float(c) for c in n] for n in nrm]
    gltf = sun()
    gltf.update({
        "materials": [lambertian("white")],
        "meshes": [{"name": "bad", "primitives": [b.primitive(pos, nrm, idx, 0)]},
                   {"name": "ball", "primitives": [b.primitive(*uv_sphere(6, 12), 0)]}],
        "nodes": [{"name": "bad", "mesh": 0},
                  {"name": "mirrored", "mesh": 1, "translation": [0.0, 1.0, 0.0],
                   "scale": [-0.5, 0.5, 0.5]},
                  {"name": "squashed", "mesh": 1, "translation": [0.0, 1.0, 2.0],
                   "scale": [2.0, 0.25, 1.0]},
                  {"name": "sun", "rotation": down_quaternion(),
                   "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "scenes": [{"nodes": [0, 1, 2, 3]}]})
    write("bad-geometry.gltf", b, gltf)


def png_rgb(r, g, b):
    """A 1 x 1 8-bit RGB PNG."""
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
    raw = bytes([0, r, g, b])
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 1, 1, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def bump_plane():
    b = Builder()
    pos, nrm, idx = quad([[-1, 0, 1], [1, 0, 1], [1, 0, -1], [-1, 0, -1]], [0, 1, 0])
    prim = b.primitive([[float(c) for c in p] for p in pos], [[float(c) for c in n] for n in nrm],
                       idx, 0)
    uv = struct.pack("<8f", 0, 1, 1, 1, 1, 0, 0, 0)  # u along +x, v along -z (glTF UVs)
    b.accessors.append({"bufferView": b._view(uv, 34962), "componentType": 5126, "count": 4,
                        "type": "VEC2"})
    prim["attributes"]["TEXCOORD_0"] = len(b.accessors) - 1
    prim["attributes"]["TANGENT"] = b.vec4([[1.0, 0.0, 0.0, 1.0]] * 4)
    # Tangent-space normal (sin 40, 0, cos 40) as 8-bit RGB: tilted towards +x.
    tilt = math.radians(40)
    texel = [round(255 * (0.5 + 0.5 * c)) for c in (math.sin(tilt), 0.0, math.cos(tilt))]
    gltf = sun()
    gltf.update({
        "materials": [dict(lambertian("white"), normalTexture={"index": 0})],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9728, "minFilter": 9728}],
        "images": [{"uri": "data:image/png;base64," +
                    base64.b64encode(png_rgb(*texel)).decode("ascii")}],
        "meshes": [{"name": "plane", "primitives": [prim]}],
        "nodes": [{"name": "plane", "mesh": 0},
                  {"name": "sun", "rotation": down_quaternion(),
                   "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "scenes": [{"nodes": [0, 1]}]})
    write("bump-plane.gltf", b, gltf)


if __name__ == "__main__":
    acne_plane()
    thin_sheets()
    terminator_sphere()
    scale_scene()
    lights_scene()
    bad_geometry()
    bump_plane()
