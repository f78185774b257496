#!/usr/bin/env python3
"""Fills a libFuzzer seed corpus for the glTF loader: every .gltf/.glb under the given
folders up to --max-bytes (default 1 MiB; larger seeds slow every mutation), copied as they
are, with a .gltf's external buffers and images inlined as data: URIs (the fuzz target's
input has no folder of its own to find them in), plus a .glb made from each .gltf whose
buffers are then all data: URIs (buffer 0 moved into the GLB's BIN chunk), so that the
binary path starts from valid files too. The source files are only read."""
import argparse
import base64
import json
import pathlib
import shutil
import struct
import urllib.parse


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


def inline_external(doc, folder):
    """The document with the buffers and images it names by relative URI, where those
    files exist, as data: URIs; None when it names none."""
    changed = False
    for kind in ("buffers", "images"):
        for item in doc.get(kind, []):
            uri = item.get("uri", "") if isinstance(item, dict) else ""
            if not uri or uri.startswith("data:") or "://" in uri:
                continue
            path = folder / urllib.parse.unquote(uri)
            if not path.is_file():
                continue
            item["uri"] = ("data:application/octet-stream;base64," +
                           base64.b64encode(path.read_bytes()).decode())
            changed = True
    return doc if changed else None


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("out")
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--max-bytes", type=int, default=1 << 20)
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    count = skipped = 0

    def write(name, data):
        nonlocal count, skipped
        if len(data) > args.max_bytes:
            skipped += 1
            return
        (out / name).write_bytes(data)
        count += 1

    for folder in args.folders:
        for src in sorted(pathlib.Path(folder).rglob("*")):
            if src.suffix not in (".gltf", ".glb") or not src.is_file():
                continue
            stem = "_".join(src.relative_to(folder).with_suffix("").parts)
            if src.suffix == ".glb":
                write(stem + ".glb", src.read_bytes())
                continue
            try:
                doc = json.loads(src.read_text())
                inlined = inline_external(doc, src.parent) if isinstance(doc, dict) else None
            except (ValueError, KeyError, IndexError, TypeError, AttributeError):
                doc = inlined = None  # a deliberately broken file: the copy is the seed
            if inlined is None:
                write(stem + ".gltf", src.read_bytes())
            else:
                write(stem + ".gltf", json.dumps(inlined).encode())
            try:
                glb = to_glb(inlined or doc) if isinstance(doc, dict) else None
            except (ValueError, KeyError, IndexError, TypeError, AttributeError):
                glb = None
            if glb:
                write(stem + ".glb", glb)
    print(f"seeds: {count} files ({skipped} over {args.max_bytes} bytes left out)")


if __name__ == "__main__":
    main()
