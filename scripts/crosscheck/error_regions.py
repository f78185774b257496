#!/usr/bin/env python3
"""Where in the image each renderer's error lies: per-pixel relMSE of the harness's cached
renders (scripts/crosscheck/efficiency.py) against each renderer's own reference, by block.

  python3 scripts/crosscheck/error_regions.py --spp 128 \\
      --penumbra ~/.cache/penumbra-efficiency/helmet-*/penumbra-0.1.0-<build>-<settings> \\
      --cycles ~/.cache/penumbra-efficiency/helmet-*/cycles-3.4.1-v1-<settings> --out /tmp/helmet
      [--penumbra-reference FOLDER]  (where --reuse-references left the reference)

Each folder holds spp<N>-seed<K>.exr and the reference halves (seeds 1001 and 1002). The
relMSE is not corrected for the reference's own error, as efficiency.py's is (its "ref.
share" column says how much that is). Prints, per block of --block pixels, penumbra's
relMSE over Cycles' and
each block's share of each renderer's whole relMSE; with --out, writes OUT-penumbra.png
and OUT-cycles.png, maps of sqrt(relMSE) on one scale (white: --map-max). On FlightHelmet
they show the lenses holding 58% of penumbra's error (docs/performance.md). Standard
library only, as efficiency.py.
"""
import argparse
import glob
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from efficiency_metrics import EPSILON, average, read_rgb, write_pfm  # noqa: E402


def pixel_relmse(images, ref, eps=EPSILON):
    """Per pixel: the mean over the images and RGB of (x - ref)^2 / (ref^2 + eps)."""
    n = len(ref) // 3
    out = [0.0] * n
    for image in images:
        for i in range(n):
            s = 0.0
            for c in range(3):
                r = ref[3 * i + c]
                s += (image[3 * i + c] - r) ** 2 / (r * r + eps)
            out[i] += s / 3
    return [v / len(images) for v in out]


def block_sums(values, width, height, block):
    """Sums of per-pixel values over blocks of block x block pixels: rows of columns."""
    rows = []
    for by in range(0, height, block):
        row = []
        for bx in range(0, width, block):
            row.append(sum(values[y * width + x] for y in range(by, min(by + block, height))
                           for x in range(bx, min(bx + block, width))))
        rows.append(row)
    return rows


def block_table(a, b, width, height, block):
    """Per block: (ratio of a's sum to b's, share of a's total, share of b's total); the
    ratio is None where b's block is 0."""
    sa, sb = block_sums(a, width, height, block), block_sums(b, width, height, block)
    ta, tb = sum(map(sum, sa)) or 1.0, sum(map(sum, sb)) or 1.0
    return [[(x / y if y > 0 else None, x / ta, y / tb) for x, y in zip(ra, rb)]
            for ra, rb in zip(sa, sb)]


def cached(folder):
    """{spp: [(seed, path)]} of a cache folder's renders."""
    found = {}
    for path in glob.glob(os.path.join(folder, "spp*-seed*.exr")):
        m = re.match(r"spp(\d+)-seed(\d+)\.exr$", os.path.basename(path))
        if m:
            found.setdefault(int(m.group(1)), []).append((int(m.group(2)), path))
    return found


def renders(folder, spp, reference_folder=None):
    """(width, height, [images at spp], reference): the reference is the mean of the two
    halves (seeds 1001 and 1002) at the largest spp that has them, from reference_folder
    (default: folder; --reuse-references leaves them in another build's folder)."""
    found = cached(folder)
    if spp not in found:
        raise SystemExit("%s: no spp%d-seed*.exr (has spp %s)" % (folder, spp, sorted(found)))
    ref_found = cached(reference_folder or folder)
    halves = []
    for n in sorted(ref_found, reverse=True):
        halves = [p for s, p in sorted(ref_found[n]) if s in (1001, 1002)]
        if len(halves) == 2:
            break
    if len(halves) != 2:
        raise SystemExit("%s: no reference halves (seeds 1001 and 1002); give the folder "
                         "that has them" % (reference_folder or folder))
    w, h, a = read_rgb(halves[0])
    _, _, b = read_rgb(halves[1])
    images = [read_rgb(p)[2] for s, p in sorted(found[spp]) if s < 1000]
    return w, h, images, average(a, b)


def write_map(path, values, width, height, top):
    """sqrt(relMSE) / sqrt(top) as grey, clamped at white, written as PNG through oiiotool."""
    grey = [min(1.0, (v / top) ** 0.5) for v in values]
    with tempfile.TemporaryDirectory() as tmp:
        pfm = os.path.join(tmp, "map.pfm")
        write_pfm(pfm, width, height, [g for g in grey for _ in range(3)])
        subprocess.run(["oiiotool", pfm, "-d", "uint8", "-o", path], check=True,
                       capture_output=True)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--penumbra", required=True, help="penumbra's cache folder for the scene")
    ap.add_argument("--cycles", required=True, help="Cycles' cache folder for the same scene")
    ap.add_argument("--penumbra-reference", help="folder with penumbra's reference halves "
                    "(default: --penumbra's)")
    ap.add_argument("--cycles-reference", help="folder with Cycles' reference halves")
    ap.add_argument("--spp", type=int, required=True)
    ap.add_argument("--block", type=int, default=32)
    ap.add_argument("--out", help="write OUT-penumbra.png and OUT-cycles.png error maps")
    ap.add_argument("--map-max", type=float, default=1e-3, help="relMSE shown as white")
    args = ap.parse_args(argv)
    w, h, p_images, p_ref = renders(args.penumbra, args.spp, args.penumbra_reference)
    wc, hc, c_images, c_ref = renders(args.cycles, args.spp, args.cycles_reference)
    if (w, h) != (wc, hc):
        raise SystemExit("image sizes differ: %dx%d and %dx%d" % (w, h, wc, hc))
    p, c = pixel_relmse(p_images, p_ref), pixel_relmse(c_images, c_ref)
    print("relMSE at %d spp (%d and %d images): penumbra %.3g, Cycles %.3g, ratio %.2f"
          % (args.spp, len(p_images), len(c_images), sum(p) / len(p), sum(c) / len(c),
             sum(p) / max(sum(c), 1e-30)))
    table = block_table(p, c, w, h, args.block)
    for title, k, fmt in (("penumbra / Cycles per block", 0, "%5.2f"),
                          ("share of penumbra's relMSE, %", 1, "%5.1f"),
                          ("share of Cycles' relMSE, %", 2, "%5.1f")):
        print("\n%s (rows from the top, %d px blocks)" % (title, args.block))
        for y, row in enumerate(table):
            cells = []
            for cell in row:
                v = cell[k]
                cells.append("    -" if v is None else fmt % (v * (100 if k else 1)))
            print("%4d %s" % (y * args.block, " ".join(cells)))
    if args.out:
        write_map(args.out + "-penumbra.png", p, w, h, args.map_max)
        write_map(args.out + "-cycles.png", c, w, h, args.map_max)
        print("\nmaps: %s-penumbra.png, %s-cycles.png" % (args.out, args.out))


if __name__ == "__main__":
    main()
