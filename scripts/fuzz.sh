#!/usr/bin/env bash
# Fuzzes with libFuzzer for FUZZ_SECONDS (default 60) per target:
#   scripts/fuzz.sh [gltf]   the glTF loader (.gltf and .glb), fuzz/gltf_loader_fuzzer
#   scripts/fuzz.sh ktx2     the KTX2 decoder, fuzz/ktx2_decoder_fuzzer
#   scripts/fuzz.sh all      every target in turn, FUZZ_SECONDS each
# Builds the target in the asan preset's build (build/asan, or BUILD_DIR) and seeds a
# temporary corpus. glTF: from scenes/ and, in ../shared, the Khronos samples, the real
# files of scenes/wild/, the KHR_texture_basisu scene of scenes/ktx2/ and the fuzzer's
# earlier finds in scenes/fuzz-found/ (copied with PNG and JPEG images scaled down to 64
# pixels a side, kept in BUILD_DIR/fuzz-seed-images for later runs; at most
# FUZZ_MAX_SEED_BYTES each, default 256 KiB, also the longest input a mutation may make;
# the originals are not touched). KTX2: the files of ../shared/scenes/ktx2. A crash
# fails the script and leaves its input in FUZZ_ARTIFACTS (default build/fuzz-artifacts);
# fix it and add the input to scenes/invalid/ with its expected message.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${BUILD_DIR:-build/asan}"
seconds="${FUZZ_SECONDS:-60}"
artifacts="${FUZZ_ARTIFACTS:-build/fuzz-artifacts}"
shared="${PENUMBRA_SHARED_DIR:-../shared}"
max_bytes="${FUZZ_MAX_SEED_BYTES:-262144}"
mode="${1:-gltf}"
case "$mode" in
    gltf) targets=(gltf) ;;
    ktx2) targets=(ktx2) ;;
    all) targets=(gltf ktx2) ;;
    *) echo "usage: scripts/fuzz.sh [gltf|ktx2|all]" >&2; exit 2 ;;
esac
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
    cmake --preset asan -B "$build_dir"
fi
names=()
for t in "${targets[@]}"; do
    case "$t" in
        gltf) names+=(gltf_loader_fuzzer) ;;
        ktx2) names+=(ktx2_decoder_fuzzer) ;;
    esac
done
cmake --build "$build_dir" --parallel "$(nproc)" --target "${names[@]}"
mkdir -p "$artifacts"

# ASan's fast (frame-pointer) malloc stacks: full ones (fast_unwind_on_malloc=0) unwind
# every allocation through libgcc and cost about two thirds of each glTF run. The one
# suppression (fuzz/lsan.supp) names a frame only full stacks reach, so should its leak
# come back the run stops on it (a false alarm, never a hidden leak): rerun the artifact
# with ASAN_OPTIONS=detect_leaks=1:fast_unwind_on_malloc=0 to tell.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:halt_on_error=1}"
source scripts/sanitizer_env.sh

# run_target NAME: seeds a corpus for NAME and fuzzes it for $seconds.
run_target() {
    local name="$1" corpus extra=()
    corpus="$(mktemp -d)"
    if [ "$name" = gltf ]; then
        local seed_dirs=(scenes)
        for d in khronos wild fuzz-found ktx2; do
            if [ -d "$shared/scenes/$d" ]; then seed_dirs+=("$shared/scenes/$d"); fi
        done
        python3 fuzz/make_seeds.py "$corpus" "${seed_dirs[@]}" --max-bytes "$max_bytes" \
            --image-cache "$build_dir/fuzz-seed-images"
        extra=(-dict=fuzz/gltf.dict -max_len="$max_bytes")
        binary="$build_dir/bin/gltf_loader_fuzzer"
    else
        cp "$shared"/scenes/ktx2/*.ktx2 "$corpus"/
        extra=(-max_len="$max_bytes")
        binary="$build_dir/bin/ktx2_decoder_fuzzer"
    fi
    local log="$artifacts/fuzz-$name.log" status=0
    "$binary" "$corpus" -max_total_time="$seconds" "${extra[@]}" -timeout=20 \
        -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/" 2>"$log" ||
        status=$?
    grep -E '^(INFO: seed corpus|#[0-9]+ *DONE|stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb|==[0-9]+==ERROR|SUMMARY)' "$log" || true
    echo "fuzz $name: corpus $(find "$corpus" -type f | wc -l) files after ${seconds} s"
    rm -rf "$corpus"
    if [ "$status" -ne 0 ]; then
        tail -n 60 "$log"
        echo "fuzz $name: FAILED (status $status); inputs in $artifacts/" >&2
        exit "$status"
    fi
}
for t in "${targets[@]}"; do run_target "$t"; done
