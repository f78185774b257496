#!/usr/bin/env python3
"""What a frame costs beyond its samples: wall and CPU time of one process rendering N frames
of a scene (`--frames 0-(N-1)`) against one rendering frame 0 alone. Tiny images at 1 spp keep
the samples' share small; the EXR headers' penumbra:render_seconds (--timing-metadata) give the
render loops' own time, which is subtracted to leave the per-frame overhead. The log's "load
and build" lines split the frames after the first into parse, meshes, materials (image
decoding), nodes (animation, skins) and the accelerator build.

  python3 scripts/frame_overhead.py ../shared/scenes/wild/Fox/Fox.glb --frames 8 --rounds 3 \
      --baseline /tmp/penumbra-main

Prints, per scene (and binary: --baseline's rounds alternate with --binary's, as the machine
is shared), the median over rounds of: seconds per extra frame (wall, CPU), the render
loop's share, and the mean split of the extra frames' set-up in milliseconds.
"""
import argparse
import os
import re
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from view_overhead import (overhead_arguments, render_arguments, render_seconds,  # noqa: E402
                           run_logged)

STAGES = ["parse", "meshes", "materials", "nodes", "build"]
LINE = re.compile(r"(?:load|pose) and build: parse ([\d.]+) s \(cpu [\d.]+\), "
                  r"meshes ([\d.]+) \([\d.]+\), materials ([\d.]+) \([\d.]+\), "
                  r"nodes ([\d.]+) \([\d.]+\); \S+ build ([\d.]+) s")


def split(log):
    """Mean milliseconds per stage over the set-ups after the first one in the log."""
    rows = [[float(x) * 1000 for x in m.groups()] for m in LINE.finditer(log)][1:]
    if not rows:
        return {s: 0.0 for s in STAGES}
    return {s: sum(r[i] for r in rows) / len(rows) for i, s in enumerate(STAGES)}


def measure(binary, scene, frames, common, tmp):
    def frames_run(n, out):
        return run_logged(binary, ["render", scene, "--frames", "0-%d" % (n - 1),
                                   "--out-dir", out, "--overwrite"] + common)

    one = frames_run(1, os.path.join(tmp, "one"))
    many = frames_run(frames, os.path.join(tmp, "many"))
    loop = render_seconds(os.path.join(tmp, "many")) - render_seconds(os.path.join(tmp, "one"))
    result = {
        "per_frame_wall": (many[0] - one[0]) / (frames - 1),
        "per_frame_cpu": (many[1] - one[1]) / (frames - 1),
        "loop_per_frame": loop / (frames - 1),
    }
    result.update(split(many[2]))
    return result


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    overhead_arguments(ap)
    ap.add_argument("--baseline", help="another penumbra binary, measured alternately")
    ap.add_argument("--frames", type=int, default=8)
    a = ap.parse_args()
    common = render_arguments(a)
    print("scene  binary  s/frame  cpu s/frame  of which render loop  | ms per later frame: " +
          "  ".join(STAGES))
    binaries = [a.binary] + ([a.baseline] if a.baseline else [])
    for scene in a.scenes:
        rounds = {b: [] for b in binaries}
        for _ in range(a.rounds):
            for b in binaries:
                with tempfile.TemporaryDirectory() as tmp:
                    rounds[b].append(measure(b, scene, a.frames, common, tmp))
        for b in binaries:
            med = {k: statistics.median(r[k] for r in rounds[b]) for k in rounds[b][0]}
            print("%s  %s  %.4f  %.4f  %.4f  | %s" % (
                os.path.basename(scene), b, med["per_frame_wall"], med["per_frame_cpu"],
                med["loop_per_frame"], "  ".join("%.1f" % med[s] for s in STAGES)))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
