#!/usr/bin/python3
"""penumbra against three-gpu-pathtracer (../shared/tools/tgpt) on real glTF files.

Both render every model under a uniform white environment of radiance 1, the only light,
with the same camera (the file's first, else penumbra's framing, which tgpt copies), at the
same size, 8 bounces. tgpt's compare.py then gives the mean luminance ratio over the pixels
either image covers and the coverage IoU. Prints a markdown table (docs/validation.md,
"Second opinion: three-gpu-pathtracer").

    python3 scripts/crosscheck/tgpt_wild.py [--tgpt /tmp/tgpt] [--size 128] [--spp 64]
        [--out out/tgpt] [--models GolfBall ...] [--penumbra-only] [--tgpt-only]

The tool must be set up first (bash ../shared/tools/tgpt/setup.sh /tmp/tgpt), and its
compare.py needs python3-openimageio (apt).
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SHARED = os.path.abspath(os.path.join(ROOT, "..", "shared"))


def models(selected):
    """(name, path) of every glTF file under ../shared/scenes/wild, sorted by name."""
    out = []
    wild = os.path.join(SHARED, "scenes", "wild")
    for folder in sorted(os.listdir(wild)):
        d = os.path.join(wild, folder)
        if not os.path.isdir(d):
            continue
        for f in sorted(os.listdir(d)):
            if f.lower().endswith((".gltf", ".glb")):
                name = os.path.splitext(f)[0]
                if not selected or folder in selected or name in selected:
                    out.append((name, os.path.join(d, f)))
    return out


def render_penumbra(exe, name, path, a):
    out = os.path.join(a.out, "penumbra", name + ".exr")
    cmd = [exe, "render", path, "-o", out, "--width", str(a.size), "--height", str(a.size),
           "--spp", str(a.spp), "--env-color", "1", "1", "1", "--no-default-light",
           "--max-depth", "8", "--overwrite", "--no-preview"]
    if a.no_file_lights:
        cmd.append("--no-file-lights")
    r = subprocess.run(cmd, capture_output=True, text=True)
    return out if r.returncode == 0 else None, r.stderr.strip().splitlines()[-1:] if r.stderr else []


def compare(tgpt, a_exr, b_exr, prefix):
    # compare.py needs numpy and OpenImageIO: Debian's python3, as tgpt's render.mjs uses.
    r = subprocess.run(["/usr/bin/python3", os.path.join(tgpt, "compare.py"), a_exr, b_exr, prefix],
                       capture_output=True, text=True)
    text = r.stdout
    ratio = re.search(r"ratio A/B=([0-9.naninf]+)", text)
    iou = re.search(r"coverage IoU=([0-9.]+)", text)
    rgb = re.search(r"R=([0-9.]+) G=([0-9.]+) B=([0-9.]+)", text)
    return (float(ratio.group(1)) if ratio else float("nan"),
            float(iou.group(1)) if iou else float("nan"),
            tuple(float(x) for x in rgb.groups()) if rgb else None)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tgpt", default="/tmp/tgpt")
    ap.add_argument("--exe", default=os.path.join(ROOT, "build", "bin", "penumbra"))
    ap.add_argument("--size", type=int, default=128)
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "tgpt"))
    ap.add_argument("--models", nargs="*")
    ap.add_argument("--penumbra-only", action="store_true", help="reuse tgpt's images in --out")
    ap.add_argument("--tgpt-only", action="store_true", help="reuse penumbra's images in --out")
    ap.add_argument("--no-file-lights", action="store_true",
                    help="switch the files' punctual lights off in penumbra (tgpt's --env 1 has none)")
    a = ap.parse_args()
    todo = models(a.models)
    os.makedirs(os.path.join(a.out, "tgpt"), exist_ok=True)
    os.makedirs(os.path.join(a.out, "penumbra"), exist_ok=True)
    os.makedirs(os.path.join(a.out, "diff"), exist_ok=True)

    if not a.tgpt_only:
        for name, path in todo:
            _, err = render_penumbra(a.exe, name, path, a)
            if err:
                print(f"penumbra {name}: {err[0]}", file=sys.stderr)
    if not a.penumbra_only:
        listing = os.path.join(a.out, "tgpt", "list.tsv")
        with open(listing, "w") as f:
            for name, path in todo:
                f.write(f"{name}\t{path}\n")
        subprocess.run(["node", os.path.join(a.tgpt, "render.mjs"), "--list", listing,
                        "--out-dir", os.path.join(a.out, "tgpt"), "--width", str(a.size),
                        "--height", str(a.size), "--spp", str(a.spp), "--env", "1",
                        "--bounces", "8"], check=False)

    print(f"| model | penumbra / tgpt (luminance) | R, G, B ratios | coverage IoU |")
    print("|---|---|---|---|")
    for name, _ in todo:
        pe = os.path.join(a.out, "penumbra", name + ".exr")
        te = os.path.join(a.out, "tgpt", name + ".exr")
        if not (os.path.exists(pe) and os.path.exists(te)):
            missing = "penumbra" if not os.path.exists(pe) else "tgpt"
            print(f"| {name} | no image from {missing} | | |")
            continue
        ratio, iou, rgb = compare(a.tgpt, pe, te, os.path.join(a.out, "diff", name))
        flag = "**" if abs(ratio - 1) > 0.10 else ""
        rgbs = ", ".join(f"{x:.2f}" for x in rgb) if rgb else ""
        print(f"| {name} | {flag}{ratio:.3f}{flag} | {rgbs} | {iou:.3f} |")


if __name__ == "__main__":
    main()
