#!/usr/bin/env bash
# scripts/thread_scaling.py reads each render's seconds from its EXR header and prints the
# 1-thread and 2-thread medians, the speed-up and the user-CPU ratio, all positive.
set -euo pipefail
bin=$1
cd "$(dirname "$0")/../.."
out=$(python3 scripts/thread_scaling.py "$bin" --rounds 2 -- scenes/cornell-box.gltf \
    --width 32 --spp 2)
echo "$out"
fail() { echo "FAIL: $1"; exit 1; }
for t in 1 2; do
    echo "$out" | grep -Eq "^$t thread\(s\): render median [0-9]+\.[0-9]{4} s \(min [0-9.]+\)" ||
        fail "no $t-thread line"
done
ratio=$(echo "$out" | sed -n 's/^speed-up \([0-9.]*\)x (medians).*/\1/p')
[ -n "$ratio" ] || fail "no speed-up line"
python3 -c "import sys; sys.exit(0 if 0 < float('$ratio') < 100 else 1)" ||
    fail "speed-up $ratio out of range"
echo "ok"
