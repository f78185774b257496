"""Equal-spp time against Embree 3.13.5's pathtracer tutorial (Debian's embree-tools) for
scripts/crosscheck/efficiency.py --embree: its Cornell box (cornell_box.ecs: the OBJ, pure
Lambert, one point light) at 256 x 256, 64 spp, 8 path segments, 2 threads, against
penumbra and Cycles on scenes/cornell-box-point.gltf (the same room from
make_cornell_box.py, a point light, and a mirror sphere the OBJ lacks) at the same settings,
and penumbra on the tutorial's own scene converted to glTF (embree_cornell.py: its OBJ with
albedo-1 walls, its point light and camera).
The tutorial's time is its whole process (it loads its 36-triangle OBJ in about 50 ms).
"""
import copy
import os
import shutil
import subprocess
import tempfile
import time

from efficiency_metrics import median
from efficiency_render import (Cache, CyclesSession, children_cpu, cycles_renders,
                               penumbra_render)
from efficiency_scenes import prepare

ECS = "/usr/share/doc/embree3/models/cornell_box.ecs"
SIZE, SPP, SEGMENTS = 256, 64, 8


def embree_available():
    return bool(shutil.which("pathtracer")) and os.path.exists(ECS)


def embree_run(threads, tmp):
    """(wall, CPU) seconds of one whole pathtracer run."""
    start, cpu = time.time(), children_cpu()
    subprocess.run(["pathtracer", "-c", ECS, "--size", str(SIZE), str(SIZE), "--spp",
                    str(SPP), "--max-path-length", str(SEGMENTS), "--threads", str(threads),
                    "-o", os.path.join(tmp, "embree.ppm")], check=True, capture_output=True)
    return time.time() - start, children_cpu() - cpu


def timed_row(name, cache, seeds):
    """(name, render s, process s, CPU s): medians over the seeds' renders."""
    times = [cache.times(SPP, s) for s in seeds]
    return (name, median([t["render_s"] for t in times]),
            median([t["process_s"] for t in times]), median([t["cpu_s"] for t in times]))


def penumbra_cache(scene, args, identities):
    prepared = prepare(scene, os.path.join(args.cache, "scenes"))
    return prepared, Cache(args.cache, scene, prepared, identities["penumbra"],
                           {"size": SIZE, "max_depth": SEGMENTS, "threads": args.threads,
                            "extra": args.penumbra_args})


def embree_table(args, identities):
    """The table's runs: penumbra on cornell-point, Cycles on it, penumbra on the
    tutorial's own OBJ, light and camera (embree_cornell.py: the same work as the
    tutorial, ray for ray up to the two renderers' sampling), and the tutorial. With
    --interleave, one run of each per seed, the first of them turning round from seed to
    seed; else each renderer's runs together."""
    a = copy.copy(args)
    a.size, a.max_depth = SIZE, SEGMENTS  # penumbra's --max-depth 8: 8 path segments
    seeds = list(range(1, args.repeats + 1))
    prepared, pen = penumbra_cache("cornell-point", args, identities)
    own = penumbra_cache("embree-cornell", args, identities) if os.path.exists(ECS) else None
    cyc = None
    if "cycles" in args.renderers:
        cyc = Cache(args.cache, "cornell-point", prepared, identities["cycles"],
                    {"size": SIZE, "max_depth": SEGMENTS, "threads": args.threads})
    embree = []
    with tempfile.TemporaryDirectory() as tmp:
        def penumbra(target, seed):
            if not target[1].done(SPP, seed):
                penumbra_render(a, target[0], target[1], SPP, seed)

        if args.interleave:
            # penumbra's first render gives Cycles its camera, so it opens seed 1.
            penumbra((prepared, pen), seeds[0])
            session = None
            if cyc:
                session = CyclesSession(a, "cornell-point", prepared, cyc, pen.path(SPP, 1),
                                        [(SPP, s) for s in seeds if not cyc.done(SPP, s)],
                                        paced=True)
            for i, seed in enumerate(seeds):
                steps = [lambda s=seed: penumbra((prepared, pen), s)]
                if session and (SPP, seed) in session.todo:
                    steps.append(session.render_next)
                if own:
                    steps.append(lambda s=seed: penumbra(own, s))
                if embree_available():
                    steps.append(lambda: embree.append(embree_run(args.threads, tmp)))
                k = i % len(steps)
                for step in steps[k:] + steps[:k]:
                    step()
            if session:
                session.finish()
        else:
            for seed in seeds:
                penumbra((prepared, pen), seed)
            if cyc:
                cycles_renders(a, "cornell-point", prepared, cyc, pen.path(SPP, 1),
                               [(SPP, s) for s in seeds if not cyc.done(SPP, s)])
            if own:
                for seed in seeds:
                    penumbra(own, seed)
            if embree_available():
                embree = [embree_run(args.threads, tmp) for _ in seeds]
    rows = [timed_row("penumbra", pen, seeds)]
    if cyc:
        rows.append(timed_row("Cycles", cyc, seeds))
    if own:
        rows.append(timed_row("penumbra, the tutorial's scene", own[1], seeds))
    lines = ["Equal spp: Cornell box with a point light, %d x %d, %d spp, %d path segments, "
             "%d threads; medians of %d. CPU seconds: the whole process for penumbra and "
             "Embree, the render with its sync for Cycles." % (
                 SIZE, SIZE, SPP, SEGMENTS, args.threads, args.repeats), "",
             "| renderer | render s | process s | cpu-s | render s / Embree's process s "
             "| cpu-s / Embree's |", "|---|---|---|---|---|---|"]
    e_wall = median([w for w, _ in embree]) if embree else None
    e_cpu = median([c for _, c in embree]) if embree else None
    for name, render_s, process_s, cpu_s in rows:
        lines.append("| %s | %.2f | %.2f | %.2f | %s | %s |" % (
            name, render_s, process_s, cpu_s, "%.2f" % (render_s / e_wall) if embree else "n/a",
            "%.2f" % (cpu_s / e_cpu) if embree else "n/a"))
    if embree:
        lines.append("| Embree 3.13.5 pathtracer | | %.2f | %.2f | 1 | 1 |" % (e_wall, e_cpu))
    else:
        lines.append("| Embree pathtracer | not installed (Debian: embree-tools) | | | | |")
    return "\n".join(lines)
