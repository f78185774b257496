#!/usr/bin/env bash
# Instructions that penumbra binaries execute inside the render loop (render_samples and
# all it calls, Embree included; the toggle names the function exactly, since a pattern
# would also flip collection off again in the lambdas and templates named after it), counted by valgrind's callgrind: the same count on
# every run of an idle machine, so two builds can be compared where timing cannot
# resolve a few percent (on a VM whose speed swings by 30% from minute to minute;
# docs/performance.md, "How to measure"). The renderer sizes its passes by elapsed time,
# so the binaries run with a clock slowed 1000 times (scripts/slow_clock.c, where a C
# compiler is found): their passes, and so their counts, do not follow the machine's
# load. Fewer instructions is not always less
# time: confirm a cut with scripts/ab_render_time.py. Each binary takes about 15 s at
# the default size.
#
#   scripts/render_instructions.sh OLD/penumbra build/bin/penumbra
#   scripts/render_instructions.sh build/bin/penumbra -- render scenes/glossy.gltf --width 64 --spp 16
#
# Without `--`, the render is the point-light Cornell box at 64 px, 16 spp, box filter,
# 8 segments, one thread. For a line-level profile, run callgrind on a build with -g and
# read it with `callgrind_annotate --auto=yes`, or by the line each inlined instruction
# came from with scripts/inline_profile.py.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v valgrind >/dev/null || { echo "needs valgrind (apt-get install valgrind)" >&2; exit 1; }
binaries=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do binaries+=("$1"); shift; done
[ $# -gt 0 ] && shift
args=("$@")
if [ ${#args[@]} -eq 0 ]; then
    args=(render scenes/cornell-box-point.gltf --width 64 --spp 16 --filter box --max-depth 8
          --no-default-light)
fi
[ ${#binaries[@]} -gt 0 ] || { echo "usage: $0 BINARY... [-- render ARGS]" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
preload=()
if cc -O2 -shared -fPIC -o "$tmp/slow_clock.so" scripts/slow_clock.c -ldl 2>/dev/null; then
    preload=(env LD_PRELOAD="$tmp/slow_clock.so")
else
    echo "no C compiler: the counts follow the passes, which follow the machine's load" >&2
fi
first=""
for bin in "${binaries[@]}"; do
    # The progress reporter inside the loop is left out: how often it prints depends on
    # the wall clock, so on a loaded machine its instructions would vary from run to run.
    "${preload[@]}" valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" \
        --toggle-collect='penumbra::render_samples(*' --toggle-collect='*ProgressReporter::update*' \
        "$bin" "${args[@]}" -o "$tmp/out.exr" \
        --threads 1 --no-preview --overwrite >"$tmp/log" 2>&1 ||
        { cat "$tmp/log" >&2; exit 1; }
    n=$(sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$tmp/log")
    if [ -z "$first" ]; then
        first=$n
        echo "$bin: $n instructions"
    else
        echo "$bin: $n instructions ($(python3 -c "print('%.4f' % ($n / $first))") of the first)"
    fi
done
