#!/usr/bin/env bash
# Fuzzes the glTF loader (.gltf and .glb) with libFuzzer for FUZZ_SECONDS (default 60):
# builds fuzz/gltf_loader_fuzzer in the asan preset's build (build/asan, or BUILD_DIR),
# seeds a temporary corpus from scenes/ and, in ../shared, the Khronos samples, the real
# files of scenes/wild/ and the fuzzer's earlier finds in scenes/fuzz-found/ (copied, at
# most FUZZ_MAX_SEED_BYTES each, default 1 MiB; the originals are not touched) and runs. A crash fails the script and leaves its input in
# FUZZ_ARTIFACTS (default build/fuzz-artifacts); fix it and add the input to
# scenes/invalid/ with its expected message.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${BUILD_DIR:-build/asan}"
seconds="${FUZZ_SECONDS:-60}"
artifacts="${FUZZ_ARTIFACTS:-build/fuzz-artifacts}"
shared="${PENUMBRA_SHARED_DIR:-../shared}"
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
    cmake --preset asan -B "$build_dir"
fi
cmake --build "$build_dir" --parallel "$(nproc)" --target gltf_loader_fuzzer

corpus="$(mktemp -d)"
trap 'rm -rf "$corpus"' EXIT
seed_dirs=(scenes)
for d in khronos wild fuzz-found; do
    if [ -d "$shared/scenes/$d" ]; then seed_dirs+=("$shared/scenes/$d"); fi
done
python3 fuzz/make_seeds.py "$corpus" "${seed_dirs[@]}" --max-bytes "${FUZZ_MAX_SEED_BYTES:-1048576}"
mkdir -p "$artifacts"

# Full malloc stacks: the suppressions name frames inside libraries built without frame
# pointers, which the fast unwinder never reaches.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:halt_on_error=1:fast_unwind_on_malloc=0}"
source scripts/sanitizer_env.sh
log="$artifacts/fuzz.log"
status=0
"$build_dir/bin/gltf_loader_fuzzer" "$corpus" -max_total_time="$seconds" \
    -dict=fuzz/gltf.dict -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$artifacts/" 2>"$log" || status=$?
grep -E '^(INFO: seed corpus|#[0-9]+ *DONE|stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb|==[0-9]+==ERROR|SUMMARY)' "$log" || true
echo "fuzz: corpus $(find "$corpus" -type f | wc -l) files after ${seconds} s"
if [ "$status" -ne 0 ]; then
    tail -n 60 "$log"
    echo "fuzz: FAILED (status $status); inputs in $artifacts/" >&2
    exit "$status"
fi
