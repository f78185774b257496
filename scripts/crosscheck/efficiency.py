#!/usr/bin/env python3
"""Equal-error efficiency of penumbra against Blender's Cycles: each renderer
renders each scene at several spp, its relMSE is measured against its own converged image
(so model differences between the two do not count as error), and the table gives
1 / (relMSE x render seconds) per renderer and the ratio penumbra / Cycles.

  python3 scripts/crosscheck/efficiency.py --quick                        # a few minutes
  python3 scripts/crosscheck/efficiency.py --scenes all --spp 16,64,256 --out /tmp/eff.md
  python3 scripts/crosscheck/efficiency.py --embree                       # + Embree tutorial
  python3 scripts/crosscheck/efficiency.py --embree-only --repeats 6 --interleave
                                                                          # that table alone

Matched in both: resolution, a one-pixel box filter, the path length (penumbra's
--max-depth N, Cycles' N - 1 bounces of every kind), 2 threads, no denoising, no adaptive
sampling, no clamping, Cycles' light threshold 0, the same environment image. Time is the
render alone (penumbra's render_seconds; Cycles' path-tracing clock, without sync), with
the whole process's in parentheses, and CPU seconds (N spp less a 1-spp render), which a
loaded machine distorts far less. References: two halves of --ref-spp with seeds 1001
and 1002; their difference estimates the reference's own relMSE, which is subtracted
from each measurement and reported as a share of it.
Renders are cached under --cache (default $XDG_CACHE_HOME or ~/.cache, penumbra-efficiency);
docs/performance.md keeps the baseline and the method. Needs oiiotool and Debian's blender.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

from efficiency_metrics import EPSILON, efficiency, median, read_rgb, reference_relmse, relmse
from efficiency_metrics import average
from efficiency_render import (Cache, CyclesSession, cycles_identity, cycles_renders,
                               interleave, penumbra_identity, penumbra_render)
from efficiency_scenes import ALL, QUICK, ROOT, prepare

REF_SEEDS = (1001, 1002)
RENDERERS = ("penumbra", "cycles")


def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scenes", default="all", help="comma-separated: %s, or all" % ",".join(ALL))
    ap.add_argument("--spp", default="16,64,256", help="comma-separated sample counts")
    ap.add_argument("--size", type=int, default=128, help="image width (height: the camera's)")
    ap.add_argument("--ref-spp", type=int, help="reference spp (default 16 x the largest --spp)")
    ap.add_argument("--repeats", type=int, default=3,
                    help="renders per spp (seeds 1..R): relMSE averaged, time the median")
    ap.add_argument("--max-depth", type=int, default=8)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--quick", action="store_true",
                    help="--size 64 --spp 4,16 --ref-spp 256 --repeats 1 --scenes %s unless "
                    "given" % ",".join(QUICK))
    ap.add_argument("--renderers", default="penumbra,cycles")
    ap.add_argument("--penumbra", default=os.path.join(ROOT, "build", "bin", "penumbra"))
    ap.add_argument("--penumbra-args", default="",
                    help="extra penumbra render options, e.g. '--sampler sobol'")
    ap.add_argument("--retime", action="store_true",
                    help="render every timed render again (keep the references): the cache "
                         "keeps each render's time, so a run under another load would mix loads")
    ap.add_argument("--interleave", action="store_true",
                    help="alternate the renderers per (spp, seed), Blender waiting between its "
                         "renders, so that both see the same minutes of a machine whose speed "
                         "drifts (else all of penumbra's renders, then all of Cycles')")
    ap.add_argument("--reuse-references", action="store_true",
                    help="use a cached reference made by another penumbra/Blender build")
    ap.add_argument("--cache", default=os.path.join(
        os.environ.get("XDG_CACHE_HOME", os.path.expanduser("~/.cache")), "penumbra-efficiency"))
    ap.add_argument("--out", help="also write the markdown table here (and OUT.json)")
    ap.add_argument("--timeout", type=int, default=1800, help="seconds per render")
    ap.add_argument("--embree", action="store_true",
                    help="also the equal-spp comparison with Embree's pathtracer tutorial")
    ap.add_argument("--embree-only", action="store_true",
                    help="only that comparison (its own fixed scene, size and spp: the "
                         "256 px, 64 spp), none of the efficiency scenes")
    args = ap.parse_args(argv)
    if args.quick:
        given = " ".join(argv)
        args.size = args.size if "--size" in given else 64
        args.spp = args.spp if "--spp" in given else "4,16"
        args.ref_spp = args.ref_spp or 256
        args.repeats = args.repeats if "--repeats" in given else 1
        args.scenes = args.scenes if "--scenes" in given else ",".join(QUICK)
    args.spp = sorted(int(s) for s in args.spp.split(","))
    args.ref_spp = args.ref_spp or 16 * args.spp[-1]
    if args.ref_spp < 2 or args.ref_spp % 2:
        ap.error("--ref-spp must be even (two halves)")
    args.scenes = ALL if args.scenes == "all" else args.scenes.split(",")
    args.renderers = args.renderers.split(",")
    return args


def settings(args, renderer):
    s = {"size": args.size, "max_depth": args.max_depth, "threads": args.threads}
    if renderer == "penumbra":
        s["extra"] = args.penumbra_args
    return s


def reference(args, cache, renderer):
    """Paths of the two reference halves: this build's, or with --reuse-references any
    build's cached ones."""
    half = args.ref_spp // 2
    paths = []
    for seed in REF_SEEDS:
        if cache.done(half, seed, need_cpu=False) or not args.reuse_references:
            paths.append(cache.path(half, seed))
        else:
            paths.append(cache.other_reference(renderer, half, seed) or cache.path(half, seed))
    return paths


def render_scene(args, name, identities):
    """Renders what the cache lacks; returns per renderer its caches and reference paths.
    penumbra's 1-spp render comes first (it gives Cycles the camera, and penumbra's fixed
    cost inside render_seconds); then, with --interleave, the two renderers' timed renders
    alternate per (spp, seed) (efficiency_render.interleave), else all of penumbra's and
    then all of Cycles'."""
    prepared = prepare(name, os.path.join(args.cache, "scenes"))
    out, todo = {}, {}
    for renderer in RENDERERS:
        if renderer not in args.renderers and renderer != "penumbra":
            continue
        cache = Cache(args.cache, name, prepared, identities[renderer],
                      settings(args, renderer))
        refs = reference(args, cache, renderer)
        todo[renderer] = [(args.ref_spp // 2, seed) for seed, p in zip(REF_SEEDS, refs)
                          if not os.path.exists(p + ".json")]
        todo[renderer] += [(spp, seed) for spp in args.spp
                           for seed in range(1, args.repeats + 1) if not cache.done(spp, seed)]
        out[renderer] = (cache, refs)
    if "penumbra" not in args.renderers:  # only the camera for Cycles
        todo["penumbra"] = []
    penumbra_cache = out["penumbra"][0]

    def penumbra(spp, seed):
        log("%s: penumbra %d spp, seed %d" % (name, spp, seed))
        penumbra_render(args, prepared, penumbra_cache, spp, seed)

    if not penumbra_cache.done(1, 1):
        penumbra(1, 1)
    camera = penumbra_cache.path(1, 1)
    cycles_todo = todo.get("cycles", [])
    if args.interleave and cycles_todo:
        steps = interleave(todo["penumbra"], cycles_todo)
        session = CyclesSession(args, name, prepared, out["cycles"][0], camera,
                                [key for r, key in steps if r == "cycles"], paced=True)
        for renderer, (spp, seed) in steps:
            if renderer == "penumbra":
                penumbra(spp, seed)
            else:
                log("%s: Cycles %d spp, seed %d" % (name, spp, seed))
                session.render_next()
        session.finish()
        return out
    for spp, seed in todo["penumbra"]:
        penumbra(spp, seed)
    if cycles_todo:
        log("%s: Cycles %s" % (name, ", ".join("%d spp seed %d" % t for t in cycles_todo)))
        cycles_renders(args, name, prepared, out["cycles"][0], camera, cycles_todo)
    return out


def measure(args, cache, refs):
    """Per spp: relMSE (reference error subtracted), its raw value, the reference's share,
    median render, process and CPU seconds, and the efficiencies by render and CPU seconds.
    CPU seconds are those of N spp less those of a 1-spp render (penumbra: its 1-spp
    process, so load, build and start-up go; Cycles: a 1-spp render in the same process,
    so sync goes): the cost of the samples, robust on a loaded machine, where wall time
    is not."""
    _, _, a = read_rgb(refs[0])
    _, _, b = read_rgb(refs[1])
    ref, ref_err = average(a, b), reference_relmse(a, b)
    rows = []
    for spp in args.spp:
        raw = [relmse(read_rgb(cache.path(spp, s))[2], ref) for s in range(1, args.repeats + 1)]
        times = [cache.times(spp, s) for s in range(1, args.repeats + 1)]
        cpu_1 = [t.get("cpu_1spp_s", cache.times(1, 1)["cpu_s"] if cache.done(1, 1) else 0)
                 for t in times]
        raw_mean = sum(raw) / len(raw)
        err = raw_mean - ref_err
        render_s = median([t["render_s"] for t in times])
        cpu_s = median([t["cpu_s"] - c1 for t, c1 in zip(times, cpu_1)])
        rows.append({"spp": spp, "relmse": err, "relmse_raw": raw_mean,
                     "ref_share": ref_err / raw_mean if raw_mean > 0 else float("nan"),
                     "render_s": render_s, "process_s": median([t["process_s"] for t in times]),
                     "cpu_s": cpu_s,
                     "efficiency": efficiency(err, render_s) if err > 0 else float("nan"),
                     "efficiency_cpu": efficiency(err, cpu_s) if err > 0 and cpu_s > 0
                     else float("nan"),
                     "sampler": times[0].get("sampler")})
    return rows


def fmt(v, digits=3):
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "n/a"
    return "%.*g" % (digits, v)


def seconds(row):
    return "n/a" if not row else "%s (%s)" % (fmt(row["render_s"]), fmt(row["process_s"], 2))


def table(results, args):
    lines = ["| scene | spp | penumbra relMSE | s (process) | cpu-s | efficiency | Cycles relMSE "
             "| s (process) | cpu-s | efficiency | penumbra / Cycles | by cpu-s | ref. share "
             "P / C |", "|---" * 13 + "|"]
    for name, per in results.items():
        p, c = per.get("penumbra"), per.get("cycles")
        for k, spp in enumerate(args.spp):
            pr, cr = (p[k] if p else None), (c[k] if c else None)
            ratio = pr["efficiency"] / cr["efficiency"] if pr and cr else float("nan")
            ratio_cpu = pr["efficiency_cpu"] / cr["efficiency_cpu"] if pr and cr else \
                float("nan")
            lines.append("| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | **%s** | **%s** "
                         "| %s / %s |" % (
                             name, spp, fmt(pr and pr["relmse"]), seconds(pr),
                             fmt(pr and pr["cpu_s"]), fmt(pr and pr["efficiency"]),
                             fmt(cr and cr["relmse"]), seconds(cr), fmt(cr and cr["cpu_s"]),
                             fmt(cr and cr["efficiency"]), fmt(ratio, 2), fmt(ratio_cpu, 2),
                             fmt(pr and pr["ref_share"], 2), fmt(cr and cr["ref_share"], 2)))
    lines.append("")
    lines.append("penumbra's render_seconds at 1 spp (fixed start-up inside the render time): " +
                 ", ".join("%s %s s" % (n, fmt(r["penumbra_1spp_s"], 2))
                           for n, r in results.items()) + ".")
    return "\n".join(lines)


def sampler(results, renderer):
    for per in results.values():
        if per.get(renderer):
            return per[renderer][0]["sampler"]
    return "?"


def log(message):
    print("[%s] %s" % (time.strftime("%H:%M:%S"), message), file=sys.stderr, flush=True)


def main(argv):
    args = parse_args(argv)
    started = time.time()
    if args.retime:
        Cache.retime_since = started
    identities = {"penumbra": penumbra_identity(args.penumbra)}
    if "cycles" in args.renderers:
        identities["cycles"] = cycles_identity()
    if args.embree_only:
        from efficiency_embree import embree_table
        return write_report(args, embree_table(args, identities))
    results = {}
    for name in args.scenes:
        caches = render_scene(args, name, identities)
        results[name] = {r: measure(args, *caches[r]) for r in args.renderers if r in caches}
        results[name]["penumbra_1spp_s"] = caches["penumbra"][0].times(1, 1)["render_s"]
    load = os.getloadavg()
    report = ["penumbra %s (commit %s, sampler %s%s) against Cycles (%s, sampling pattern %s, "
              "no light tree in 3.4); %d px wide, "
              "max depth %d, %d threads, box filter; reference %d spp; relMSE epsilon %g; "
              "%d repeat(s) per spp (relMSE mean, time median)%s; load average %.2f %.2f %.2f; "
              "%.0f s in all." % (
                  identities["penumbra"]["version"], identities["penumbra"]["commit"],
                  sampler(results, "penumbra"),
                  (", " + args.penumbra_args) if args.penumbra_args else "",
                  identities.get("cycles", {}).get("version", "not run"),
                  sampler(results, "cycles"), args.size,
                  args.max_depth, args.threads, args.ref_spp, EPSILON, args.repeats,
                  ", renderers interleaved per (spp, seed)" if args.interleave else "",
                  load[0], load[1], load[2], time.time() - started), "", table(results, args)]
    worst = max((r["ref_share"] for per in results.values() for rows in per.values()
                 if isinstance(rows, list) for r in rows if not math.isnan(r["ref_share"])),
                default=0)
    if worst > 0.1:
        report.append("\nwarning: a reference's own error is %.0f%% of a measured relMSE "
                      "(more than 10%%): raise --ref-spp." % (100 * worst))
    if args.embree:
        from efficiency_embree import embree_table
        report += ["", embree_table(args, identities)]
    return write_report(args, "\n".join(report),
                        {"args": vars(args), "identities": identities, "results": results})


def write_report(args, text, record=None):
    """Prints the report, and writes it to --out (with the measurements as OUT.json)."""
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text + "\n")
        if record is not None:
            with open(args.out + ".json", "w") as f:
                json.dump(record, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
