#!/usr/bin/env python3
"""The dynamic loader's symbol search at start-up, and the check that cmake/loader_order.txt
shortens it without changing what any symbol binds to.

Every penumbra process (each render, each Slurm task, each of ctest's ~760 test processes)
starts by binding about 155,000 symbols across the 265 libraries that Debian's OpenImageIO
brings in; most are built with BIND_NOW, so all of them are bound before main. ld.so looks
each one up library by library, in load order (breadth first from the executable), and
four fifths of them are a library's references to its own C++ symbols (libopenvdb alone
has 57,000), found only when the search reaches that library: position 34 for libopenvdb,
199 for libxerces-c, 256 for libgeos. Without the list, that search is 65% of `penumbra --version`'s
instructions (docs/performance.md, "Start-up"). Naming the heaviest of those
libraries in the executable's own DT_NEEDED, right after the C++ and C runtimes, puts them
near the front of the search; CMake does that from cmake/loader_order.txt.

Moving a library forward can change which of two definitions of a symbol wins. `check`
runs BINARY under LD_DEBUG=bindings and, for every binding, finds the library that would
have won in the order without the list (rebuilt from each library's DT_NEEDED, and
checked against ld.so's own order), from each library's exported symbols (nm -D, with
ld.so's version rules). A binding may move from one weak definition to another: a C++
template instance or inline function that many libraries compile from the same header
and export, one definition by the one-definition rule, bound by every reference to
whichever copy comes first, as under any link order (about 500 do). A binding that moves
to or from a strong definition is a real choice (libblas and liblapack both define
xerbla_): exit status 1, as when the search is not at most --at-most of the default's.

  scripts/loader_order.py check build/bin/penumbra --at-most 0.5
  scripts/loader_order.py rank build/bin/penumbra     # libraries by the search they cost

The cost printed is the number of libraries searched, summed over all bindings.
"""
import argparse
import collections
import concurrent.futures
import functools
import os
import re
import subprocess
import sys
import tempfile

LIST = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cmake",
                    "loader_order.txt")


# Each binding names its libraries by the paths ld.so opened: resolved once per path.
real = functools.lru_cache(maxsize=None)(os.path.realpath)


def listed():
    """The sonames of cmake/loader_order.txt, in order."""
    with open(LIST) as f:
        return [line.split("#")[0].strip() for line in f if line.split("#")[0].strip()]


def loaded(binary):
    """(soname, path) of every object in ld.so's load order, the executable first."""
    out = subprocess.run([binary], env=dict(os.environ, LD_TRACE_LOADED_OBJECTS="1"),
                         capture_output=True, text=True, check=True).stdout
    objects = [(os.path.basename(binary), real(binary))]
    for line in out.splitlines():
        m = re.match(r"\s*(\S+) => (\S+) \(", line)
        if m:
            objects.append((m.group(1), m.group(2)))
        elif "ld-linux" in line:
            path = line.split()[0]
            objects.append((os.path.basename(path), path))
    return objects


@functools.lru_cache(maxsize=None)
def needed(path):
    out = subprocess.run(["readelf", "-dW", path], capture_output=True, text=True).stdout
    return re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", out)


def breadth_first(binary, top, paths):
    """ld.so's load order when the executable needs the sonames `top`."""
    order, seen, queue = [os.path.basename(binary)], {os.path.basename(binary)}, list(top)
    while queue:
        name = queue.pop(0)
        if name in seen or name not in paths:
            continue
        seen.add(name)
        order.append(name)
        queue.extend(needed(paths[name]))
    # ld.so itself, when nothing needed it by that name, comes last.
    order += [n for n in paths if n not in seen]
    return order


def bindings(binary):
    """(referencing path, symbol, defining path) of every binding at start-up."""
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, LD_DEBUG="bindings", LD_DEBUG_OUTPUT=os.path.join(tmp, "b"))
        subprocess.run([binary, "--version"], env=env, capture_output=True, check=True)
        found = []
        for name in os.listdir(tmp):
            with open(os.path.join(tmp, name)) as f:
                for line in f:
                    m = re.search(r"binding file (\S+) \[\d+\] to (\S+) \[\d+\]: "
                                  r"\S+ symbol `([^']+)'(?: \[([^\]]+)\])?", line)
                    if m:
                        found.append((m.group(1), (m.group(3), m.group(4) or ""), m.group(2)))
        return found


def exports(path, wanted):
    """{(name, version): weak} for the references in `wanted` (name -> versions) that a
    definition in path satisfies, as ld.so's check_match decides: a versioned reference
    takes that version or an unversioned definition; an unversioned one takes the default
    (@@) version or an unversioned definition, never a hidden (@) one. weak: a weak or
    unique definition (a C++ inline function or template instance, which any library
    using it may export)."""
    out = subprocess.run(["nm", "-D", "--defined-only", path], capture_output=True,
                         text=True).stdout
    versions = collections.defaultdict(dict)  # name -> {"" | "@V" | "@@V": weak}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) >= 3 and parts[1] != "A":
            name, at, version = parts[2].partition("@")
            versions[name][at + version] = parts[1] in "WVu"
    found = {}
    for name, version in ((n, v) for n in versions.keys() & wanted.keys() for v in wanted[n]):
        have = versions[name]
        for v in ("", "@" + version, "@@" + version) if version else ("",):
            if v in have and (name, version) not in found:
                found[(name, version)] = have[v]
        if not version and (name, version) not in found:
            default = [w for v, w in have.items() if v.startswith("@@")]
            if default:
                found[(name, version)] = default[0]
    return found


def cost(binds, order, paths):
    """Libraries searched, summed over the bindings (each lookup stops at its definer)."""
    position = {real(paths[n]): i + 1 for i, n in enumerate(order)}
    return sum(position.get(real(d), 1) for _, _, d in binds)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("mode", choices=["check", "rank"])
    ap.add_argument("binary")
    ap.add_argument("--at-most", type=float, default=1.0,
                    help="check: fail unless the search is at most this share of the "
                    "default order's (that the list took effect)")
    args = ap.parse_args()
    objects = loaded(args.binary)
    paths = dict(objects)
    actual = [n for n, _ in objects]
    top = needed(args.binary)
    early = set(listed())
    # Without the list, the compiler driver adds the C++ and C runtimes last.
    runtimes = ["libstdc++.so.6", "libm.so.6", "libgcc_s.so.1", "libc.so.6"]
    default_top = [n for n in top if n not in early] + [n for n in runtimes if n in early]
    emulated = breadth_first(args.binary, top, paths)
    if emulated != actual:
        print("the breadth-first emulation does not match ld.so's order; cannot check")
        return 2
    default = breadth_first(args.binary, default_top, paths)
    binds = bindings(args.binary)
    base, now = cost(binds, default, paths), cost(binds, actual, paths)
    print("%d bindings; libraries searched: %d in the default order, %d now (%.3f)"
          % (len(binds), base, now, now / base))
    if args.mode == "rank":
        by_lib = collections.Counter(real(d) for _, _, d in binds)
        position = {real(paths[n]): (i + 1, n) for i, n in enumerate(actual)}
        ranked = sorted(by_lib, key=lambda p: -by_lib[p] * position.get(p, (1, ""))[0])
        for p in ranked[:40]:
            i, n = position.get(p, (1, p))
            print("%9d lookups-deep  %6d bindings  position %3d  %s"
                  % (by_lib[p] * i, by_lib[p], i, n))
        return 0
    # The winner of each bound symbol in the default order. The executable's references
    # bind once past it (copy relocations, whose search skips the executable) and once to
    # itself (to the copy): either answer is the order's.
    exe = real(args.binary)
    wanted = collections.defaultdict(set)  # name -> the versions asked for
    for _, (name, version), _ in binds:
        wanted[name].add(version)
    winner, past_exe, weak = {}, {}, {}
    with concurrent.futures.ThreadPoolExecutor(os.cpu_count()) as pool:
        defined = list(pool.map(lambda n: exports(real(paths[n]), wanted), default))
    for name, found in zip(default, defined):
        path = real(paths[name])
        for s, is_weak in found.items():
            weak[(s, path)] = is_weak
            winner.setdefault(s, path)
            if path != exe:
                past_exe.setdefault(s, path)

    def expected(r, s):
        return (past_exe if real(r) == exe else winner).get(s)

    def agrees(r, s, d):
        d = real(d)
        return d == expected(r, s) or (real(r) == exe and d == winner.get(s))

    changed = [(r, s, d) for r, s, d in binds if expected(r, s) and not agrees(r, s, d)]
    # A weak definition in both libraries is one function by the one-definition rule (a
    # template instance or inline function that each library compiled from the same
    # header and exports weakly): whichever copy the search finds first, every reference
    # binds to that one, as with any link order. Strong definitions are real choices.
    interchangeable = [(r, s, d) for r, s, d in changed
                       if weak.get((s, real(d))) and weak.get((s, expected(r, s)))]
    weak_moves = set(interchangeable)
    strong = [c for c in changed if c not in weak_moves]
    for r, s, d in strong[:20]:
        print("CHANGED %s: %s@%s binds to %s, not %s" % (r, s[0], s[1], d, expected(r, s)))
    unresolved = [s for r, s, _ in binds if not expected(r, s)]
    print("%d bindings changed by the order: %d from one weak definition to another, %d "
          "otherwise (%d symbols the libraries do not list, such as the vDSO's, skipped)"
          % (len(changed), len(interchangeable), len(strong), len(unresolved)))
    if now > args.at_most * base:
        print("the search is %.3f of the default order's, more than --at-most %.3f"
              % (now / base, args.at_most))
        return 1
    return 1 if strong else 0


if __name__ == "__main__":
    sys.exit(main())
