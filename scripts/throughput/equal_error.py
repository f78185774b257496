#!/usr/bin/env python3
"""Images per hour at equal error: penumbra at SPP samples with --denoise against Blender
3.4's Cycles raw (Debian's Blender has no Open Image Denoise), on the task of
vs_blender.py (orbit views, SIZE^2 pixels, RGB + depth + normal + object index, a uniform
white environment, matched bounces and clamping, all cores).

Each renderer's error is its relMSE (core/film/image_error.h: epsilon 0.01, RGB) against
its own reference at REF_SPP samples, so the comparison measures noise, not the small
shading differences between the two renderers. Blender renders at several sample counts;
its relMSE falls as 1/spp, so a least-squares line through log relMSE against log spp
gives the count at which it matches penumbra's denoised error, and its time there comes
from the line through its times (import and start-up included, as in vs_blender.py).

Usage: scripts/throughput/equal_error.py [--assets Fox,FlightHelmet,...] [--views 2]
       [--size 256] [--spp 32] [--ref-spp 1024] [--blender-spp 32,128,512] [--out DIR]
       [--reuse-references]   (keep the references of an earlier run in DIR: they take
                               most of the time, and the timed renders do not need them)
"""
import argparse
import glob
import json
import math
import os
import subprocess
import sys
import time

import numpy
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import vs_blender  # noqa: E402  (its Blender runner and asset list)

EPSILON = 1e-2


def rgb(path):
    """The RGB of an EXR: penumbra's main layer, or Blender's ViewLayer.Combined."""
    image = oiio.ImageInput.open(path)
    if image is None:
        sys.exit("cannot read %s" % path)
    names = list(image.spec().channelnames)
    pixels = image.read_image(oiio.FLOAT)
    image.close()
    for prefix in ("", "ViewLayer.Combined."):
        if all(prefix + c in names for c in "RGB"):
            return numpy.stack([pixels[..., names.index(prefix + c)] for c in "RGB"], -1)
    sys.exit("%s: no RGB channels in %s" % (path, names))


def relmse(image, reference):
    return float(numpy.mean((image - reference) ** 2 / (reference ** 2 + EPSILON)))


def penumbra(args, asset, spp, out, extra=()):
    """One command for all views of asset; returns the wall seconds."""
    cmd = [args.penumbra, "render", asset, "--views", "orbit:%d" % args.views,
           "--width", str(args.size), "--height", str(args.size), "--spp", str(spp),
           "--aov", "depth,normal,object_id", "--env-color", "1", "1", "1",
           "-o", os.path.join(out, "{view}.exr"), "--overwrite", "--no-preview", "-q", *extra]
    start = time.time()
    subprocess.run(cmd, check=True)
    return time.time() - start


def blender(args, assets, spp, tag):
    """Blender's views of every asset at spp; returns {name: wall seconds}."""
    job = argparse.Namespace(blender=args.blender, spp=spp, out=os.path.join(args.out, tag))
    os.makedirs(job.out, exist_ok=True)
    # vs_blender.run_blender reads penumbra's transforms.json under out/penumbra/NAME.
    for asset in assets:
        name = os.path.splitext(os.path.basename(asset))[0]
        link = os.path.join(job.out, "penumbra", name)
        os.makedirs(os.path.dirname(link), exist_ok=True)
        if not os.path.exists(link):
            os.symlink(os.path.join(args.out, "penumbra_ref", name), link)
    result = vs_blender.run_blender(job, assets)
    if result["skipped"]:
        sys.exit("blender could not import %s" % result["skipped"])
    return {os.path.splitext(n)[0]: s for n, s in result["seconds"].items()}


def mean_error(folder_of, reference_of, names, views, pattern):
    errors = [relmse(rgb(os.path.join(folder_of(n), pattern % v)),
                     rgb(os.path.join(reference_of(n), pattern % v)))
              for n in names for v in range(views)]
    return sum(errors) / len(errors)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    vs_blender.add_tool_arguments(p)
    p.add_argument("--assets", default="Fox,FlightHelmet,SheenCloth,AttenuationTest")
    p.add_argument("--views", type=int, default=2)
    p.add_argument("--size", type=int, default=256)
    p.add_argument("--spp", type=int, default=32)
    p.add_argument("--ref-spp", type=int, default=1024)
    p.add_argument("--blender-spp", default="32,128,512")
    p.add_argument("--out", default=os.path.join(ROOT, "build", "equal_error"))
    p.add_argument("--reuse-references", action="store_true")
    args = p.parse_args()
    wanted = args.assets.split(",")
    assets = [a for a in vs_blender.wild_assets(args.shared, 100)
              if os.path.basename(os.path.dirname(a)) in wanted]
    names = [os.path.splitext(os.path.basename(a))[0] for a in assets]
    out = lambda *parts: os.path.join(args.out, *parts)  # noqa: E731

    pen_seconds = {"raw": 0.0, "denoised": 0.0}
    for asset, name in zip(assets, names):
        if not (args.reuse_references and os.path.exists(out("penumbra_ref", name, "0000.exr"))):
            penumbra(args, asset, args.ref_spp, out("penumbra_ref", name))
        pen_seconds["raw"] += penumbra(args, asset, args.spp, out("penumbra_raw", name))
        pen_seconds["denoised"] += penumbra(args, asset, args.spp, out("penumbra_dn", name),
                                            ["--denoise"])
    pen_error = {kind: mean_error(lambda n, k=kind: out("penumbra_" + k, n),
                                  lambda n: out("penumbra_ref", n), names, args.views, "%04d.exr")
                 for kind in ("raw", "dn")}

    if not (args.reuse_references and
            all(os.path.exists(out("blender_ref", "blender", n, "0000.exr")) for n in names)):
        blender(args, assets, args.ref_spp, "blender_ref")
    counts = [int(s) for s in args.blender_spp.split(",")]
    b_error, b_seconds = [], []
    for spp in counts:
        seconds = blender(args, assets, spp, "blender_%d" % spp)
        b_seconds.append(sum(seconds.values()))
        b_error.append(mean_error(lambda n, s=spp: out("blender_%d" % s, "blender", n),
                                  lambda n: out("blender_ref", "blender", n), names,
                                  args.views, "%04d.exr"))
    # relMSE = c / spp^k (k near 1), seconds = a + b spp: both fitted by least squares.
    slope, intercept = numpy.polyfit(numpy.log(counts), numpy.log(b_error), 1)
    b, a = numpy.polyfit(counts, b_seconds, 1)
    # Blender's spp and seconds at the relMSE of penumbra's denoised and raw images.
    equal_spp = {k: math.exp((math.log(pen_error[k]) - intercept) / slope) for k in pen_error}
    equal_s = {k: a + b * spp for k, spp in equal_spp.items()}
    images = len(names) * args.views
    report = {
        "assets": names, "views": args.views, "size": args.size, "spp": args.spp,
        "ref_spp": args.ref_spp,
        "penumbra": {"raw_relmse": pen_error["raw"], "denoised_relmse": pen_error["dn"],
                     "raw_s": pen_seconds["raw"], "denoised_s": pen_seconds["denoised"]},
        "blender": {"spp": counts, "relmse": b_error, "seconds": b_seconds,
                    "relmse_slope": slope, "equal_error_spp": equal_spp,
                    "seconds_at_equal_error": equal_s},
    }
    print(json.dumps(report, indent=1))
    seconds = {"dn": pen_seconds["denoised"], "raw": pen_seconds["raw"]}
    for kind, label in (("dn", "denoised"), ("raw", "raw")):
        print("%d images: penumbra %d spp %s relMSE %.2e in %.1f s; blender reaches it at "
              "%.0f spp in %.1f s" % (images, args.spp, label, pen_error[kind], seconds[kind],
                                      equal_spp[kind], equal_s[kind]))
        print("  images per hour at equal error: penumbra %.0f, blender %.0f: %.2fx" % (
            3600 * images / seconds[kind], 3600 * images / equal_s[kind],
            equal_s[kind] / seconds[kind]))


if __name__ == "__main__":
    main()
