#!/usr/bin/env python3
"""Thread scaling of one render (the goal: at least 1.9x on 2 cores for every image of
256 x 256 or more): the render's own seconds (the EXR's penumbra:render_seconds, written with
--timing-metadata; load, BVH build and writing left out) on 1 thread and on N, the two
alternated round by round so that both see the same spells of a shared machine.

  python3 scripts/thread_scaling.py build/bin/penumbra --rounds 11 -- \\
      scenes/cornell-box.gltf --width 256 --spp 16

Prints the medians and minima of each, their ratios, and the user CPU seconds of each
process (load included): equal user time on 1 and N threads means the threads do not slow
each other (no shared cache lines written, no lock), so a ratio below N comes from idle
threads (a pass's tail, a fixed cost per pass) or from the machine. On a VM whose vCPUs
the host also serves, the median of an N-thread render suffers whenever any of its vCPUs
is taken, the 1-thread one only when its own is: read the minima beside the medians.
"""
import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile


def render(binary, args, threads, out):
    """(render seconds from the header, user CPU seconds of the process)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    subprocess.run([binary, "render"] + args + ["--threads", str(threads), "-o", out,
                                                "--overwrite", "--timing-metadata",
                                                "--no-preview", "-q"], check=True)
    user = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before
    info = subprocess.run(["oiiotool", "--info", "-v", out], capture_output=True, text=True,
                          check=True).stdout
    m = re.search(r'penumbra:render_seconds: "?([0-9.eE+-]+)', info)
    if not m:
        raise RuntimeError("no penumbra:render_seconds in %s" % out)
    return float(m.group(1)), user


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("binary")
    ap.add_argument("--rounds", type=int, default=11)
    ap.add_argument("--threads", type=int, default=2, help="N, measured against 1")
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    opts = ap.parse_args(argv[:split])
    args = argv[split + 1:]  # the scene and penumbra's render options
    if not args:
        ap.error("give the scene and render options after --")
    if opts.threads < 2:
        ap.error("--threads must be at least 2 (it is measured against 1)")
    counts = (1, opts.threads)
    seconds = {t: [] for t in counts}
    user = {t: [] for t in counts}
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "scaling.exr")
        for i in range(opts.rounds):
            for t in counts if i % 2 == 0 else counts[::-1]:
                s, u = render(opts.binary, args, t, out)
                seconds[t].append(s)
                user[t].append(u)
    one, n = counts
    med = {t: statistics.median(seconds[t]) for t in counts}
    low = {t: min(seconds[t]) for t in counts}
    for t in counts:
        print("%d thread(s): render median %.4f s (min %.4f), user CPU median %.3f s" %
              (t, med[t], low[t], statistics.median(user[t])))
    print("speed-up %.2fx (medians), %.2fx (minima), over %d rounds; user CPU %d/%d threads "
          "%.3f" % (med[one] / med[n], low[one] / low[n], opts.rounds, n, one,
                    statistics.median(user[n]) / statistics.median(user[one])))
    return 0


if __name__ == "__main__":
    sys.exit(main())
