#!/usr/bin/env python3
"""Embree's share of a render's time: `perf record` samples in libembree3 over those in
libembree3 and penumbra (the goal for the "share of time inside Embree" is 50%),
for one or more binaries, run in turn round after round so that each sees the same spells
of a shared machine. Prints each run's sample counts and share, then per binary the
median share and its range, the median counts, and libembree3's share of the whole
process (start-up included: the dynamic loader and the kernel take about 5%).

The share moves by about two points from run to run and from day to day on this VM, and
it barely follows penumbra's own instruction count: when ours falls, Embree's samples
fall about as much (docs/performance-traversal.md, "Embree's share of a render"). Compare
binaries in one invocation, and quote medians of several rounds.

  python3 scripts/embree_share.py /tmp/old/penumbra build/bin/penumbra --rounds 8

The default render: the point-light Cornell box, 256 px, 32 spp,
box filter, 8 segments, one thread, pinned to one core (--core; -1 leaves it unpinned).
Arguments after `--` replace it (keep --threads 1); scene paths are relative to the
repository root. Needs linux-perf (scripts/setup.sh --test installs it) and permission
to record (root, or kernel.perf_event_paranoid at most 2).
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

DEFAULT_RENDER = ["render", "scenes/cornell-box-point.gltf", "--width", "256", "--spp", "32",
                  "--filter", "box", "--max-depth", "8", "--no-default-light",
                  "--threads", "1"]


def samples_by_object(binary, render_args, core, tmp):
    """perf samples per shared object (and the binary) of one render."""
    data = os.path.join(tmp, "perf.data")
    cmd = ["perf", "record", "-q", "-e", "cpu-clock", "-F", "1999", "-o", data, "--"]
    if core >= 0:
        cmd += ["taskset", "-c", str(core)]
    cmd += [binary] + render_args + ["-o", os.path.join(tmp, "share.exr"), "--overwrite",
                                     "--no-preview", "-q"]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError("%s failed (exit %d):\n%s" % (" ".join(cmd), p.returncode,
                                                         p.stderr[-2000:]))
    report = subprocess.run(["perf", "report", "-i", data, "--sort", "dso", "--stdio",
                             "-F", "sample,dso"], capture_output=True, text=True,
                            check=True).stdout
    counts = {}
    for line in report.splitlines():
        m = re.match(r"\s*(\d+)\s+(\S+)", line)
        if m and not line.lstrip().startswith("#"):
            counts[m.group(2)] = int(m.group(1))
    return counts


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("binaries", nargs="+")
    ap.add_argument("--rounds", type=int, default=6)
    ap.add_argument("--core", type=int, default=1, help="core to pin to; -1: unpinned")
    argv = sys.argv[1:]
    render_args = DEFAULT_RENDER
    if "--" in argv:
        render_args = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    args = ap.parse_args(argv)
    binaries = [os.path.abspath(b) for b in args.binaries]
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

    runs = {b: [] for b in binaries}
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(args.rounds):
            for b in binaries:
                counts = samples_by_object(b, render_args, args.core, tmp)
                embree = sum(n for k, n in counts.items() if k.startswith("libembree3"))
                ours = counts.get(os.path.basename(b), 0)
                total = sum(counts.values())
                if embree + ours == 0:
                    raise RuntimeError("no samples in libembree3 or %s" % os.path.basename(b))
                runs[b].append((embree, ours, total))
                print("round %d %s: embree %d, penumbra %d, share %.1f%%" %
                      (r + 1, b, embree, ours, 100 * embree / (embree + ours)), flush=True)
    for b, rs in runs.items():
        shares = [100 * e / (e + o) for e, o, _ in rs]
        process = [100 * e / t for e, _, t in rs]
        print("%s: share median %.1f%% (%.1f-%.1f) over %d runs; samples median embree %d, "
              "penumbra %d; embree of the whole process median %.1f%%" %
              (b, statistics.median(shares), min(shares), max(shares), len(rs),
               statistics.median(e for e, _, _ in rs), statistics.median(o for _, o, _ in rs),
               statistics.median(process)))


if __name__ == "__main__":
    main()
