#!/usr/bin/env python3
"""Poses skinned glTF files with penumbra and with Blender 3.4's own glTF importer at
several times of each animation clip, and compares their silhouettes.

  python3 scripts/crosscheck/skin_pose.py FILE... [--fractions 0.1,0.35,0.6,0.85]
      [--times T,...] [--size 160] [--spp 16] [--max-px 1] [--out DIR]

Each clip is posed alone: a copy of the file keeps only that animation (penumbra plays all
of a file's animations together; the importer activates the first). For each time
penumbra renders first (its file camera, else its framing camera) and writes its camera
into the EXR header; Blender rebuilds it from there (blender_camera.py), poses the scene at
frame t x fps and renders with Cycles. Both give the coverage (one-pixel box
filter): penumbra's is its albedo AOV of the copy, whose materials are made white and
opaque (vertex colours dropped), and Blender's the alpha of a transparent film; a pixel is
in the silhouette when its coverage is at least 0.5. Reported per
time: IoU of the two silhouettes, and the largest disagreement, in pixels: over the pixels
in one silhouette and not the other, the largest distance to the nearest pixel of the
other silhouette (1: a pixel along the edge). Exits 1 when any exceeds --max-px, 2 when a
renderer fails, 77 when blender or oiiotool is missing. Standard library only here.
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

from compare_cycles import blender_env
from gltf_sun import GLB_MAGIC, read_glb, write_glb
from wild_models import exr_header, floats, pixels, run

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def clip_files(path, out_dir):
    """[(clip name, duration in s, path of a copy holding only that animation)]; one entry
    (None, 0, path of a copy) for a file without animations."""
    with open(path, "rb") as f:
        data = f.read()
    glb = data[:4] == GLB_MAGIC
    doc, binary = read_glb(data) if glb else (json.loads(data.decode("utf-8")), None)
    animations = doc.get("animations", [])
    src_dir = os.path.dirname(os.path.abspath(path))
    for item in doc.get("buffers", []) + doc.get("images", []):
        uri = item.get("uri")
        if uri and not uri.startswith("data:") and "://" not in uri:
            item["uri"] = os.path.relpath(os.path.join(src_dir, uri), out_dir)
    # Every material white, opaque and double-sided, vertex colours dropped: penumbra's
    # albedo AOV (a miss counting as zero) is then its coverage. Double-sided because
    # penumbra's camera rays cull single-sided back faces (seen through an open tube's
    # end) and Cycles draws them: the silhouette compares poses, not culling.
    doc["materials"] = [{"name": m.get("name", ""), "doubleSided": True,
                         "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1]}}
                        for m in doc.get("materials", [])]
    for mesh in doc.get("meshes", []):
        for prim in mesh.get("primitives", []):
            prim.get("attributes", {}).pop("COLOR_0", None)
    stem, ext = os.path.splitext(os.path.basename(path))

    def write(target, content):
        if glb:
            write_glb(target, content, binary)
        else:
            with open(target, "w") as f:
                json.dump(content, f)

    out = []
    for k, anim in enumerate(animations or [None]):
        if anim is None:
            target = os.path.join(out_dir, stem + ext)
            write(target, doc)
            out.append((None, 0.0, target))
            break
        name = anim.get("name") or "animation%d" % k
        duration = max(doc["accessors"][s["input"]].get("max", [0])[0] for s in anim["samplers"])
        target = os.path.join(out_dir, "%s-%d%s" % (stem, k, ext))
        write(target, dict(doc, animations=[anim]))
        out.append((name, duration, target))
    return out


def penumbra_render(args, scene, time, out):
    cmd = [args.penumbra, "render", scene, "-o", out, "--width", str(args.size), "--height",
           str(args.size), "--spp", str(args.spp), "--time", repr(time), "--filter", "box",
           "--max-depth", "1", "--no-default-light", "--env-color", "0", "0", "0",
           "--aperture-radius", "0", "--aov", "albedo", "--threads", str(args.threads), "--no-preview", "-q",
           "--overwrite"]
    rc, log, _ = run(cmd, args.timeout)
    if rc != 0 or not os.path.exists(out):
        lines = [l for l in log.splitlines() if l.strip()]
        raise RuntimeError("penumbra: " + (lines[-1] if lines else "exit status %s" % rc))


def blender_render(args, scene, renders, job_path):
    with open(job_path, "w") as f:
        json.dump({"scene": os.path.abspath(scene), "spp": args.spp, "threads": args.threads,
                   "renders": renders}, f)
    rc, log, _ = run(["blender", "-b", "--factory-startup", "-P",
                      os.path.join(HERE, "skin_pose_blender.py"), "--", job_path],
                     args.timeout, env=blender_env())
    for line in (log or "").splitlines():
        if line.startswith("SKINPOSE-ERROR "):
            raise RuntimeError("blender: " + line[len("SKINPOSE-ERROR "):])
        if line.startswith("SKINPOSE "):
            return
    lines = [l for l in (log or "").splitlines() if l.strip()]
    raise RuntimeError("blender exit %s: %s" % (rc, lines[-1] if lines else ""))


def silhouette(path, channel):
    """Width, height and the coverage >= 0.5 mask (row-major list of bools)."""
    width, height, _, _ = exr_header(path)
    return width, height, [a >= 0.5 for (a,) in pixels(path, [channel])]


def disagreement(a, b, width, height):
    """(IoU, largest distance in pixels from a pixel in one mask only to the other mask)."""
    inter = sum(1 for x, y in zip(a, b) if x and y)
    union = sum(1 for x, y in zip(a, b) if x or y)
    worst = 0.0
    for i, (x, y) in enumerate(zip(a, b)):
        if x == y:
            continue
        other = b if x else a
        px, py = i % width, i // width
        best = None
        # Rings of growing radius (up to 64: farther is reported as infinite); the nearest
        # pixel lies within radius r * sqrt(2).
        for r in range(1, min(max(width, height), 65)):
            for qy in range(max(py - r, 0), min(py + r, height - 1) + 1):
                for qx in range(max(px - r, 0), min(px + r, width - 1) + 1):
                    if other[qy * width + qx]:
                        d = math.hypot(qx - px, qy - py)
                        best = d if best is None else min(best, d)
            if best is not None and best <= r:
                break
        worst = max(worst, best if best is not None else float("inf"))
    return (inter / union if union else 1.0), worst


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("files", nargs="+")
    ap.add_argument("--fractions", default="0.1,0.35,0.6,0.85",
                    help="times as fractions of each clip's duration")
    ap.add_argument("--times", help="times in seconds instead of --fractions")
    ap.add_argument("--size", type=int, default=160)
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--max-px", type=float, default=1.0,
                    help="largest disagreement allowed, in pixels (exit 1 above)")
    ap.add_argument("--penumbra", default=os.path.join(ROOT, "build", "bin", "penumbra"))
    ap.add_argument("--out", help="folder for the renders (default: a temporary one, removed)")
    ap.add_argument("--json", help="write the results here")
    ap.add_argument("--timeout", type=int, default=600)
    args = ap.parse_args()
    if not shutil.which("blender") or not shutil.which("oiiotool"):
        print("skin_pose: blender or oiiotool missing; skipped")
        return 77
    out_dir = args.out or tempfile.mkdtemp(prefix="skin_pose-")
    os.makedirs(out_dir, exist_ok=True)
    results, status = [], 0
    try:
        for path in args.files:
            for clip, duration, scene in clip_files(path, out_dir):
                times = [float(t) for t in args.times.split(",")] if args.times else \
                    [round(float(f) * duration, 4) for f in args.fractions.split(",")]
                tag = os.path.splitext(os.path.basename(scene))[0]
                renders = []
                for t in times:
                    pen = os.path.join(out_dir, "%s-t%g-penumbra.exr" % (tag, t))
                    penumbra_render(args, scene, t, pen)
                    width, height, _, attrs = exr_header(pen)
                    renders.append({"time": t, "out": os.path.join(out_dir, "%s-t%g-blender.exr"
                                                                   % (tag, t)),
                                    "penumbra": pen, "width": width, "height": height,
                                    "world_to_camera": floats(attrs["worldToCamera"]),
                                    "world_to_ndc": floats(attrs["worldToNDC"])})
                blender_render(args, scene, renders, os.path.join(out_dir, tag + "-job.json"))
                for r in renders:
                    w, h, a = silhouette(r["penumbra"], "Albedo.R")
                    _, _, b = silhouette(r["out"], "A")
                    iou, worst = disagreement(a, b, w, h)
                    row = {"file": os.path.basename(path), "clip": clip, "time": r["time"],
                           "pixels": sum(a), "iou": iou, "max_px": worst}
                    results.append(row)
                    print("%-22s %-10s t=%-7g silhouette %6d px  IoU %.4f  largest "
                          "disagreement %.2f px" % (row["file"], clip or "-", r["time"],
                                                    row["pixels"], iou, worst))
                    sys.stdout.flush()
                    if worst > args.max_px:
                        status = 1
    except RuntimeError as e:
        print("skin_pose: %s" % e)
        status = 2
    finally:
        if args.json:
            with open(args.json, "w") as f:
                json.dump(results, f, indent=1)
        if not args.out:
            shutil.rmtree(out_dir, ignore_errors=True)
    return status


if __name__ == "__main__":
    sys.exit(main())
