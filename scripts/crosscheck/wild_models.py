#!/usr/bin/env python3
"""Renders every model of ../shared/scenes/wild/ (and the Khronos samples) with penumbra and
with Cycles through Blender 3.4's own glTF importer, under the same camera and lighting,
and reports mean ratios penumbra/Cycles per model (docs/validation.md keeps the table).

  python3 scripts/crosscheck/wild_models.py [--size 160] [--spp 64] [--models Fox GolfBall]

Lighting: a uniform environment (--env, default white 1) and no default lights in both.
Camera: penumbra renders first (its file camera, else its framing camera) and writes the
camera into its EXR header (worldToCamera, worldToNDC); Blender rebuilds it from there.
Each renderer renders twice, spp/2 samples each with seeds 1 and 2: the average is the
image and the per-pixel differences give the noise. Needs oiiotool and Debian's blender
(with python3-numpy, which Blender's glTF importer imports); standard library only here.
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

from compare_cycles import blender_env
from gltf_sun import read_json, with_sun

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SHARED = os.path.join(os.path.dirname(ROOT), "shared", "scenes")
NO_HIT_DEPTH = 1e10  # penumbra's Depth AOV where no sample hit (Film::kNoHitDepth)
LUMINANCE = (0.2126, 0.7152, 0.0722)  # Rec.709 / sRGB primaries, penumbra's working space
FURNACE = "furnace/material-spheres"
GRID = 5  # furnace_spheres' rows and columns


def furnace_spheres(out_dir):
    """scenes/material-spheres.gltf (5 x 5 spheres, metallic down, roughness across, one
    per 1/5 x 1/5 of a square image) with white base colour and without its key light: a
    white furnace sweep where model differences show sphere by sphere."""
    doc = json.load(open(os.path.join(ROOT, "scenes", "material-spheres.gltf")))
    doc.pop("extensionsUsed", None)
    doc.pop("extensions", None)
    for node in doc["nodes"]:
        node.pop("extensions", None)
    for m in doc["materials"]:
        m["pbrMetallicRoughness"]["baseColorFactor"] = [1.0, 1.0, 1.0, 1.0]
    path = os.path.join(out_dir, "furnace-spheres.gltf")
    with open(path, "w") as f:
        json.dump(doc, f)
    return path


def discover(which, out_dir):
    """(label, path) of every .gltf/.glb under the chosen shared folders, and the furnace
    sweep."""
    models = []
    if which in ("furnace", "all"):
        models.append((FURNACE, furnace_spheres(out_dir)))
    if which in ("wild", "all"):
        wild = os.path.join(SHARED, "wild")
        for folder in sorted(os.listdir(wild)):
            path = os.path.join(wild, folder)
            if not os.path.isdir(path):
                continue
            files = sorted(f for f in os.listdir(path) if f.endswith((".gltf", ".glb")))
            for f in files:
                label = folder if len(files) == 1 else "%s/%s" % (folder, os.path.splitext(f)[0])
                models.append((label, os.path.join(path, f)))
    if which in ("khronos", "all"):
        khronos = os.path.join(SHARED, "khronos")
        for f in sorted(os.listdir(khronos)):
            if f.endswith((".gltf", ".glb")):
                models.append(("khronos/" + os.path.splitext(f)[0], os.path.join(khronos, f)))
    return models


def features(path):
    """A short list of what the file uses: extensions (KHR_materials_ shortened), skins,
    animations, cameras."""
    try:
        doc = read_json(path)
    except (OSError, ValueError) as e:
        return "unreadable (%s)" % e
    required = set(doc.get("extensionsRequired", []))
    out = []
    for ext in doc.get("extensionsUsed", []):
        name = ext.replace("KHR_materials_", "").replace("KHR_", "")
        out.append(name + ("!" if ext in required else ""))
    for key, word in (("skins", "skin"), ("animations", "anim"), ("cameras", "camera")):
        if doc.get(key):
            out.append(word)
    return ", ".join(out) or "core"


def run(cmd, timeout, env=None):
    start = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        return None, "timed out after %d s" % timeout, time.time() - start
    return p.returncode, p.stdout + p.stderr, time.time() - start


def exr_header(path):
    """Width, height, channel names and attributes (name -> text) of an EXR."""
    text = subprocess.run(["oiiotool", "--info", "-v", path], capture_output=True, text=True,
                          check=True).stdout
    m = re.search(r":\s+(\d+) x\s+(\d+),", text)
    channels = re.search(r"channel list: (.*)", text).group(1).split(", ")
    attrs = {}
    for line in text.splitlines()[2:]:
        key, sep, value = line.strip().partition(": ")
        if sep:
            attrs[key] = value.strip('"')
    return int(m.group(1)), int(m.group(2)), channels, attrs


def floats(text):
    return [float(v) for v in text.replace(",", " ").split()]


def pixels(path, names):
    """The named channels of every pixel, row by row, through oiiotool --dumpdata."""
    _, _, channels, _ = exr_header(path)
    index = [channels.index(n) for n in names]
    out = subprocess.run(["oiiotool", "--dumpdata", path], capture_output=True, text=True,
                         check=True).stdout
    rows = []
    for line in out.splitlines():
        if "Pixel (" in line:
            values = line.split("):", 1)[1].split()
            rows.append([float(values[i]) for i in index])
    return rows


def penumbra_render(args, scene, out, seed):
    cmd = [args.penumbra, "render", scene, "-o", out, "--width", str(args.size), "--height",
           str(args.size), "--spp", str(args.spp // 2), "--seed", str(seed), "--filter", "box",
           "--max-depth", str(args.max_depth), "--no-default-light", "--env-color"] + \
          [str(c) for c in args.env] + \
          (["--camera", args.camera] if args.camera else []) + \
          ["--aperture-radius", "0", "--aov", "depth", "--threads", str(args.threads),
           "--timing-metadata", "--no-preview", "-q", "--overwrite"]
    rc, log, wall = run(cmd, args.timeout)
    if rc != 0 or not os.path.exists(out):
        lines = [l for l in log.splitlines() if l.strip()]
        return None, (lines[-1] if lines else "exit status %s" % rc)
    return wall, None


def cycles_render(args, scene, prefix, header):
    job = {"scene": os.path.abspath(scene), "out_prefix": prefix, "spp": args.spp // 2,
           "seeds": [1, 2], "max_depth": args.max_depth, "threads": args.threads,
           "env": list(args.env), "lighting_mode": args.blender_lighting}
    if header:
        width, height, _, attrs = header
        job.update(width=width, height=height, world_to_camera=floats(attrs["worldToCamera"]),
                   world_to_ndc=floats(attrs["worldToNDC"]))
    else:
        job["import_only"] = True
    job_path = prefix + "-job.json"
    with open(job_path, "w") as f:
        json.dump(job, f)
    rc, log, wall = run(["blender", "-b", "--factory-startup", "-P",
                         os.path.join(HERE, "cycles_import_render.py"), "--", job_path],
                        args.timeout, env=blender_env())
    for line in log.splitlines():
        if line.startswith("CROSSCHECK-ERROR "):
            return None, line[len("CROSSCHECK-ERROR "):]
        if line.startswith("CROSSCHECK "):
            return json.loads(line[len("CROSSCHECK "):]), None
    lines = [l for l in log.splitlines() if l.strip()]
    return None, "blender exit %s: %s" % (rc, lines[-1] if lines else "")


def region_stats(a, b, mask):
    """Per channel (R, G, B, Y): mean of the two seeds' average over the masked pixels, the
    standard error of that mean, and the per-pixel standard deviation of the average, from
    Var(pixel of the average) ~ (a - b)^2 / 4."""
    n = sum(mask)
    out = []
    for c in range(4):
        s = d2 = 0.0
        for pa, pb, m in zip(a, b, mask):
            if not m:
                continue
            va = pa[c] if c < 3 else sum(w * pa[k] for k, w in enumerate(LUMINANCE))
            vb = pb[c] if c < 3 else sum(w * pb[k] for k, w in enumerate(LUMINANCE))
            s += 0.5 * (va + vb)
            d2 += 0.25 * (va - vb) ** 2
        out.append((s / n, math.sqrt(d2) / n, math.sqrt(d2 / n)) if n else (0.0, 0.0, 0.0))
    return out


def ratio(p, c):
    """penumbra / Cycles and its standard error from both standard errors."""
    (mp, sp, _), (mc, sc, _) = p, c
    if mp <= 0 or mc <= 0:
        return float("nan"), float("nan")
    r = mp / mc
    return r, r * math.hypot(sp / mp, sc / mc)


def compare(pen, cyc, env, cells=False):
    """Ratios over the image and over the model's pixels, coverage agreement and noise."""
    p1, p2 = (pixels(f, ["R", "G", "B", "Depth.Z"]) for f in pen)
    c1, c2 = (pixels(f, ["R", "G", "B", "A"]) for f in cyc)
    # Transparent film: add what an opaque film shows behind the model, the environment.
    c1, c2 = ([[q[k] + (1 - q[3]) * env[k] for k in range(3)] + [q[3]] for q in c]
              for c in (c1, c2))
    pen_hit = [a[3] < NO_HIT_DEPTH or b[3] < NO_HIT_DEPTH for a, b in zip(p1, p2)]
    pen_full = [a[3] < NO_HIT_DEPTH and b[3] < NO_HIT_DEPTH for a, b in zip(p1, p2)]
    cyc_alpha = [0.5 * (a[3] + b[3]) for a, b in zip(c1, c2)]
    union = sum(p or a > 0 for p, a in zip(pen_hit, cyc_alpha))
    inter = sum(p and a > 0 for p, a in zip(pen_hit, cyc_alpha))
    # The model's pixels: every sample of penumbra's and 99% of Cycles' coverage on it.
    model = [p and a >= 0.99 for p, a in zip(pen_full, cyc_alpha)]
    everything = [True] * len(p1)
    result = {"iou": inter / union if union else float("nan"),
              "model_fraction": sum(model) / len(model)}
    for name, mask in (("image", everything), ("model", model)):
        ps, cs = region_stats(p1, p2, mask), region_stats(c1, c2, mask)
        result[name] = {
            "ratio": [ratio(ps[c], cs[c]) for c in range(4)],  # R, G, B, Y
            "penumbra_mean_Y": ps[3][0], "cycles_mean_Y": cs[3][0],
            "penumbra_pixel_noise": ps[3][2] / ps[3][0] if ps[3][0] > 0 else float("nan"),
            "cycles_pixel_noise": cs[3][2] / cs[3][0] if cs[3][0] > 0 else float("nan"),
        }
    if cells:
        # Per sphere: the model's pixels inside its cell of the grid.
        w = int(round(math.sqrt(len(p1))))
        result["cells"] = []
        for row in range(GRID):
            for col in range(GRID):
                mask = [m and (i % w) * GRID // w == col and (i // w) * GRID // w == row
                        for i, m in enumerate(model)]
                ps, cs = region_stats(p1, p2, mask), region_stats(c1, c2, mask)
                result["cells"].append({"row": row, "col": col, "penumbra_Y": ps[3][0],
                                        "cycles_Y": cs[3][0], "ratio": ratio(ps[3], cs[3])})
    return result


def side_by_side(pen, cyc, env, stem):
    """STEM-penumbra.exr and STEM-cycles.exr (over the environment), both seeds averaged,
    and STEM.png: penumbra | Cycles | ratio / 2 (grey 0.5 where they agree), sRGB."""
    w, h, _, _ = exr_header(pen[0])
    color = ",".join(str(c) for c in env) + ",1"
    p, c, r = stem + "-penumbra.exr", stem + "-cycles.exr", stem + "-ratio.exr"
    subprocess.run(
        ["oiiotool", pen[0], pen[1], "--add", "--mulc", "0.5", "--ch", "R,G,B", "-o", p,
         cyc[0], cyc[1], "--add", "--mulc", "0.5", "--pattern", "constant:color=" + color,
         "%dx%d" % (w, h), "4", "--over", "--ch", "R,G,B", "-o", c,
         p, c, "--div", "--mulc", "0.5", "-o", r,
         p, c, r, "--mosaic:pad=4", "3x1", "--colorconvert", "linear", "sRGB", "-d", "uint8",
         "-o", stem + ".png"],
        check=True, capture_output=True)


def fmt_ratio(r):
    value, se = r
    return "n/a" if math.isnan(value) else "%.3f+-%.3f" % (value, se)


def table(results):
    lines = ["| model | features | penumbra | Cycles | IoU | Y image | Y model | R G B model "
             "| noise P / C | time P / C (s) |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        s = r.get("stats")
        # penumbra's messages start "error: FILE: "; the model column names the file.
        short = (r["penumbra_error"] or "").replace("error: ", "", 1).replace(
            os.path.abspath(r["scene"]) + ": ", "").replace(r["scene"] + ": ", "")
        pen = "ok" if not r["penumbra_error"] else "FAILED: " + short
        cyc = "ok" if not r["cycles_error"] else "FAILED: " + r["cycles_error"]
        if r["cycles_error"] is None and s is None:
            cyc = "imports (not rendered)"
        if s:
            m = s["model"]
            cols = ["%.3f" % s["iou"], fmt_ratio(s["image"]["ratio"][3]),
                    fmt_ratio(m["ratio"][3]),
                    " ".join("%.3f" % m["ratio"][c][0] for c in range(3)),
                    "%.1f%% / %.1f%%" % (100 * m["penumbra_pixel_noise"],
                                         100 * m["cycles_pixel_noise"]),
                    "%.1f / %.1f" % (r["penumbra_s"], r["cycles_s"])]
        else:
            cols = [""] * 6
        lines.append("| " + " | ".join([r["model"], r["features"], pen, cyc] + cols) + " |")
    return "\n".join(lines)


def cell_table(cells):
    """The furnace sweep: penumbra's and Cycles' mean luminance per sphere and their ratio."""
    lines = ["| metallic \\ roughness | " + " | ".join("%.2f" % (c / (GRID - 1))
                                                     for c in range(GRID)) + " |",
             "|---" * (GRID + 1) + "|"]
    for row in range(GRID):
        cols = []
        for c in cells[row * GRID:(row + 1) * GRID]:
            cols.append("%.3f / %.3f = %s" % (c["penumbra_Y"], c["cycles_Y"],
                                             fmt_ratio(c["ratio"])))
        lines.append("| %.2f | " % (row / (GRID - 1)) + " | ".join(cols) + " |")
    return "\n".join(lines)


def changes(results, baseline):
    """Models whose status or model luminance ratio moved beyond 3 combined standard
    errors since a baseline (an earlier results.json's content)."""
    before = {r["model"]: r for r in baseline["results"]}
    lines = ["| model | before | now |", "|---|---|---|"]
    for r in results:
        b = before.get(r["model"])
        old = fmt_ratio(b["stats"]["model"]["ratio"][3]) if b and b.get("stats") else "failed"
        new = fmt_ratio(r["stats"]["model"]["ratio"][3]) if r.get("stats") else "failed"
        if old != "failed" and new != "failed":
            (v0, e0), (v1, e1) = b["stats"]["model"]["ratio"][3], r["stats"]["model"]["ratio"][3]
            if abs(v1 - v0) <= 3 * math.hypot(e0, e1):
                continue
        if old != new:
            lines.append("| %s | %s | %s |" % (r["model"], old, new))
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--set", choices=["wild", "khronos", "furnace", "all"], default="all")
    ap.add_argument("--models", nargs="*", help="only labels containing one of these")
    ap.add_argument("--size", type=int, default=160, help="image width and height")
    ap.add_argument("--spp", type=int, default=64, help="samples per pixel, over both seeds")
    ap.add_argument("--max-depth", type=int, default=8, help="bounce limit for both renderers")
    ap.add_argument("--env", type=float, nargs=3, default=[1.0, 1.0, 1.0])
    ap.add_argument("--sun", type=float, default=0, metavar="LUX",
                    help="add a white directional light of LUX lux to every model (0: none)")
    ap.add_argument("--sun-from", type=float, nargs=3, default=[-0.5, 1.0, 0.7],
                    metavar=("X", "Y", "Z"), help="direction towards the sun, glTF world")
    ap.add_argument("--blender-lighting", choices=["SPEC", "COMPAT", "RAW"], default="SPEC",
                    help="the importer's light units: SPEC W = lux / 683 (its default), "
                         "COMPAT W = lux")
    ap.add_argument("--camera", help="penumbra's --camera (name or index) for every model")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--timeout", type=int, default=900, help="seconds per render call")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "crosscheck"))
    ap.add_argument("--baseline", help="an earlier results.json: list what changed")
    ap.add_argument("--penumbra", default=os.path.join(ROOT, "build", "bin", "penumbra"))
    args = ap.parse_args()
    if args.spp < 2:
        ap.error("--spp must be at least 2 (two seeds)")
    os.makedirs(args.out, exist_ok=True)
    baseline = json.load(open(args.baseline)) if args.baseline else None  # before --out's
    models = discover(args.set, args.out)
    if args.models:
        models = [m for m in models if any(k.lower() in m[0].lower() for k in args.models)]
    results = []
    scratch = tempfile.mkdtemp(prefix="crosscheck-sun-") if args.sun > 0 else None
    for label, scene in models:
        if scratch:
            scene = with_sun(scene, scratch, args.sun, args.sun_from)
        stem = os.path.join(args.out, label.replace("/", "_"))
        r = {"model": label, "scene": scene, "features": features(scene),
             "penumbra_error": None, "cycles_error": None}
        pen = ["%s-penumbra-%d.exr" % (stem, s) for s in (1, 2)]
        pen_s = 0.0
        for seed, out in zip((1, 2), pen):
            wall, err = penumbra_render(args, scene, out, seed)
            if err:
                r["penumbra_error"] = err
                break
            pen_s += float(exr_header(out)[3].get("penumbra:render_seconds", wall))
        header = None if r["penumbra_error"] else exr_header(pen[0])
        info, err = cycles_render(args, scene, stem + "-cycles", header)
        r["cycles_error"] = err
        if header and info:
            cyc = ["%s-cycles-%d.exr" % (stem, s) for s in (1, 2)]
            r["penumbra_s"], r["cycles_s"] = pen_s, sum(info["render_s"].values())
            r["cycles_import_s"] = info["import_s"]
            r["stats"] = compare(pen, cyc, args.env, cells=label == FURNACE)
            side_by_side(pen, cyc, args.env, stem)
        results.append(r)
        print(table([r]).splitlines()[-1], flush=True)
    if scratch:
        shutil.rmtree(scratch)
    with open(os.path.join(args.out, "results.json"), "w") as f:
        json.dump({"args": vars(args), "results": results}, f, indent=1)
    report = table(results)
    for r in results:
        if r.get("stats", {}).get("cells"):
            report += "\n\n" + r["model"] + ": penumbra / Cycles luminance per sphere\n\n" + \
                cell_table(r["stats"]["cells"])
    if args.baseline:
        report += "\n\nChanged since %s:\n\n%s" % (args.baseline, changes(results, baseline))
    with open(os.path.join(args.out, "report.md"), "w") as f:
        f.write(report + "\n")
    print()
    print(report)
    return 0


if __name__ == "__main__":
    sys.exit(main())
