#!/usr/bin/env python3
"""Batch throughput of penumbra against Blender's Cycles on one task, side by side on
this machine: N assets, V orbit views each, SIZE^2 pixels, SPP samples, RGB + depth +
normal + object index, under a uniform white environment, all cores.

penumbra: one command per asset (`render --views orbit:V`, one load per asset). Blender:
one process that imports every asset and renders the same cameras (penumbra's
transforms.json) with matched settings (blender_views.py). Both wall times include
start-up and loading; the ratio is in images per hour.

Assets Blender cannot import (Debian's Blender lacks Draco and meshopt; webp required)
are left out of both totals and named.

Usage: scripts/throughput/vs_blender.py [--penumbra build/bin/penumbra] [--assets N]
       [--views 8] [--size 256] [--spp 32] [--out build/throughput] [--skip-blender]
"""
import argparse
import glob
import json
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def wild_assets(shared, count):
    """The first `count` folders of scenes/wild (by name) with a glTF file."""
    found = []
    for folder in sorted(glob.glob(os.path.join(shared, "scenes", "wild", "*"))):
        files = sorted(glob.glob(os.path.join(folder, "*.glb")) +
                       glob.glob(os.path.join(folder, "*.gltf")))
        if files:
            found.append(files[0])
    return found[:count]


def run_penumbra(args, assets):
    seconds = {}
    for asset in assets:
        name = os.path.splitext(os.path.basename(asset))[0]
        out = os.path.join(args.out, "penumbra", name)
        cmd = [args.penumbra, "render", asset, "--views", "orbit:%d" % args.views,
               "--width", str(args.size), "--height", str(args.size), "--spp", str(args.spp),
               "--aov", "depth,normal,object_id", "--env-color", "1", "1", "1",
               "-o", os.path.join(out, "{view}.exr"), "--overwrite", "--no-preview", "-q"]
        start = time.time()
        subprocess.run(cmd, check=True)
        seconds[name] = time.time() - start
    return seconds


def run_blender(args, assets):
    job = {"assets": [], "spp": args.spp, "max_depth": 8, "threads": os.cpu_count(),
           "env": [1, 1, 1]}
    for asset in assets:
        name = os.path.splitext(os.path.basename(asset))[0]
        job["assets"].append({
            "scene": asset,
            "transforms": os.path.join(args.out, "penumbra", name, "transforms.json"),
            "out": os.path.join(args.out, "blender", name)})
    path = os.path.join(args.out, "blender_job.json")
    with open(path, "w") as f:
        json.dump(job, f)
    start = time.time()
    run = subprocess.run([args.blender, "-b", "--factory-startup", "-P",
                          os.path.join(HERE, "blender_views.py"), "--", path],
                         capture_output=True, text=True)
    wall = time.time() - start
    lines = [l for l in run.stdout.splitlines() if l.startswith("THROUGHPUT ")]
    if run.returncode != 0 or not lines:
        sys.exit("blender failed:\n" + run.stdout[-3000:] + run.stderr[-3000:])
    result = json.loads(lines[-1][len("THROUGHPUT "):])
    result["wall_s"] = wall
    return result


def add_tool_arguments(p):
    """The binaries and the shared assets, as the throughput scripts take them."""
    p.add_argument("--penumbra", default=os.path.join(ROOT, "build", "bin", "penumbra"))
    p.add_argument("--blender", default=shutil.which("blender") or "blender")
    p.add_argument("--shared", default=os.environ.get("PENUMBRA_SHARED_DIR",
                                                      os.path.join(ROOT, "..", "shared")))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_tool_arguments(p)
    p.add_argument("--assets", type=int, default=100)
    p.add_argument("--views", type=int, default=8)
    p.add_argument("--size", type=int, default=256)
    p.add_argument("--spp", type=int, default=32)
    p.add_argument("--out", default=os.path.join(ROOT, "build", "throughput"))
    p.add_argument("--skip-blender", action="store_true")
    args = p.parse_args()
    assets = wild_assets(args.shared, args.assets)
    os.makedirs(args.out, exist_ok=True)
    pen = run_penumbra(args, assets)
    print("penumbra: %s" % ", ".join("%s %.1f s" % kv for kv in pen.items()))
    if args.skip_blender:
        return
    blend = run_blender(args, assets)
    for name, why in blend["skipped"].items():
        print("blender could not import %s (%s): left out of both" % (name, why))
    # The assets both rendered: Blender's wall time (one process, start-up included)
    # against the sum of penumbra's commands for them.
    common = [os.path.splitext(n)[0] for n in blend["seconds"]]
    images = len(common) * args.views
    pen_total = sum(pen[n] for n in common)
    print("blender:  %s" % ", ".join("%s %.1f s" % kv for kv in blend["seconds"].items()))
    print("%d assets, %d images: penumbra %.1f s, blender %.1f s wall (%.1f after start-up)" % (
        len(common), images, pen_total, blend["wall_s"], blend["total_s"]))
    print("images per hour: penumbra %.0f, blender %.0f: %.2fx" % (
        3600 * images / pen_total, 3600 * images / blend["wall_s"], blend["wall_s"] / pen_total))

if __name__ == "__main__":
    main()
