"""Renders for scripts/crosscheck/efficiency.py, cached so that a run resumes where it stopped
and a re-run renders only what changed: one folder per scene (its file hash), renderer
identity (penumbra: its version and the binary's hash; Cycles: Blender's version and
efficiency_cycles.py's SETUP_VERSION) and settings, holding one EXR and one JSON of times per
(spp, seed).
"""
import glob
import hashlib
import json
import os
import re
import resource
import subprocess
import threading
import time

from compare_cycles import blender_env
from efficiency_scenes import HERE, ROOT, SCENES, cycles_world, file_hash, penumbra_lighting


def penumbra_identity(binary):
    """The build decides the image and the time, so the cache key is the binary's hash (a
    commit that changes only scripts or docs keeps the renders); the commit is recorded."""
    def git(*a):
        return subprocess.run(["git", "-C", ROOT] + list(a), capture_output=True,
                              text=True).stdout.strip()
    dirty = "-dirty" if git("status", "--porcelain", "--untracked-files=no") else ""
    version = subprocess.run([binary, "--version"], capture_output=True, text=True).stdout
    return {"version": version.strip(), "commit": git("rev-parse", "--short", "HEAD") + dirty,
            "key": "penumbra-%s-%s" % (version.split()[-1] if version.split() else "unknown",
                                       file_hash([binary])[:12])}


def cycles_identity():
    out = subprocess.run(["blender", "--version"], capture_output=True, text=True,
                         env=blender_env()).stdout
    version = out.splitlines()[0].strip() if out else "unknown"
    with open(os.path.join(HERE, "efficiency_cycles.py")) as f:
        setup = re.search(r"^SETUP_VERSION = (\d+)", f.read(), re.M).group(1)
    return {"version": version, "commit": "setup v" + setup,
            "key": "cycles-%s-v%s" % (version.replace("Blender ", "").replace(" ", ""), setup)}


def settings_key(settings):
    return hashlib.sha256(json.dumps(settings, sort_keys=True).encode()).hexdigest()[:10]


class Cache:
    """Where a scene's renders by one renderer live. A render's times are cached with its
    image, so a run on a machine under another load would mix loads in one table: with
    retime_since set (efficiency.py --retime), timed renders older than it count as not
    done and are rendered again; references (untimed) are kept."""

    retime_since = None

    def __init__(self, root, scene, prepared, identity, settings):
        self.scene_dir = os.path.join(root, "%s-%s" % (scene, prepared["hash"]))
        self.settings = settings_key(settings)
        self.dir = os.path.join(self.scene_dir, "%s-%s" % (identity["key"], self.settings))
        os.makedirs(self.dir, exist_ok=True)

    def path(self, spp, seed):
        return os.path.join(self.dir, "spp%d-seed%d.exr" % (spp, seed))

    def done(self, spp, seed, need_cpu=True):
        """Rendered, and timed with CPU seconds unless need_cpu is False (references)."""
        p = self.path(spp, seed)
        if not (os.path.exists(p) and os.path.exists(p + ".json")):
            return False
        if need_cpu and Cache.retime_since is not None and \
                os.path.getmtime(p + ".json") < Cache.retime_since:
            return False
        return not need_cpu or "cpu_s" in self.times(spp, seed)

    def times(self, spp, seed):
        return json.load(open(self.path(spp, seed) + ".json"))

    def other_reference(self, renderer, spp, seed):
        """The newest cached render of (spp, seed) by any version of the renderer with these
        settings (--reuse-references)."""
        found = glob.glob(os.path.join(self.scene_dir, "%s-*-%s" % (renderer, self.settings),
                                       "spp%d-seed%d.exr" % (spp, seed)))
        found = [f for f in found if os.path.exists(f + ".json")]
        return max(found, key=os.path.getmtime) if found else None


def penumbra_render(args, prepared, cache, spp, seed):
    out = cache.path(spp, seed)
    cmd = [args.penumbra, "render", prepared["scene"], "-o", out + ".tmp.exr", "--width",
           str(args.size), "--spp", str(spp), "--seed", str(seed), "--filter", "box",
           "--max-depth", str(args.max_depth), "--threads", str(args.threads),
           "--timing-metadata", "--no-preview", "-q", "--overwrite"] + \
        penumbra_lighting(prepared) + args.penumbra_args.split()
    start, cpu = time.time(), children_cpu()
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=args.timeout)
    wall, cpu = time.time() - start, children_cpu() - cpu
    if p.returncode != 0:
        raise RuntimeError("penumbra failed (%s): %s" % (" ".join(cmd), p.stdout + p.stderr))
    header = exr_attributes(out + ".tmp.exr")
    os.replace(out + ".tmp.exr", out)
    times = {"render_s": float(header["penumbra:render_seconds"]),
             "load_s": float(header["penumbra:load_seconds"]),
             "build_s": float(header.get("penumbra:build_seconds", 0)),
             "process_s": wall, "cpu_s": cpu, "sampler": header.get("penumbra:sampler", "?")}
    with open(out + ".json", "w") as f:
        json.dump(times, f)


def children_cpu():
    """User + system CPU seconds of this process's finished children."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def exr_attributes(path):
    text = subprocess.run(["oiiotool", "--info", "-v", path], capture_output=True, text=True,
                          check=True).stdout
    attrs = {}
    for line in text.splitlines()[1:]:
        key, sep, value = line.strip().partition(": ")
        if sep:
            attrs[key] = value.strip('"')
    if "worldToCamera" in attrs:
        attrs["resolution"] = text.split(":", 1)[1].split(",")[0]
    return attrs


def floats(text):
    return [float(v) for v in text.replace(",", " ").split()]


def status_seconds(line):
    """The "Time:MM:SS.cc" (or HH:MM:SS.cc) field of a Cycles status line, in seconds."""
    m = re.search(r"\| Time:([0-9:.]+) \|", line)
    if not m:
        return None
    seconds = 0.0
    for part in m.group(1).split(":"):
        seconds = 60 * seconds + float(part)
    return seconds


def cycles_path_tracing_seconds(log):
    """Per render of a Blender log, the path-tracing time: Cycles' clock at its last "Sample
    N/N" line minus at "Sample 0/N" (sync, BVH build and image loading come before; the
    clock has 10 ms steps). Renders are told apart by their "| Finished" lines."""
    out, first, last = [], None, None
    for line in log.splitlines():
        if "| Sample " in line:
            t = status_seconds(line)
            if t is not None:
                first = t if first is None else first
                last = t
        elif line.rstrip().endswith("| Finished"):
            if first is None:
                raise RuntimeError("Cycles: a render without sample lines")
            out.append(max(last - first, 0.01))
            first = last = None
    return out


def interleave(penumbra_todo, cycles_todo):
    """The order of efficiency.py --interleave: each (spp, seed) that both renderers render,
    by one and then at once by the other, the first of the two alternating, so that both
    see the same minutes of a machine whose speed drifts (docs/performance.md,
    "How to measure") and neither always goes first; the renders only one of them needs are in
    their place. Returns [(renderer, (spp, seed))]."""
    steps, both = [], 0
    keys = list(penumbra_todo) + [k for k in cycles_todo if k not in penumbra_todo]
    for key in keys:
        pair = [r for r, todo in (("penumbra", penumbra_todo), ("cycles", cycles_todo))
                if key in todo]
        if len(pair) == 2:
            if both % 2:
                pair.reverse()
            both += 1
        steps += [(r, key) for r in pair]
    return steps


class CyclesSession:
    """One Blender process (one import and sync) that renders every (spp, seed) of todo, in
    order. With paced, efficiency_cycles.py waits before each render until render_next()
    says go, and that returns when it has rendered: efficiency.py --interleave runs
    penumbra's renders in between. finish() waits for the process and files the images
    and their times in the cache. command replaces Blender's (tests)."""

    def __init__(self, args, name, prepared, cache, camera_exr, todo, paced=False,
                 command=None):
        self.args, self.cache, self.todo, self.lines = args, cache, list(todo), []
        if not self.todo:
            self.proc = None
            return
        attrs = exr_attributes(camera_exr)
        width, height = (int(v) for v in attrs["resolution"].split("x"))
        job = {"scene": os.path.abspath(prepared["scene"]), "width": width, "height": height,
               "world_to_camera": floats(attrs["worldToCamera"]),
               "world_to_ndc": floats(attrs["worldToNDC"]), "max_depth": args.max_depth,
               "threads": args.threads, "materials": SCENES[name]["materials"],
               "world": cycles_world(name, prepared), "paced": paced,
               "renders": [{"spp": s, "seed": d, "out": cache.path(s, d) + ".tmp.exr"}
                           for s, d in self.todo]}
        job_path = os.path.join(cache.dir, "job.json")
        with open(job_path, "w") as f:
            json.dump(job, f)
        self.start = time.time()
        self.paused_s = 0.0  # time spent on penumbra's renders between paced ones
        command = command or ["blender", "-b", "--factory-startup", "-P",
                              os.path.join(HERE, "efficiency_cycles.py"), "--"]
        self.proc = subprocess.Popen(command + [job_path], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                     text=True, env=blender_env())
        self.waiting_since = None
        self.rendered = 0
        self.finished = False
        # Paced, Blender's start-up (launch, import, sync, its 1-spp render: 2-3 s of both
        # cores) must not run beside penumbra's first timed render, which it slowed to
        # 2.1 s from 1.0 (cornell, 32 spp): wait here until Blender asks for its first go.
        if paced:
            self._read_until("EFFICIENCY-READY")
            self.waiting_since = time.time()  # from here Blender waits: not its time

    def _read_until(self, prefix):
        for line in self.proc.stdout:
            self.lines.append(line)
            if line.startswith("EFFICIENCY-ERROR "):
                raise RuntimeError("Cycles: " + line[len("EFFICIENCY-ERROR "):].strip())
            if line.startswith(prefix):
                return
        tail = "".join(self.lines).strip().splitlines()[-5:]
        raise RuntimeError("blender exit %s before %s: %s"
                           % (self.proc.wait(), prefix, " / ".join(tail)))

    def render_next(self):
        """A paced session's next render: lets Blender render, and returns once it is idle
        again (waiting for the next go, or, after the last render, exited), so that
        nothing of Blender's runs beside the renders that follow."""
        if self.waiting_since is not None:
            self.paused_s += time.time() - self.waiting_since
        self.proc.stdin.write("go\n")
        self.proc.stdin.flush()
        self._read_until("EFFICIENCY-RENDERED")
        self.waiting_since = time.time()
        self.rendered += 1
        if self.rendered < len(self.todo):
            self._read_until("EFFICIENCY-READY")
        else:
            self.finish()

    def finish(self):
        if self.proc is None or self.finished:
            return
        self.finished = True
        # The rest of the output through the same buffered reader that render_next()
        # used: communicate() reads the pipe itself and would lose what that reader
        # already holds. A timer stands in for communicate()'s timeout.
        self.proc.stdin.close()
        timer = threading.Timer(self.args.timeout * len(self.todo), self.proc.kill)
        timer.start()
        try:
            self.lines.extend(self.proc.stdout)
            self.proc.wait()
        finally:
            timer.cancel()
        log = "".join(self.lines)
        # A paced session's clock stops at its last render: what ran after it was the
        # driver's (Blender's own exit goes uncounted there).
        end = self.waiting_since if self.waiting_since is not None else time.time()
        wall = end - self.start - self.paused_s
        info = None
        for line in log.splitlines():
            if line.startswith("EFFICIENCY-ERROR "):
                raise RuntimeError("Cycles: " + line[len("EFFICIENCY-ERROR "):])
            if line.startswith("EFFICIENCY "):
                info = json.loads(line[len("EFFICIENCY "):])
        if info is None:
            tail = log.strip().splitlines()[-5:]
            raise RuntimeError("blender exit %s: %s" % (self.proc.returncode, " / ".join(tail)))
        render_s = cycles_path_tracing_seconds(log)[1:]  # the first: the 1-spp render
        if len(render_s) != len(self.todo):
            raise RuntimeError("Cycles: %d renders finished, %d expected"
                               % (len(render_s), len(self.todo)))
        # Whole process for one render: Blender's start and import shared out, plus that
        # render with its sync.
        overhead = (wall - sum(info["render_wall_s"])) / len(self.todo)
        for (spp, seed), seconds, render_wall, cpu in zip(
                self.todo, render_s, info["render_wall_s"], info["render_cpu_s"]):
            out = self.cache.path(spp, seed)
            os.replace(out + ".tmp.exr", out)
            times = {"render_s": seconds, "render_wall_s": render_wall,
                     "process_s": overhead + render_wall, "setup_s": info["setup_s"],
                     "cpu_s": cpu, "cpu_1spp_s": info["cpu_1spp_s"],
                     "sampler": info["sampling_pattern"], "version": info["version"]}
            with open(out + ".json", "w") as f:
                json.dump(times, f)


def cycles_renders(args, name, prepared, cache, camera_exr, todo):
    """Renders every (spp, seed) of todo in one Blender process, one after the other."""
    CyclesSession(args, name, prepared, cache, camera_exr, todo).finish()
