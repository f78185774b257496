#!/usr/bin/env bash
# Set up, build and run every test (GoogleTest through CTest), then the same tests under
# ASan+UBSan and a bounded fuzzing run of each fuzz target, the glTF loader and the KTX2
# decoder (scripts/sanitize.sh, scripts/fuzz.sh all). PENUMBRA_SANITIZE=0 skips the last
# two (a quicker local run).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --test
scripts/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)" "$@"
if [ "${PENUMBRA_SANITIZE:-1}" != 0 ]; then
    scripts/sanitize.sh
    scripts/fuzz.sh all
fi
