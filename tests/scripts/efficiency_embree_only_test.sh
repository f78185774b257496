#!/usr/bin/env bash
# scripts/crosscheck/efficiency.py --embree-only prints the equal-spp table against Embree's
# pathtracer tutorial alone: penumbra's rows and the tutorial's, no efficiency table, and
# none of the efficiency scenes rendered (its cache holds the table's two scenes only).
# Skipped (77) without the tutorial (Debian's embree-tools, scripts/setup.sh --test).
set -euo pipefail
bin=$1
cd "$(dirname "$0")/../.."
command -v pathtracer >/dev/null && [ -e /usr/share/doc/embree3/models/cornell_box.ecs ] ||
    { echo "Embree's pathtracer or its Cornell box not installed: skipped"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out=$(python3 scripts/crosscheck/efficiency.py --embree-only --renderers penumbra --repeats 1 \
    --penumbra "$bin" --cache "$tmp/cache" --out "$tmp/table.md")
echo "$out"
fail() { echo "FAIL: $1"; exit 1; }
echo "$out" | grep -Eq '^\| penumbra \| [0-9.]+ \| [0-9.]+ \|' || fail "no penumbra row"
echo "$out" | grep -Eq '^\| Embree 3\.[0-9.]+ pathtracer \|' || fail "no tutorial row"
echo "$out" | grep -q '| scene | spp |' && fail "an efficiency table was printed"
echo "$out" | grep -q '^| Cycles' && fail "Cycles ran though not asked for"
cmp -s <(echo "$out") "$tmp/table.md" || fail "--out differs from what was printed"
[ ! -e "$tmp/table.md.json" ] || fail "a measurement record without measurements"
scenes=$(ls "$tmp/cache" | grep -vx scenes | sed 's/-[0-9a-f]*$//' | sort | tr '\n' ' ')
[ "$scenes" = "cornell-point embree-cornell " ] || fail "rendered scenes: $scenes"
echo "ok"
