#!/usr/bin/env python3
"""Render time of two penumbra binaries, side by side: each round runs A and B at the same
time, one thread each, pinned to different cores (taskset), and swaps the cores the next
round. Both then see the same machine: a VM's slow spells last seconds to minutes, and
runs one after the other do not resolve 2% through them (docs/performance.md,
"How to measure"). Prints each round's render seconds and B / A, then the median ratio, and
the median over pairs of rounds of their geometric mean: a pair has run each binary on each
core, so a core that is slower than the other (35% for minutes, on this VM) cancels.

--sequential runs A and B one after the other on core 1, the other core idle, the first
of each round alternating (AB, BA, ...). Side by side, the two processes share the VM's
slow spells, and a spell can still show two equal binaries 3% apart either way
(docs/performance.md, "How to measure"). Confirm a gain under 5% both ways, at different
times, before believing it.

  python3 scripts/ab_render_time.py OLD/penumbra build/bin/penumbra --rounds 8 -- \\
      render scenes/glossy.gltf --width 128 --spp 128 --filter box

Needs two cores; the render arguments must not set -o, --threads or --overwrite. The
render line gives hundredths of a second: choose renders of a second or more.
"""
import argparse
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import threading


def render_seconds(binary, core, args, out):
    cmd = ["taskset", "-c", str(core), binary] + args + [
        "-o", out, "--threads", "1", "--no-preview", "--overwrite"]
    p = subprocess.run(cmd, capture_output=True, text=True)
    m = re.search(r"render ([0-9.]+)s", p.stdout + p.stderr)
    if p.returncode != 0 or not m:
        raise RuntimeError("%s failed (exit %d):\n%s" % (" ".join(cmd), p.returncode,
                                                         p.stderr[-2000:]))
    return float(m.group(1))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("a", help="the baseline binary")
    ap.add_argument("b", help="the binary measured against it")
    ap.add_argument("--rounds", type=int, default=8, help="an even number: rounds pair up")
    ap.add_argument("--sequential", action="store_true",
                    help="one after the other on core 1 (AB, BA, ...), not side by side")
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    opts = ap.parse_args(argv[:split])
    args = argv[split + 1:]  # penumbra's own, after --
    if not args:
        ap.error("give penumbra's arguments after --")
    ratios = []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(opts.rounds):
            cores = {"a": 1, "b": 1} if opts.sequential else {"a": i % 2, "b": 1 - i % 2}
            seconds, errors = {}, []

            def run(key, binary):
                try:
                    seconds[key] = render_seconds(binary, cores[key], args,
                                                  os.path.join(tmp, key + ".exr"))
                except RuntimeError as e:  # a thread cannot exit the process
                    errors.append(str(e))

            threads = [threading.Thread(target=run, args=("a", opts.a)),
                       threading.Thread(target=run, args=("b", opts.b))]
            if opts.sequential:
                for t in threads if i % 2 == 0 else threads[::-1]:
                    t.start()
                    t.join()
            else:
                for t in threads:
                    t.start()
                for t in threads:
                    t.join()
            if errors:
                sys.exit("\n".join(errors))
            ratios.append(seconds["b"] / seconds["a"])
            print("round %d: A %.3f s (core %d), B %.3f s (core %d), B / A %.3f"
                  % (i + 1, seconds["a"], cores["a"], seconds["b"], cores["b"], ratios[-1]),
                  flush=True)
    # Side by side, a round's ratio carries the two cores' speeds: on this VM one core has
    # run 35% slower than the other for minutes. Two consecutive rounds swap the cores, so
    # the geometric mean of their ratios cancels that factor.
    pairs = [math.sqrt(ratios[i] * ratios[i + 1]) for i in range(0, len(ratios) - 1, 2)]
    print("median B / A %.3f over %d rounds (min %.3f, max %.3f)"
          % (statistics.median(ratios), len(ratios), min(ratios), max(ratios)))
    if pairs and not opts.sequential:
        print("median B / A %.3f over %d core-swapped pairs (geometric mean of each pair; "
              "min %.3f, max %.3f)" % (statistics.median(pairs), len(pairs), min(pairs),
                                       max(pairs)))


if __name__ == "__main__":
    main()
