#!/usr/bin/env bash
# scripts/render_instructions.sh counts the same instructions for the same binary and
# render on every run (what makes it usable for A/B on a noisy machine), and a count that
# is not zero. Skipped (77) without valgrind.
set -euo pipefail
bin=$1
cd "$(dirname "$0")/../.."
command -v valgrind >/dev/null || { echo "valgrind not installed: skipped"; exit 77; }
# Without default lights, as the script's own default render: --default-light auto first
# renders a preview of the view, a second parallel region, and TBB's scheduler and
# allocator vary by some hundred instructions with thread timing on a loaded machine
# (1e-4 of this small render, past the 4 decimals compared below).
out=$(scripts/render_instructions.sh "$bin" "$bin" -- render scenes/cornell-box-point.gltf \
    --width 16 --spp 2 --max-depth 4 --no-default-light)
echo "$out"
first=$(echo "$out" | sed -n '1s/.*: \([0-9]*\) instructions.*/\1/p')
[ -n "$first" ] && [ "$first" -gt 1000000 ] || { echo "no count in the first line"; exit 1; }
echo "$out" | sed -n '2p' | grep -q "(1.0000 of the first)" || { echo "counts differ"; exit 1; }
