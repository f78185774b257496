#!/usr/bin/env python3
"""Fills a libFuzzer seed corpus for the glTF loader: every .gltf/.glb under the given
folders, copied as they are, plus a .glb made from each .gltf whose buffers are all data:
URIs (buffer 0 moved into the GLB's BIN chunk), so that the binary path starts from valid
files too. The source files are only read."""
import base64
import json
import pathlib
import shutil
import struct
import sys


def to_glb(doc):
    buffers = doc.get("buffers", [])
    if not buffers or not all(b.get("uri", "").startswith("data:") for b in buffers):
        return None
    first = buffers[0]
    payload = base64.b64decode(first["uri"].split(",", 1)[1])
    doc = json.loads(json.dumps(doc))
    del doc["buffers"][0]["uri"]
    doc["buffers"][0]["byteLength"] = len(payload)
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    payload += b"\0" * (-len(payload) % 4)
    body = struct.pack("<I4s", len(text), b"JSON") + text
    body += struct.pack("<I4s", len(payload), b"BIN\0") + payload
    return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


def main():
    out = pathlib.Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    count = 0
    for folder in sys.argv[2:]:
        for src in sorted(pathlib.Path(folder).rglob("*")):
            if src.suffix not in (".gltf", ".glb") or not src.is_file():
                continue
            stem = "_".join(src.relative_to(folder).with_suffix("").parts)
            shutil.copyfile(src, out / (stem + src.suffix))
            count += 1
            if src.suffix == ".gltf":
                try:
                    glb = to_glb(json.loads(src.read_text()))
                except (ValueError, KeyError, IndexError):
                    glb = None  # a deliberately broken file: the copy is the seed
                if glb:
                    (out / (stem + ".glb")).write_bytes(glb)
                    count += 1
    print(f"seeds: {count} files")


if __name__ == "__main__":
    main()
