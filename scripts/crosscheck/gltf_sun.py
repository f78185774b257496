"""Reads the JSON of a .gltf/.glb and writes a copy of the file with one more light, a
KHR_lights_punctual directional "sun", so that penumbra and Blender's importer both
light a model with the same sun. The copy goes to a scratch folder outside the project;
a .gltf's external buffers and images stay where they are (relative URIs to them), a
.glb's binary chunk is copied as it is.
"""
import json
import math
import os
import struct

GLB_MAGIC, GLB_JSON, GLB_BIN = b"glTF", 0x4E4F534A, 0x004E4942


def read_glb(data):
    """(JSON document, binary chunk or None) of a .glb's bytes."""
    length = struct.unpack_from("<I", data, 8)[0]
    offset, doc, binary = 12, None, None
    while offset + 8 <= min(length, len(data)):
        size, kind = struct.unpack_from("<II", data, offset)
        chunk = data[offset + 8:offset + 8 + size]
        if kind == GLB_JSON:
            doc = json.loads(chunk.decode("utf-8"))
        elif kind == GLB_BIN and binary is None:
            binary = chunk
        offset += 8 + size
    return doc, binary


def read_json(path):
    """The JSON document of a .gltf or a .glb."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] == GLB_MAGIC:
        return read_glb(data)[0]
    return json.loads(data.decode("utf-8"))


def write_glb(path, doc, binary):
    """A .glb of doc and binary (chunks padded to 4 bytes: JSON with spaces, BIN with 0)."""
    text = json.dumps(doc).encode("utf-8")
    text += b" " * (-len(text) % 4)
    chunks = struct.pack("<II", len(text), GLB_JSON) + text
    if binary is not None:
        binary += b"\0" * (-len(binary) % 4)
        chunks += struct.pack("<II", len(binary), GLB_BIN) + binary
    with open(path, "wb") as f:
        f.write(GLB_MAGIC + struct.pack("<II", 2, 12 + len(chunks)) + chunks)


def rotation_from_minus_z(d):
    """The unit quaternion (x, y, z, w) turning -Z (a glTF light's direction) onto d."""
    n = math.sqrt(sum(c * c for c in d))
    b = [c / n for c in d]
    dot = -b[2]  # a = (0, 0, -1)
    if dot < -0.999999:  # opposite: half a turn about X
        return [1.0, 0.0, 0.0, 0.0]
    axis = [b[1], -b[0], 0.0]  # a x b
    q = axis + [1 + dot]
    n = math.sqrt(sum(c * c for c in q))
    return [c / n for c in q]


def with_sun(path, out_dir, lux, towards_sun):
    """Writes OUT_DIR/<name> with a white directional light of `lux` shining from the
    direction towards_sun (world space, +Y up) and returns its path."""
    with open(path, "rb") as f:
        data = f.read()
    glb = data[:4] == GLB_MAGIC
    doc, binary = read_glb(data) if glb else (json.loads(data.decode("utf-8")), None)
    # External files stay in place: URIs relative to the copy's folder.
    src_dir = os.path.dirname(os.path.abspath(path))
    for item in doc.get("buffers", []) + doc.get("images", []):
        uri = item.get("uri")
        if uri and not uri.startswith("data:") and "://" not in uri:
            item["uri"] = os.path.relpath(os.path.join(src_dir, uri), out_dir)
    used = doc.setdefault("extensionsUsed", [])
    if "KHR_lights_punctual" not in used:
        used.append("KHR_lights_punctual")
    lights = doc.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {})
    lights.setdefault("lights", []).append(
        {"name": "crosscheck sun", "type": "directional", "color": [1, 1, 1], "intensity": lux})
    doc.setdefault("nodes", []).append(
        {"name": "crosscheck sun", "rotation": rotation_from_minus_z([-c for c in towards_sun]),
         "extensions": {"KHR_lights_punctual": {"light": len(lights["lights"]) - 1}}})
    scenes = doc.setdefault("scenes", [{"nodes": []}])
    scenes[doc.get("scene", 0)].setdefault("nodes", []).append(len(doc["nodes"]) - 1)
    out = os.path.join(out_dir, os.path.basename(path))
    if glb:
        write_glb(out, doc, binary)
    else:
        with open(out, "w") as f:
            json.dump(doc, f)
    return out
