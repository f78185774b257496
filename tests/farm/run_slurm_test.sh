#!/usr/bin/env bash
# The farm end to end on a real Slurm cluster it starts itself (tests/farm/slurm_cluster.sh,
# single node, localhost): `farm submit --wait` on a job file with several scenes, an
# animation's frames, banded images (one denoised by the merge) and a broken scene writes
# every image with the pixels of `render --job` on one machine and names the broken scene; a task stopped with
# SIGTERM and requeued continues from its checkpoint to the same pixels. Exits 77 (ctest:
# skipped) without Slurm or root. Usage: run_slurm_test.sh PENUMBRA_BINARY
set -euo pipefail

penumbra=$(realpath "${1:?usage: run_slurm_test.sh PATH/TO/penumbra}")
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
for cmd in munged slurmctld slurmd sbatch squeue scontrol scancel idiff; do
    if ! command -v "$cmd" >/dev/null; then
        echo "SKIP: $cmd is not installed (scripts/setup.sh --test installs slurm-wlm, munge)"
        exit 77
    fi
done
if [ "$(id -u)" -ne 0 ]; then
    echo "SKIP: starting munged, slurmctld and slurmd needs root"
    exit 77
fi

# shellcheck source=tests/farm/slurm_cluster.sh
source "$here/slurm_cluster.sh"
work=$(mktemp -d /tmp/penumbra_farm.XXXXXX)
cleanup() {
    cluster_stop "$work/cluster"
    if [ "${KEEP_FARM_TEST:-0}" = 1 ]; then echo "kept $work"; else rm -rf "$work"; fi
}
trap cleanup EXIT
cluster_start "$work/cluster"
cd "$work"

failures=0
fail() {
    echo "FAIL: $*"
    failures=$((failures + 1))
}
# Bitwise: idiff with zero tolerance over every channel.
same() {
    if ! idiff -fail 0 -warn 0 "$1" "$2" >/dev/null 2>&1; then
        fail "$2 differs from $1: $(idiff -fail 0 -warn 0 "$1" "$2" 2>&1 | tail -3 | tr '\n' ' ')"
    fi
}
wait_gone() {  # job id, seconds
    local i
    for i in $(seq 1 $(($2 * 5))); do
        [ -z "$(squeue -h -j "$1" -o %i 2>/dev/null)" ] && return 0
        sleep 0.2
    done
    return 1
}

cornell=$repo/scenes/cornell-box.gltf
echo '{"asset": ' >broken.gltf
# OUT_DIR differs between the one-machine and the farm copy.
write_job() {
    cat >"$1" <<JSON
{
  "defaults": {"width": 32, "spp": 4, "out_dir": "$2"},
  "jobs": [
    {"scene": "$cornell", "name": "cornell.exr"},
    {"scene": "$repo/scenes/glossy.gltf", "name": "glossy_banded.exr", "bands": 3,
     "aov": "albedo,normal,depth,variance,samples"},
    {"scene": "$repo/scenes/motion-blur.gltf", "name": "anim_{frame}.exr", "frames": "1-3",
     "frames_per_task": 2},
    {"scene": "broken.gltf"},
    {"scene": "$repo/scenes/soft-shadows.gltf", "name": "soft_half.exr", "half": true,
     "bands": 2},
    {"scene": "$cornell", "name": "denoised_banded.exr", "bands": 2, "denoise": true,
     "aov": "albedo"}
  ]
}
JSON
}
write_job ref.json ref
write_job job.json farm
t0=$(date +%s.%N)
set +e
"$penumbra" render --job ref.json -q >ref.log 2>&1
ref_status=$?
"$penumbra" farm submit job.json --cpus-per-task 1 --partition test \
    --sbatch-args "--comment 'penumbra farm test' --time=30" --wait >submit.log 2>&1
submit_status=$?
set -e
t1=$(date +%s.%N)
cat submit.log
[ "$ref_status" = 1 ] || fail "render --job exited $ref_status, expected 1 (the broken scene)"
[ "$submit_status" = 1 ] || fail "farm submit --wait exited $submit_status, expected 1"
grep -Eq 'broken\.gltf +- +failed .*broken\.gltf' submit.log ||
    fail "the summary does not name the broken scene"
grep -q '8 images: 7 ok, 0 partial, 1 failed' submit.log || fail "the summary's counts"
# 11 work items with MaxArraySize=5: three arrays.
[ "$(grep -c '^array' job.farm/jobs.txt)" = 3 ] || fail "not cut into three arrays: $(cat job.farm/jobs.txt)"
for f in cornell.exr cornell.png glossy_banded.exr glossy_banded.png anim_0001.exr \
    anim_0002.exr anim_0003.exr soft_half.exr soft_half.png denoised_banded.exr \
    denoised_banded.png; do
    if [ -f "farm/$f" ]; then same "ref/$f" "farm/$f"; else fail "farm/$f was not written"; fi
done
if ls farm | grep -q '\.band-'; then fail "band files left after the merge: $(ls farm)"; fi
echo "render --job and farm submit --wait: $(awk "BEGIN {print $t1 - $t0}") s"

# Preemption: a longer image first, with --max-running 1 so the other tasks wait behind
# it (so the array is not done, and the merge not started, when the task is requeued);
# SIGTERM to its batch step (scancel --full), then requeue: Slurm holds a requeued job for
# cred_expire seconds (10 in our slurm.conf), then the rerun must continue from the
# checkpoint and give the uninterrupted image.
cat >long.json <<JSON
{
  "defaults": {"width": 48, "spp": 384, "out_dir": "long"},
  "jobs": [
    {"scene": "$cornell", "name": "long.exr", "aov": "albedo,variance"},
    {"scene": "$cornell", "name": "after_{frame}.exr", "spp": 8, "frames": "1-5"}
  ]
}
JSON
sed -e 's/"out_dir": "long"/"out_dir": "long_ref"/' long.json >long_ref.json
"$penumbra" render --job long_ref.json -q
"$penumbra" farm submit long.json --max-running 1 >long_submit.log
array=$(awk '/^array/ {print $2; exit}' long.farm/jobs.txt)  # item 0 is in the first
merge=$(awk '/^merge/ {print $2}' long.farm/jobs.txt)
log=long.farm/logs/task-${array}_0.log
# Slurm requeues a preempted job in the same step as it stops it, so its dependants never
# see it finished; a signal and a requeue by hand are two steps, so the merge is held
# between them (on a quiet machine the other tasks would end, and the merge start, first).
scontrol hold "$merge"
for _ in $(seq 1 300); do grep -q ': started, ' "$log" 2>/dev/null && break; sleep 0.1; done
# At once: the last pass holds half the samples, and the signal must come before it.
# Slurm 22.05's scancel exits 1 (saying nothing) when a signal reaches the batch step
# but no other step; the checkpoint below shows whether it arrived.
scancel --full --signal=TERM "${array}_0" || true
# The task's result record is its last act: requeue at once, while the other tasks
# still keep the array (and so the merge) from finishing.
for _ in $(seq 1 300); do
    [ -f long.farm/results/item-000000.json ] && break
    sleep 0.05
done
[ -f long/long.exr.ckpt ] || fail "no checkpoint after SIGTERM: $(tail -5 "$log")"
if ! out=$(scontrol requeue "${array}_0" 2>&1); then fail "scontrol requeue ${array}_0: $out"; fi
scontrol release "$merge"
wait_gone "$merge" 240 || fail "the merge of long.json did not finish"
grep -q 'resuming from the checkpoint at ' "$log" || fail "the requeued task did not resume: $(cat "$log")"
grep -q '"restarts": 1' long.farm/results/item-000000.json || fail "SLURM_RESTART_COUNT not 1"
same long_ref/long.exr long/long.exr
same long_ref/after_0005.exr long/after_0005.exr
if [ -f long/long.exr.ckpt ]; then fail "the checkpoint outlived the finished image"; fi
"$penumbra" farm status long.json >status.log
grep -q '6 of 6 work items finished (0 failed), 6 images' status.log || fail "farm status: $(cat status.log)"

if [ "$failures" -ne 0 ]; then
    echo "$failures failures; logs in $work (KEEP_FARM_TEST=1 keeps them)"
    exit 1
fi
echo "PASS: farm outputs are bitwise those of render --job; the preempted task resumed"
