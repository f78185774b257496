#!/usr/bin/env python3
"""What a view costs beyond its samples: wall and CPU time of one process rendering N views
of a scene (`--views orbit:N`, one load) against one rendering 1 view, and against a job file
of N entries of the same scene (a load and an accelerator build per image, as a batch of
one view per entry does). Tiny images at 1 spp keep the samples' share small; the EXR
headers' penumbra:render_seconds (--timing-metadata) give the render loops' own time, which
is subtracted to leave the per-view overhead (camera, film, EXR and PNG writing, report).

  python3 scripts/view_overhead.py ../shared/scenes/wild/FlightHelmet/FlightHelmet.gltf \\
      --views 9 --rounds 3

Prints, per scene, the median over rounds of: seconds per extra view with one load, the
render loop's share of it, and seconds per extra image with a load per image.
"""
import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import OpenImageIO as oiio


def run_logged(binary, args):
    """Wall and CPU (user + system) seconds of one penumbra process, and its log."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    p = subprocess.run([binary] + args, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        raise RuntimeError("%s failed:\n%s" % (" ".join(args), p.stderr[-2000:]))
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, p.stdout + p.stderr


def run(binary, args):
    """Wall and CPU (user + system) seconds of one penumbra process."""
    return run_logged(binary, args)[:2]


def render_seconds(folder):
    total = 0.0
    for name in os.listdir(folder):
        if name.endswith(".exr"):
            total += oiio.ImageInput.open(os.path.join(folder, name)).spec().getattribute(
                "penumbra:render_seconds")
    return total


def measure(binary, scene, views, common, tmp):
    def views_run(n, out):
        return run(binary, ["render", scene, "--views", "orbit:%d" % n, "--out-dir", out,
                            "--overwrite", "-q"] + common)

    stem = os.path.splitext(os.path.basename(scene))[0]
    one = views_run(1, os.path.join(tmp, "one"))
    many = views_run(views, os.path.join(tmp, "many"))
    # The first render of a process pays one-time costs (tables built on first use): the
    # extra views' loops are the difference.
    loop = render_seconds(os.path.join(tmp, "many", stem)) - render_seconds(
        os.path.join(tmp, "one", stem))
    job = os.path.join(tmp, "job.json")
    with open(job, "w") as f:
        json.dump({"jobs": [{"scene": os.path.abspath(scene), "output": "img%d.exr" % i}
                            for i in range(views)]}, f)
    # A load per image: the same number of entries, each its own scene load.
    reload_many = run(binary, ["render", "--job", job, "--overwrite", "-q"] + common)
    return {
        "per_view_wall": (many[0] - one[0]) / (views - 1),
        "per_view_cpu": (many[1] - one[1]) / (views - 1),
        "loop_per_view": loop / (views - 1),
        "per_image_reload_wall": (reload_many[0] - one[0]) / (views - 1),
        "per_image_reload_cpu": (reload_many[1] - one[1]) / (views - 1),
    }


def overhead_arguments(ap):
    """The scenes, binary, rounds and image of an overhead measurement (also frame_overhead.py)."""
    ap.add_argument("scenes", nargs="+")
    ap.add_argument("--binary", default="build/bin/penumbra")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--size", type=int, default=64)
    ap.add_argument("--threads", type=int, default=1)


def render_arguments(a):
    """The render options every measured process gets: 1 spp, timings in the EXR."""
    return ["--width", str(a.size), "--height", str(a.size), "--spp", "1", "--threads",
            str(a.threads), "--timing-metadata"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    overhead_arguments(ap)
    ap.add_argument("--views", type=int, default=9)
    a = ap.parse_args()
    common = render_arguments(a)
    print("scene  s/view (one load)  cpu s/view  of which render loop  s/image (a load each)  cpu")
    for scene in a.scenes:
        rounds = []
        for _ in range(a.rounds):
            with tempfile.TemporaryDirectory() as tmp:
                rounds.append(measure(a.binary, scene, a.views, common, tmp))
        med = {k: statistics.median(r[k] for r in rounds) for k in rounds[0]}
        print("%s  %.4f  %.4f  %.4f  %.4f  %.4f" % (
            os.path.basename(scene), med["per_view_wall"], med["per_view_cpu"],
            med["loop_per_view"], med["per_image_reload_wall"], med["per_image_reload_cpu"]))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
