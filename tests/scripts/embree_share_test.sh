#!/usr/bin/env bash
# scripts/embree_share.py records a render with perf and finds samples in both libembree3
# and the binary, with a share strictly between 0 and 100. Skipped (77) without perf or
# without permission to record.
set -euo pipefail
bin=$1
cd "$(dirname "$0")/../.."
command -v perf >/dev/null || { echo "perf not installed: skipped"; exit 77; }
probe=$(mktemp)
trap 'rm -f "$probe"' EXIT
perf record -q -e cpu-clock -o "$probe" -- true >/dev/null 2>&1 ||
    { echo "perf cannot record here: skipped"; exit 77; }
out=$(python3 scripts/embree_share.py "$bin" --rounds 1 --core -1 -- render \
    scenes/cornell-box-point.gltf --width 64 --spp 16 --max-depth 4 --threads 1)
echo "$out"
line=$(echo "$out" | sed -n '1p')
embree=$(echo "$line" | sed -n 's/.*embree \([0-9]*\),.*/\1/p')
ours=$(echo "$line" | sed -n 's/.*penumbra \([0-9]*\),.*/\1/p')
[ -n "$embree" ] && [ "$embree" -gt 0 ] || { echo "no Embree samples"; exit 1; }
[ -n "$ours" ] && [ "$ours" -gt 0 ] || { echo "no penumbra samples"; exit 1; }
echo "$out" | tail -1 | grep -Eq "share median [0-9]+\.[0-9]% " || { echo "no summary"; exit 1; }
