#!/usr/bin/env python3
"""Compares penumbra with Blender's Cycles on the Cornell box, region by region.

Renders the scene twice with each renderer (different seeds), estimates each region's
mean radiance and its standard error from the per-pixel differences between the two
seeds, and prints the z-score of penumbra against Cycles per region and channel. Exits 1
when any |z| exceeds 4. Needs Debian's blender package (not a build dependency).

  python3 scripts/crosscheck/compare_cycles.py [--size 128] [--spp 512]
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# (name, x0, y0, x1, y1) in a 128 x 128 image of scenes/cornell-box.gltf's "front" camera.
REGIONS = [
    ("ceiling", 40, 2, 88, 10),
    ("light panel", 54, 15, 72, 19),
    ("back wall", 60, 22, 90, 42),
    ("red wall", 4, 30, 14, 90),
    ("green wall", 114, 30, 124, 90),
    ("floor", 20, 112, 50, 124),
    ("tall block", 40, 60, 60, 95),
    ("short block", 68, 90, 90, 110),
    ("mirror sphere", 68, 52, 88, 72),
    ("whole image", 0, 0, 128, 128),
]


def region_avg(args, region, scale):
    """Per-channel average of an oiiotool expression over the region."""
    _, x0, y0, x1, y1 = (region[0],) + tuple(int(v * scale) for v in region[1:])
    out = subprocess.run(["oiiotool"] + args + ["--cut", "%dx%d+%d+%d" % (x1 - x0, y1 - y0, x0, y0),
                          "--printstats"], capture_output=True, text=True)
    if out.returncode != 0:
        raise SystemExit("oiiotool failed: " + out.stdout + out.stderr)
    out = out.stdout
    line = next(l for l in out.splitlines() if "Stats Avg:" in l)
    values = [float(v) for v in line.split("Avg:")[1].split()[:3]]
    return values, (x1 - x0) * (y1 - y0)


def region_stats(a, b, region, scale):
    """Mean of the two renders over the region and the standard error of that mean."""
    sums, n = region_avg([a, b, "--add"], region, scale)
    d2, _ = region_avg([a, b, "--sub", "--powc", "2"], region, scale)
    # Var(pixel) ~ E[(a - b)^2] / 2; the region mean averages 2n independent pixels.
    return [(sums[c] / 2, math.sqrt(d2[c] / 2 / (2 * n))) for c in range(3)]


def blender_env():
    """Blender finds its Python by searching PATH; a pyenv or virtualenv interpreter
    first on PATH would hide Debian's numpy from it."""
    env = dict(os.environ)
    env["PATH"] = os.pathsep.join(p for p in env.get("PATH", "").split(os.pathsep)
                                  if ".pyenv" not in p and "virtualenv" not in p)
    return env


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--size", type=int, default=128)
    ap.add_argument("--spp", type=int, default=512)
    ap.add_argument("--max-depth", type=int, default=8, help="bounce limit for both renderers")
    ap.add_argument("--scene", default=os.path.join(ROOT, "scenes", "cornell-box.gltf"))
    args = ap.parse_args()
    scale = args.size / 128
    with tempfile.TemporaryDirectory() as tmp:
        images = {}
        for seed in (1, 2):
            pen = os.path.join(tmp, "penumbra-%d.exr" % seed)
            subprocess.run([os.path.join(ROOT, "build", "bin", "penumbra"), "render", args.scene,
                            "-o", pen, "--width", str(args.size), "--spp", str(args.spp),
                            "--seed", str(seed), "--filter", "box", "-q", "--no-preview",
                            "--max-depth", str(args.max_depth)],
                           check=True)
            cyc = os.path.join(tmp, "cycles-%d.exr" % seed)
            subprocess.run(["blender", "-b", "--factory-startup", "-P",
                            os.path.join(ROOT, "scripts", "crosscheck", "cycles_render.py"), "--",
                            args.scene, cyc, str(args.size), str(args.spp), str(seed),
                            str(args.max_depth)],
                           check=True, stdout=subprocess.DEVNULL, env=blender_env())
            images[("penumbra", seed)] = pen
            images[("cycles", seed)] = cyc
        worst = 0.0
        print("%-14s %-3s %12s %12s %9s %7s" % ("region", "ch", "penumbra", "cycles", "rel.diff",
                                                "z"))
        for region in REGIONS:
            pen = region_stats(images[("penumbra", 1)], images[("penumbra", 2)], region, scale)
            cyc = region_stats(images[("cycles", 1)], images[("cycles", 2)], region, scale)
            for c, ch in enumerate("RGB"):
                (mp, sp), (mc, sc) = pen[c], cyc[c]
                z = (mp - mc) / math.hypot(sp, sc) if sp or sc else 0.0
                worst = max(worst, abs(z))
                print("%-14s %-3s %8.4f+-%.4f %8.4f+-%.4f %+8.2f%% %+7.2f" % (
                    region[0], ch, mp, sp, mc, sc, 100 * (mp - mc) / mc if mc else 0.0, z))
        print("largest |z| = %.2f (agreement within the noise: |z| <= 4)" % worst)
        return 0 if worst <= 4 else 1


if __name__ == "__main__":
    sys.exit(main())
