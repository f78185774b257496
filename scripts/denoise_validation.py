#!/usr/bin/env python3
"""The denoiser against converged references: for each scene, a reference at --ref-spp
(another seed, not denoised, with the error AOV so that its own noise is known), then
renders at each of --spp with --denoise, and raw at --raw-spp for comparison. Prints the
markdown table of docs/validation.md ("Denoising"): relMSE of raw and denoised, and the
denoiser's own estimate beside the measured value; writes
side-by-side PNGs (raw | denoised | reference) to look at.

    scripts/denoise_validation.py --out /tmp/denoise scenes/cornell-box.gltf ...

Every number comes from the EXR headers penumbra writes (penumbra:relmse,
penumbra:noisy_relmse, penumbra:denoise_relmse_estimate). References and the raw renders
at --raw-spp are kept in --out and reused when they exist (delete them after changing
the renderer; a denoiser change needs only the denoised renders again).
"""
import argparse
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def header(path):
    """The EXR's penumbra: attributes, as strings."""
    out = subprocess.run(["oiiotool", "--info", "-v", path], capture_output=True, text=True,
                         check=True).stdout
    attrs = {}
    for line in out.splitlines():
        m = re.match(r'\s*(penumbra:\w+): "?([^"]*)"?$', line)
        if m:
            attrs[m.group(1)] = m.group(2)
    return attrs


def mean_square(path, channel):
    """Mean over pixels of a channel's square (oiiotool's statistics)."""
    out = subprocess.run(["oiiotool", path, "--ch", channel, "--powc", "2", "--printstats"],
                         capture_output=True, text=True, check=True).stdout
    m = re.search(r"Stats Avg:\s*([0-9.eE+-]+)", out)
    return float(m.group(1))


def render(binary, scene, out, args):
    cmd = [binary, "render", scene, "-o", out, "--overwrite", "-q"] + args
    start = time.monotonic()
    subprocess.run(cmd, check=True)
    return time.monotonic() - start


def png(exr, channels, out):
    subprocess.run(["oiiotool", exr, "--ch", channels, "--chnames", "R,G,B", "--colorconvert",
                    "linear", "sRGB", "-o", out], check=True)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scenes", nargs="+")
    p.add_argument("--out", required=True)
    p.add_argument("--binary", default=os.path.join(ROOT, "build/bin/penumbra"))
    p.add_argument("--width", type=int, default=160)
    p.add_argument("--ref-spp", type=int, default=8192)
    p.add_argument("--spp", default="16,32,64")
    p.add_argument("--raw-spp", type=int, default=512)
    p.add_argument("--threads", type=int, default=0)
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    common = ["--width", str(a.width)] + (["--threads", str(a.threads)] if a.threads else [])
    spps = [int(s) for s in a.spp.split(",")]
    print("| scene | ref. noise | " + " | ".join(
        f"{s} spp raw / denoised (estimate)" for s in spps) + f" | {a.raw_spp} spp raw |")
    print("|---|---|" + "---|" * len(spps) + "---|")
    for scene in a.scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        ref = os.path.join(a.out, f"{name}_ref.exr")
        if not os.path.exists(ref):
            render(a.binary, scene, ref, common + ["--spp", str(a.ref_spp), "--seed", "1000",
                                                  "--aov", "error", "--no-preview"])
        # The error AOV is the relative standard error per pixel: its mean square is the
        # reference's own relMSE, which every measured value below includes.
        ref_noise = mean_square(ref, "Error.X")
        cells = []
        for spp in spps:
            out = os.path.join(a.out, f"{name}_{spp}.exr")
            render(a.binary, scene, out, common + ["--spp", str(spp), "--denoise", "--reference",
                                                  ref, "--no-preview"])
            h = header(out)
            cells.append("%.2e / **%.2e** (%.2e)" % (float(h["penumbra:noisy_relmse"]),
                                                     float(h["penumbra:relmse"]),
                                                     float(h["penumbra:denoise_relmse_estimate"])))
            png(out, "Noisy.R,Noisy.G,Noisy.B", os.path.join(a.out, f"{name}_{spp}_raw.png"))
            png(out, "R,G,B", os.path.join(a.out, f"{name}_{spp}_denoised.png"))
        raw = os.path.join(a.out, f"{name}_{a.raw_spp}raw.exr")
        if not os.path.exists(raw):
            render(a.binary, scene, raw, common + ["--spp", str(a.raw_spp), "--reference", ref,
                                                  "--no-preview"])
        raw_relmse = float(header(raw)["penumbra:relmse"])
        png(ref, "R,G,B", os.path.join(a.out, f"{name}_ref.png"))
        mid = spps[len(spps) // 2]
        subprocess.run(["oiiotool", os.path.join(a.out, f"{name}_{mid}_raw.png"),
                        os.path.join(a.out, f"{name}_{mid}_denoised.png"),
                        os.path.join(a.out, f"{name}_ref.png"), "--mosaic", "3x1", "-o",
                        os.path.join(a.out, f"{name}_compare.png")], check=True)
        print(f"| {name} | {ref_noise:.1e} | " + " | ".join(cells) + f" | {raw_relmse:.2e} |",
              flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
