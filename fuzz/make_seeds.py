#!/usr/bin/env python3
"""Fills a libFuzzer seed corpus for the glTF loader: every .gltf/.glb under the given
folders up to --max-bytes (default 1 MiB; larger seeds slow every mutation), with a .gltf's
external buffers and images inlined as data: URIs (the fuzz target's input has no folder of
its own to find them in), plus a .glb made from each .gltf whose buffers are then all data:
URIs (buffer 0 moved into the GLB's BIN chunk), so that the binary path starts from valid
files too.

PNG and JPEG images wider or taller than --max-image-side (default 64) pixels are scaled
down to it with oiiotool, in their own format, and the buffers holding them repacked:
decoding megapixel textures and their mip pyramids would otherwise take most of each run,
and their bytes most of each seed, while a small image reaches the same decoder and
texture code. Palette and interlaced PNGs and progressive JPEGs stay as they are, since
oiiotool would write them in another encoding. Files whose images stay as they are (none too large, no oiiotool, a format
it cannot read or write) are copied byte for byte. The source files are only read."""
import argparse
import base64
import hashlib
import json
import pathlib
import shutil
import struct
import subprocess
import tempfile
import urllib.parse


def pack_glb(doc, payload):
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    payload += b"\0" * (-len(payload) % 4)
    body = struct.pack("<I4s", len(text), b"JSON") + text
    body += struct.pack("<I4s", len(payload), b"BIN\0") + payload
    return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


def to_glb(doc):
    buffers = doc.get("buffers", [])
    if not buffers or not all(b.get("uri", "").startswith("data:") for b in buffers):
        return None
    first = buffers[0]
    payload = base64.b64decode(first["uri"].split(",", 1)[1])
    doc = json.loads(json.dumps(doc))
    del doc["buffers"][0]["uri"]
    doc["buffers"][0]["byteLength"] = len(payload)
    return pack_glb(doc, payload)


def unpack_glb(data):
    """The JSON document and BIN chunk (None if absent) of a GLB."""
    if len(data) < 20 or data[:4] != b"glTF":
        raise ValueError("not a GLB")
    length, kind = struct.unpack_from("<I4s", data, 12)
    if kind != b"JSON":
        raise ValueError("no JSON chunk")
    doc = json.loads(data[20:20 + length])
    at = 20 + length
    if at + 8 <= len(data) and data[at + 4:at + 8] == b"BIN\0":
        size = struct.unpack_from("<I", data, at)[0]
        return doc, data[at + 8:at + 8 + size]
    return doc, None


def image_size(data):
    """(width, height) of a PNG that is neither palette nor interlaced, or of a baseline or
    extended sequential JPEG (SOF0, SOF1); None otherwise. oiiotool writes only those
    encodings, so other images stay as they are and keep their decoder paths in the seeds."""
    if data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) >= 29 and data[12:16] == b"IHDR":
        palette, interlaced = data[25] == 3, data[28] != 0
        return None if palette or interlaced else struct.unpack_from(">II", data, 16)
    if data[:2] != b"\xff\xd8":
        return None
    at = 2
    while at + 9 <= len(data) and data[at] == 0xFF:
        marker = data[at + 1]
        if 0xC0 <= marker <= 0xCF and marker not in (0xC4, 0xC8, 0xCC):
            height, width = struct.unpack_from(">HH", data, at + 5)
            return (width, height) if marker in (0xC0, 0xC1) else None
        at += 2 + struct.unpack_from(">H", data, at + 2)[0]
    return None


class ImageShrinker:
    """Scales PNG and JPEG images down to at most max_side pixels a side, in their own
    format, with one oiiotool run for all of them (each run starts by loading OIIO's
    plugins). Called with an image's bytes it returns the scaled copy once `run` has made
    it, else the same bytes, noting the image for the next `run`. Copies are kept in
    `cache` (a folder, optional) by the source's hash, so that later corpora skip oiiotool."""

    def __init__(self, max_side, cache=None):
        self.max_side = max_side
        self.cache = pathlib.Path(cache) if cache else None
        self.tool = shutil.which("oiiotool")
        self.todo = {}
        self.done = {}

    def __call__(self, data):
        size = image_size(data)
        if not size or max(size) <= self.max_side or min(size) == 0 or not self.tool:
            return data
        key = hashlib.sha1(data + str(self.max_side).encode()).hexdigest()
        if key not in self.done and self.cache and (self.cache / key).is_file():
            self.done[key] = (self.cache / key).read_bytes()
        if key in self.done:
            return self.done[key] or data
        self.todo[key] = (data, size)
        return data

    def run(self):
        if not self.todo:
            return
        with tempfile.TemporaryDirectory() as tmp:
            jobs = []
            for key, (data, size) in self.todo.items():
                ext = ".png" if data[:4] == b"\x89PNG" else ".jpg"
                src, dst = pathlib.Path(tmp, key + ext), pathlib.Path(tmp, key + ".out" + ext)
                src.write_bytes(data)
                scale = self.max_side / max(size)
                width, height = (max(1, round(side * scale)) for side in size)
                jobs.append((key, [str(src), "--resize", f"{width}x{height}", "-o", str(dst)],
                             dst))
            # One run for all; if an image breaks it, one run per image. Without
            # --nosoftwareattrib each image would carry the whole command line.
            tool = [self.tool, "--nosoftwareattrib"]
            batch = tool + [arg for _, args, _ in jobs for arg in args]
            if subprocess.run(batch, stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL).returncode != 0:
                for _, args, _ in jobs:
                    subprocess.run(tool + args, stdout=subprocess.DEVNULL,
                                   stderr=subprocess.DEVNULL)
            for key, _, dst in jobs:
                self.done[key] = dst.read_bytes() if dst.is_file() else b""
                if self.cache:
                    self.cache.mkdir(parents=True, exist_ok=True)
                    (self.cache / key).write_bytes(self.done[key])
        self.todo = {}


def data_uri_bytes(uri):
    return base64.b64decode(uri.split(",", 1)[1]) if uri.startswith("data:") else None


def repack(doc, data, replaced):
    """Rebuilds the buffers that have bytes (data[i] not None) from the byte ranges their
    bufferViews and meshopt extensions name, in order and 4-byte aligned, with the views in
    `replaced` given new bytes; updates the offsets and lengths in doc and returns the new
    bytes by buffer index."""
    out = {i: bytearray() for i, d in enumerate(data) if d is not None}

    def place(holder, buffer, src):
        b = out[buffer]
        b.extend(b"\0" * (-len(b) % 4))
        holder["byteOffset"] = len(b)
        holder["byteLength"] = len(src)
        b.extend(src)

    def bytes_of(holder, buffer):
        start = holder.get("byteOffset", 0)
        return data[buffer][start:start + holder["byteLength"]]

    for index, view in enumerate(doc.get("bufferViews", [])):
        for name in ("EXT_meshopt_compression", "KHR_meshopt_compression"):
            ext = view.get("extensions", {}).get(name)
            if isinstance(ext, dict) and ext.get("buffer") in out:
                place(ext, ext["buffer"], bytes_of(ext, ext["buffer"]))
        if view.get("buffer") in out:
            src = replaced[index] if index in replaced else bytes_of(view, view["buffer"])
            place(view, view["buffer"], src)
    for i, b in out.items():
        doc["buffers"][i]["byteLength"] = len(b)
    return {i: bytes(b) for i, b in out.items()}


def shrink_images(doc, data, shrink):
    """Scales down the document's images (data: URIs in place, bufferViews by repacking
    `data`, the bytes of each buffer or None); returns the new buffer bytes by index, or
    None when no image changed."""
    changed = False
    replaced = {}
    for image in doc.get("images", []):
        if not isinstance(image, dict):
            continue
        uri = image.get("uri", "")
        if isinstance(uri, str) and uri.startswith("data:"):
            old = data_uri_bytes(uri)
            new = shrink(old)
            if new != old:
                image["uri"] = uri.split(",", 1)[0] + "," + base64.b64encode(new).decode()
                changed = True
        elif "bufferView" in image:
            view = doc["bufferViews"][image["bufferView"]]
            if data[view["buffer"]] is None:
                continue
            start = view.get("byteOffset", 0)
            old = data[view["buffer"]][start:start + view["byteLength"]]
            new = shrink(old)
            if new != old:
                replaced[image["bufferView"]] = new
    if replaced:
        return repack(doc, data, replaced)
    return {} if changed else None


def shrunk_glb(raw, shrink):
    """The GLB with its images scaled down, or None when none changed."""
    doc, payload = unpack_glb(raw)
    data = [payload if i == 0 and "uri" not in b else data_uri_bytes(b.get("uri", ""))
            for i, b in enumerate(doc.get("buffers", []))]
    new = shrink_images(doc, data, shrink)
    if new is None:
        return None
    for i, b in new.items():
        if i != 0 or "uri" in doc["buffers"][0]:
            doc["buffers"][i]["uri"] = ("data:application/octet-stream;base64," +
                                        base64.b64encode(b).decode())
    return pack_glb(doc, new.get(0, payload) if payload is not None else b"")


def shrunk_gltf(doc, shrink):
    """The .gltf document (buffers as data: URIs) with its images scaled down, or None when
    none changed."""
    doc = json.loads(json.dumps(doc))
    data = [data_uri_bytes(b.get("uri", "")) for b in doc.get("buffers", [])]
    new = shrink_images(doc, data, shrink)
    if new is None:
        return None
    for i, b in new.items():
        doc["buffers"][i]["uri"] = ("data:application/octet-stream;base64," +
                                    base64.b64encode(b).decode())
    return doc


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


def make_corpus(folders, out, max_bytes, shrink):
    """Writes the seeds into `out` (None: only reads, so that `shrink` learns the images
    it is to scale down); returns the counts written, left out and with images scaled."""
    count = skipped = shrunk = 0

    def write(name, data):
        nonlocal count, skipped
        if len(data) > max_bytes:
            skipped += 1
        elif out:
            (out / name).write_bytes(data)
            count += 1

    for folder in folders:
        for src in sorted(pathlib.Path(folder).rglob("*")):
            if src.suffix not in (".gltf", ".glb") or not src.is_file():
                continue
            stem = "_".join(src.relative_to(folder).with_suffix("").parts)
            if src.suffix == ".glb":
                raw = src.read_bytes()
                try:
                    small = shrunk_glb(raw, shrink)
                except (ValueError, KeyError, IndexError, TypeError, AttributeError,
                        struct.error):
                    small = None  # a deliberately broken file: the copy is the seed
                shrunk += small is not None
                write(stem + ".glb", small or raw)
                continue
            try:
                doc = json.loads(src.read_text())
                inlined = inline_external(doc, src.parent) if isinstance(doc, dict) else None
            except (ValueError, KeyError, IndexError, TypeError, AttributeError):
                doc = inlined = None  # a deliberately broken file: the copy is the seed
            try:
                small = shrunk_gltf(inlined or doc, shrink) if isinstance(doc, dict) else None
            except (ValueError, KeyError, IndexError, TypeError, AttributeError):
                small = None  # images in a broken file stay as they are
            if small is not None:
                inlined = small
                shrunk += 1
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
    return count, skipped, shrunk


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("out")
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--max-bytes", type=int, default=1 << 20)
    parser.add_argument("--max-image-side", type=int, default=64)
    parser.add_argument("--image-cache", help="folder keeping scaled images between runs")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    shrink = ImageShrinker(args.max_image_side, args.image_cache)
    make_corpus(args.folders, None, args.max_bytes, shrink)
    shrink.run()
    count, skipped, shrunk = make_corpus(args.folders, out, args.max_bytes, shrink)
    print(f"seeds: {count} files ({skipped} over {args.max_bytes} bytes left out; "
          f"images scaled down in {shrunk} sources)")


if __name__ == "__main__":
    main()
